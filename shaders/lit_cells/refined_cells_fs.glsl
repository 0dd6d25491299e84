//VTK::System::Dec
// Step 2, the cells whose first points disagree for some light (surfel_irradiance_fs.glsl), lit
// again: with cellRefinedSamples points for the lights whose bits the first pass set, with
// cellSamples (the same points as the first pass) for the others, summed on each side as there.
// They are packed in a block of their own, sixteen to a 4 x 4 square in the order of the lights
// they mark (sssLitCells.cxx), so that the rasteriser's blocks hold only cells that refine, for
// the same lights, and none waits on a neighbour's longer loop; refined_cells_scatter_fs.glsl
// puts each back in its texel.

uniform int cellSamples;
uniform int cellRefinedSamples;
uniform sampler2D refinedCell;  // xy: the cell's texel in the surfel list, z: the lights' bits
                                // (0: no cell)

in vec2 texCoord;  // over the block

//SSS::Gather::Dec

//VTK::Output::Dec

void main()
{
  ivec2 k = ivec2(texCoord * vec2(textureSize(refinedCell, 0)));
  vec3 front = vec3(0.0), back = vec3(0.0);
  vec3 cell = texelFetch(refinedCell, k, 0).xyz;
  if (cell.z > 0.5)
  {
    ivec2 at = ivec2(cell.xy);
    int disagree;
    cellSides(at, texelFetch(surfelPoint, at, 0), cellSamples, cellRefinedSamples, int(cell.z),
      front, back, disagree);
  }
  gl_FragData[0] = vec4(front, 0.0);
  gl_FragData[1] = vec4(back, 0.0);
}
