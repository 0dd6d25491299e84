//VTK::System::Dec
// Step 2, per surfel and light (core/lit_cells/surfel_irradiance.h is the same on the CPU): the
// irradiance of eq. 15 averaged over the surfel's cell, E = albedo E_light 1/S Sum_s
// Ft(eta, theta_s) cos(theta_s) V(y_s) over S = cellSamples points (cell_samples.glsl), V from
// the light's map; and the cell as a source of the far field: its point, power E dA, normal
// (turned towards the light), radius and covariance, the finest level of that light's source
// pyramid. Where the points disagree (an edge or the terminator crosses the cell), E's alpha
// marks the cell for refined_cells_fs.glsl, which lights it again with cellRefinedSamples.

uniform int light;               // which light
uniform int cellSamples;
uniform int cellRefinedSamples;

in vec2 texCoord;  // over the surfel list

//SSS::Gather::Dec

//VTK::Output::Dec

void main()
{
  ivec2 at = ivec2(texCoord * vec2(textureSize(surfelPoint, 0)));
  vec4 point = texelFetch(surfelPoint, at, 0);
  vec3 E = vec3(0.0);
  vec3 n = vec3(0.0);
  float cellRadius = 0.0;
  float area = 0.0;
  float refine = 0.0;
  if (point.w > 0.0)
  {
    vec2 cell = texelFetch(surfelCell, at, 0).xy;
    cellRadius = cell.x;
    area = cell.y;
    n = cellNormal(at, towardsLight(light, point.xyz));
    int lit;
    vec3 mean = cellSampleMean(at, point, light, cellSamples, lit);
    E = lightIrradiance[light] * texelFetch(surfelAlbedo, at, 0).rgb * mean;
    refine = lit > 0 && lit < cellSamples && cellRefinedSamples > cellSamples ? 1.0 : 0.0;
  }
  vec3 power = E * area;
  float weight = power.r + power.g + power.b;
  // The cell as a disc of its area: variance r^2 / 4 along each tangent.
  mat3 cov = 0.25 * cellRadius * cellRadius * (mat3(1.0) - outerProduct(n, n));
  gl_FragData[0] = vec4(E, refine);
  gl_FragData[1] = vec4(point.xyz, weight);
  gl_FragData[2] = vec4(power, weight > 0.0 ? 1.0 : 0.0);
  gl_FragData[3] = vec4(n, cellRadius);
  gl_FragData[4] = vec4(cov[0][0], cov[1][1], cov[2][2], cov[0][1]);
  gl_FragData[5] = vec4(cov[0][2], cov[1][2], 0.0, 0.0);
}
