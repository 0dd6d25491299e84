//VTK::System::Dec
// Step 2, per surfel and light (core/lit_cells/surfel_irradiance.h is the same on the CPU): the
// irradiance of eq. 15 averaged over the surfel's cell, E = albedo 1/S Sum_s E_light(y_s)
// Ft(eta, theta_s) cos(theta_s) V(y_s) over S points spread over a disc of the cell's area on
// the surfel's local surface, V from the light's map, sampled again with more points where the
// first ones disagree (an edge crosses the cell); and the cell as a source of the far field:
// its point, power E dA, normal (turned towards the light), radius and covariance, the finest
// level of that light's source pyramid.

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
  vec3 l = towardsLight(light, point.xyz);
  vec3 n = vec3(0.0);
  float cellRadius = 0.0;
  float area = 0.0;
  if (point.w > 0.0)
  {
    vec4 shape = texelFetch(surfelShape, at, 0);
    vec2 cell = texelFetch(surfelCell, at, 0).xy;
    cellRadius = cell.x;
    area = cell.y;
    float side = dot(shape.xyz, l) < 0.0 ? -1.0 : 1.0;
    n = side * shape.xyz;
    float kappa = side * clamp(shape.w, -kappaLimitCell, kappaLimitCell);
    vec3 helper = abs(n.x) < 0.7 ? vec3(1.0, 0.0, 0.0) : vec3(0.0, 1.0, 0.0);
    vec3 t1 = normalize(cross(n, helper));
    vec3 t2 = cross(n, t1);
    float turn = 6.283185307 * fract(sin(dot(vec2(at), vec2(12.9898, 78.233))) * 43758.5453);
    vec3 sum = vec3(0.0);
    int lit = 0;
    int count = cellSamples;
    for (int pass = 0; pass < 2; ++pass)
    {
      sum = vec3(0.0);
      lit = 0;
      for (int s = 0; s < count; ++s)
      {
        float rho = cellRadius * sqrt((float(s) + 0.5) / float(count));
        float angle = turn + 2.399963230 * float(s);
        vec3 d = rho * (cos(angle) * t1 + sin(angle) * t2);
        vec3 y = point.xyz + d - 0.5 * kappa * dot(d, d) * n;
        vec3 ny = normalize(n + kappa * d);
        vec3 ly = towardsLight(light, y);
        float cosI = dot(ny, ly);
        if (cosI > 0.0 && lightReaches(light, y, cosI, point.w))
        {
          sum += fresnelFt(cosI) * cosI * lightFalloff(light, y);
          ++lit;
        }
      }
      sum /= float(count);
      if (lit == 0 || lit == count || cellRefinedSamples <= count)
      {
        break;
      }
      count = cellRefinedSamples;
    }
    E = lightIrradiance[light] * texelFetch(surfelAlbedo, at, 0).rgb * sum;
  }
  vec3 power = E * area;
  float weight = power.r + power.g + power.b;
  // The cell as a disc of its area: variance r^2 / 4 along each tangent.
  mat3 cov = 0.25 * cellRadius * cellRadius * (mat3(1.0) - outerProduct(n, n));
  gl_FragData[0] = vec4(E, 0.0);
  gl_FragData[1] = vec4(point.xyz, weight);
  gl_FragData[2] = vec4(power, weight > 0.0 ? 1.0 : 0.0);
  gl_FragData[3] = vec4(n, cellRadius);
  gl_FragData[4] = vec4(cov[0][0], cov[1][1], cov[2][2], cov[0][1]);
  gl_FragData[5] = vec4(cov[0][2], cov[1][2], 0.0, 0.0);
}
