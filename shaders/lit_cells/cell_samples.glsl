// Step 2's points over a surfel's cell (core/lit_cells/surfel_irradiance.h is the same on the
// CPU): `count` points spread over a disc of the cell's area on the surfel's local surface (the
// paraboloid of its clamped curvature), at a turn of the pattern that the texel fixes, each
// lit as eq. 15 has it. Needs light_maps.glsl, light_visibility.glsl, surfel_list.glsl and
// fresnel_table.glsl.

// The surfel's normal turned towards light `light`'s side (l: towards the light at the surfel).
vec3 cellNormal(ivec2 at, vec3 l)
{
  vec3 n = texelFetch(surfelShape, at, 0).xyz;
  return dot(n, l) < 0.0 ? -n : n;
}

// 1/S Sum_s Ft(eta, theta_s) cos(theta_s) V(y_s) falloff(y_s) over the cell of the surfel at
// texel `at` (point: its texel in surfelPoint), eq. 15 without the light's irradiance and the
// albedo; `lit` counts the points the light reaches.
vec3 cellSampleMean(ivec2 at, vec4 point, int light, int count, out int lit)
{
  vec4 shape = texelFetch(surfelShape, at, 0);
  float cellRadius = texelFetch(surfelCell, at, 0).x;
  vec3 l = towardsLight(light, point.xyz);
  float side = dot(shape.xyz, l) < 0.0 ? -1.0 : 1.0;
  vec3 n = side * shape.xyz;
  float kappa = side * clamp(shape.w, -kappaLimitCell, kappaLimitCell);
  vec3 helper = abs(n.x) < 0.7 ? vec3(1.0, 0.0, 0.0) : vec3(0.0, 1.0, 0.0);
  vec3 t1 = normalize(cross(n, helper));
  vec3 t2 = cross(n, t1);
  float turn = 6.283185307 * fract(sin(dot(vec2(at), vec2(12.9898, 78.233))) * 43758.5453);
  vec3 sum = vec3(0.0);
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
  return sum / float(count);
}

// E_l = albedo E_light cellSampleMean over the lights (eq. 15), summed on the side the surfel's
// normal faces (front) and on the other (back): each light turns the normal towards its side.
// A light whose bit is set in `refineLights` takes `refinedSamples` points, the others `count`;
// `disagree` gets the bits of the lights whose points disagree (an edge or the terminator
// crosses the cell).
void cellSides(ivec2 at, vec4 point, int count, int refinedSamples, int refineLights,
  out vec3 front, out vec3 back, out int disagree)
{
  vec3 albedo = texelFetch(surfelAlbedo, at, 0).rgb;
  vec3 n = texelFetch(surfelShape, at, 0).xyz;
  front = vec3(0.0);
  back = vec3(0.0);
  disagree = 0;
  for (int l = 0; l < lightCount; ++l)
  {
    int lit;
    int samples = (refineLights & (1 << l)) != 0 ? refinedSamples : count;
    vec3 E = lightIrradiance[l] * albedo * cellSampleMean(at, point, l, samples, lit);
    if (dot(n, towardsLight(l, point.xyz)) < 0.0)
    {
      back += E;
    }
    else
    {
      front += E;
    }
    if (lit > 0 && lit < samples)
    {
      disagree += 1 << l;
    }
  }
}
