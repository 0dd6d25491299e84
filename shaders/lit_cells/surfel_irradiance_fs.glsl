//VTK::System::Dec
// Step 2, per surfel (core/lit_cells/surfel_irradiance.h is the same on the CPU, per light): the
// irradiance of eq. 15 averaged over the surfel's cell, E_l = albedo E_light 1/S Sum_s
// Ft(eta, theta_s) cos(theta_s) V_l(y_s) over S = cellSamples points (cell_samples.glsl), V_l
// from light l's map, summed over the lights that light the side the surfel's normal faces
// (front) and over those that light the other (back): each light turns the normal towards its
// side (cellNormal), and the dipoles of the two sides differ. Where a light's points disagree
// (an edge or the terminator crosses the cell), the front's alpha holds the lights' bits for
// refined_cells_fs.glsl, which lights the cell again with cellRefinedSamples for them.
// lit_cell_sources_fs.glsl makes the source pyramids' finest level from both.

uniform int cellSamples;
uniform int cellRefinedSamples;

in vec2 texCoord;  // over the surfel list

//SSS::Gather::Dec

//VTK::Output::Dec

void main()
{
  ivec2 at = ivec2(texCoord * vec2(textureSize(surfelPoint, 0)));
  vec4 point = texelFetch(surfelPoint, at, 0);
  vec3 front = vec3(0.0), back = vec3(0.0);
  int refineLights = 0;
  if (point.w > 0.0)
  {
    int disagree;
    cellSides(at, point, cellSamples, cellSamples, 0, front, back, disagree);
    refineLights = cellRefinedSamples > cellSamples ? disagree : 0;
  }
  gl_FragData[0] = vec4(front, float(refineLights));
  gl_FragData[1] = vec4(back, 0.0);
}
