//VTK::System::Dec
// Step 2, the cells whose first points disagree (surfel_irradiance_fs.glsl), lit again with
// cellRefinedSamples points. They are packed side by side, one per texel of a block of their
// own, so that the rasteriser's blocks hold only cells that refine and none waits on a
// neighbour's longer loop; refined_cells_scatter_fs.glsl puts each back in its texel.

uniform int light;  // which light
uniform int cellRefinedSamples;
uniform sampler2D refinedCell;  // xy: the cell's texel in the surfel list
uniform int refinedCount;       // cells in the block, row by row

in vec2 texCoord;  // over the block

//SSS::Gather::Dec

//VTK::Output::Dec

void main()
{
  ivec2 size = textureSize(refinedCell, 0);
  ivec2 k = ivec2(texCoord * vec2(size));
  vec3 E = vec3(0.0);
  if (k.y * size.x + k.x < refinedCount)
  {
    ivec2 at = ivec2(texelFetch(refinedCell, k, 0).xy);
    vec4 point = texelFetch(surfelPoint, at, 0);
    int lit;
    E = lightIrradiance[light] * texelFetch(surfelAlbedo, at, 0).rgb *
      cellSampleMean(at, point, light, cellRefinedSamples, lit);
  }
  gl_FragData[0] = vec4(E, 0.0);
}
