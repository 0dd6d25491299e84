// The test of core/light_map/light_map.h for whether the light reaches a point, against a map of
// which surfel each texel sees (light_map_surfel_fs.glsl). Needs light_maps.glsl and
// surfel_list.glsl.

uniform sampler2D mapSurfel;   // xy: the seen surfel's texel in the surfel list; x = -1: none,
                               // x = -2: another piece's surface (sssLightMapPieces.h)
uniform float kappaLimitCell;  // 1/mm: the curvature clamp of a surfel's paraboloid (1 / radius)

// Whether the light reaches point y of a surface with cosine cosI to the light and surface
// thickness `thickness` (mm): the local surface of the disc the map sees at y's texel
// (core/light_map/light_map.cpp seen_point: the texel centre's ray meets the disc's plane at offset
// d, lifted kappa |d|^2 / 2 below it) passes within (thickness + the seen surfel's noise height)
// / cos of y along the light, or the
// texel sees no disc (nothing stands in front); not where another piece of a distributed cloud
// stands in front.
bool lightReaches(int light, vec3 y, float cosI, float thickness)
{
  vec4 rect = levelRect[light * SSS_MAX_LEVELS];
  vec2 at;
  if (!mapCoordinates(light, y, at) || at.x < 0.0 || at.y < 0.0 || at.x >= rect.z ||
    at.y >= rect.w)
  {
    return true;
  }
  vec2 seen = texelFetch(mapSurfel, ivec2(rect.xy) + ivec2(at), 0).xy;
  if (seen.x < -1.5)
  {
    return false;  // another piece of the cloud stands in front, beyond the kernel's reach
  }
  if (seen.x < 0.0)
  {
    return true;
  }
  ivec2 s = ivec2(seen);
  vec3 p = texelFetch(surfelPoint, s, 0).xyz;
  vec4 shape = texelFetch(surfelShape, s, 0);
  vec3 n = shape.xyz;
  vec3 origin, ray;
  texelRay(light, ivec2(at), origin, ray);
  float cosSeen = dot(n, ray);
  cosSeen = cosSeen < 0.0 ? min(cosSeen, -1e-4) : max(cosSeen, 1e-4);
  vec3 d = origin + (dot(p - origin, n) / cosSeen) * ray - p;
  // The texel's centre lies on the disc; only rounding can put d past its radius.
  vec4 seenCell = texelFetch(surfelCell, s, 0);
  d *= min(1.0, seenCell.z / max(length(d), 1e-30));
  float kappa = clamp(shape.w, -kappaLimitCell, kappaLimitCell);
  vec3 seenPoint = p + d - 0.5 * kappa * dot(d, d) * n;
  vec3 seenNormal = normalize(n + kappa * d);
  vec3 l = towardsLight(light, y);
  float along = dot(seenPoint - y, seenNormal) / max(abs(dot(seenNormal, l)), 0.05);
  return abs(along) <= (thickness + seenCell.w) / max(cosI, 0.1);
}
