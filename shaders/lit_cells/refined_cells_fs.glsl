//VTK::System::Dec
// Step 2, the cells whose first points disagree for some light (surfel_irradiance_fs.glsl), lit
// again: with cellRefinedSamples points for the lights whose bits the first pass set, with
// cellSamples (the same points as the first pass) for the others, summed on each side as there.
// They are packed side by side, one per texel of a block of their own, so that the
// rasteriser's blocks hold only cells that refine and none waits on a neighbour's longer loop;
// refined_cells_scatter_fs.glsl puts each back in its texel.

uniform int cellSamples;
uniform int cellRefinedSamples;
uniform sampler2D refinedCell;  // xy: the cell's texel in the surfel list, z: the lights' bits
uniform int refinedCount;       // cells in the block, row by row

in vec2 texCoord;  // over the block

//SSS::Gather::Dec

//VTK::Output::Dec

void main()
{
  ivec2 size = textureSize(refinedCell, 0);
  ivec2 k = ivec2(texCoord * vec2(size));
  vec3 front = vec3(0.0), back = vec3(0.0);
  if (k.y * size.x + k.x < refinedCount)
  {
    vec3 cell = texelFetch(refinedCell, k, 0).xyz;
    ivec2 at = ivec2(cell.xy);
    int disagree;
    cellSides(at, texelFetch(surfelPoint, at, 0), cellSamples, cellRefinedSamples, int(cell.z),
      front, back, disagree);
  }
  gl_FragData[0] = vec4(front, 0.0);
  gl_FragData[1] = vec4(back, 0.0);
}
