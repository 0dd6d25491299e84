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
    int refineLights = int(cell.z);
    vec4 point = texelFetch(surfelPoint, at, 0);
    vec3 albedo = texelFetch(surfelAlbedo, at, 0).rgb;
    vec3 n = texelFetch(surfelShape, at, 0).xyz;
    for (int l = 0; l < lightCount; ++l)
    {
      int lit;
      int samples = (refineLights & (1 << l)) != 0 ? cellRefinedSamples : cellSamples;
      vec3 E = lightIrradiance[l] * albedo * cellSampleMean(at, point, l, samples, lit);
      if (dot(n, towardsLight(l, point.xyz)) < 0.0)
      {
        back += E;
      }
      else
      {
        front += E;
      }
    }
  }
  gl_FragData[0] = vec4(front, 0.0);
  gl_FragData[1] = vec4(back, 0.0);
}
