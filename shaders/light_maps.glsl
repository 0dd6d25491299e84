// The illumination maps of step 1 (illumination_fs.glsl), one atlas for every light (with the
// paper's pyramid above each map): the samplers, where each light's levels lie in the atlas,
// and the test of core/light_map.h for whether the light reaches a point.

uniform sampler2D mapPoint;        // xyz: point (local mm), w: summed power over its channels
uniform sampler2D mapPower;        // rgb: E dA, w: lit texels
uniform sampler2D mapNormal;       // xyz: unit normal (0 where no disc), w: group radius
uniform sampler2D mapCovariance0;  // xx, yy, zz, xy of the points (mm^2)
uniform sampler2D mapCovariance1;  // xz, yz
uniform int lightCount;
uniform int levelCount[SSS_MAX_LIGHTS];
uniform vec4 levelRect[SSS_MAX_LIGHTS * SSS_MAX_LEVELS];  // atlas origin xy, size zw
uniform float texelSize[SSS_MAX_LIGHTS];                   // level 0 texel edge, mm
uniform vec3 mapAxisU[SSS_MAX_LIGHTS];    // the map's image axes in the local frame
uniform vec3 mapAxisV[SSS_MAX_LIGHTS];
uniform vec2 mapCorner[SSS_MAX_LIGHTS];   // plane coordinates of the map's lower-left corner
uniform vec3 lightDirection[SSS_MAX_LIGHTS];   // towards each light, local frame
uniform vec3 lightIrradiance[SSS_MAX_LIGHTS];  // per channel

// Whether the light reaches point y of a surface with cosine cosI to the light and surface
// thickness `thickness` (mm): the local surface of the disc the map sees at y's texel passes
// within thickness / cos of y along the light, or the texel sees no disc (nothing in front).
bool lightReaches(int light, vec3 y, float cosI, float thickness)
{
  vec4 rect = levelRect[light * SSS_MAX_LEVELS];
  vec2 at = (vec2(dot(y, mapAxisU[light]), dot(y, mapAxisV[light])) - mapCorner[light]) /
    texelSize[light];
  if (at.x < 0.0 || at.y < 0.0 || at.x >= rect.z || at.y >= rect.w)
  {
    return true;
  }
  ivec2 t = ivec2(rect.xy) + ivec2(at);
  vec3 seenNormal = texelFetch(mapNormal, t, 0).xyz;
  if (dot(seenNormal, seenNormal) < 0.25)
  {
    return true;
  }
  vec3 seenPoint = texelFetch(mapPoint, t, 0).xyz;
  vec3 l = lightDirection[light];
  float along = dot(seenPoint - y, seenNormal) / max(abs(dot(seenNormal, l)), 0.05);
  return abs(along) <= thickness / max(cosI, 0.1);
}
