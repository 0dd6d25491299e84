// The light maps of step 1, one atlas for every light (with the paper's pyramid above each map):
// where each light's levels lie in the atlas, how a map lies in the local frame, and the lights. A
// light's projection (core/light_map/light_map.h LightView) is the one thing a kind of light adds:
// orthographic along a directional light, perspective from a positional one.

uniform int lightCount;
uniform int levelCount[SSS_MAX_LIGHTS];
uniform vec4 levelRect[SSS_MAX_LIGHTS * SSS_MAX_LEVELS];  // atlas origin xy, size zw
// Level 0 texel edge: mm, or a positional light's on its image plane at unit distance.
uniform float texelSize[SSS_MAX_LIGHTS];
uniform vec3 mapAxisU[SSS_MAX_LIGHTS];    // the map's image axes in the local frame
uniform vec3 mapAxisV[SSS_MAX_LIGHTS];
uniform vec3 mapAxisW[SSS_MAX_LIGHTS];    // towards the light (a positional one's rays run along -w)
uniform vec2 mapCorner[SSS_MAX_LIGHTS];   // plane coordinates of the map's lower-left corner
uniform vec3 lightDirection[SSS_MAX_LIGHTS];   // from the focal point towards each light
uniform vec3 lightIrradiance[SSS_MAX_LIGHTS];  // per channel
uniform int lightPositional[SSS_MAX_LIGHTS];   // 1: positional (a point light or a spot)
uniform vec3 lightPosition[SSS_MAX_LIGHTS];    // positional: mm
uniform vec3 lightAttenuation[SSS_MAX_LIGHTS]; // positional: a0 + a1 d + a2 d^2, d in mm
uniform vec2 lightSpot[SSS_MAX_LIGHTS];        // positional: cone cosine (-1: none), exponent

// The unit direction from y towards the light.
vec3 towardsLight(int light, vec3 y)
{
  return lightPositional[light] != 0 ? normalize(lightPosition[light] - y) : lightDirection[light];
}

// The irradiance at y on a surface facing the light, over lightIrradiance
// (core/light_map/light_map.h LocalLight::irradiance_at: VTK's attenuation and spot).
float lightFalloff(int light, vec3 y)
{
  if (lightPositional[light] == 0)
  {
    return 1.0;
  }
  vec3 toLight = lightPosition[light] - y;
  float d = length(toLight);
  float spot = 1.0;
  vec2 cone = lightSpot[light];
  if (cone.x > -1.0)
  {
    float c = dot(toLight, lightDirection[light]) / max(d, 1e-30);
    spot = c >= cone.x ? pow(c, cone.y) : 0.0;
  }
  vec3 a = lightAttenuation[light];
  return spot / (a.x + d * (a.y + d * a.z));
}

// y's continuous texel coordinates in the light's level-0 map; false behind a positional
// light.
bool mapCoordinates(int light, vec3 y, out vec2 at)
{
  if (lightPositional[light] == 0)
  {
    at = (vec2(dot(y, mapAxisU[light]), dot(y, mapAxisV[light])) - mapCorner[light]) /
      texelSize[light];
    return true;
  }
  vec3 d = y - lightPosition[light];
  float z = -dot(d, mapAxisW[light]);
  at = (vec2(dot(d, mapAxisU[light]), dot(d, mapAxisV[light])) / max(z, 1e-30) -
         mapCorner[light]) / texelSize[light];
  return z > 0.0;
}

// The ray through the centre of level-0 texel `texel` (integer coordinates): a point on it and
// its direction (towards the light for a directional one, away from a positional one).
void texelRay(int light, ivec2 texel, out vec3 origin, out vec3 direction)
{
  vec2 plane = mapCorner[light] + (vec2(texel) + 0.5) * texelSize[light];
  if (lightPositional[light] == 0)
  {
    origin = plane.x * mapAxisU[light] + plane.y * mapAxisV[light];
    direction = lightDirection[light];
  }
  else
  {
    origin = lightPosition[light];
    direction = normalize(plane.x * mapAxisU[light] + plane.y * mapAxisV[light] - mapAxisW[light]);
  }
}
