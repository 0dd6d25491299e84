// The paper's kernel: B(x) of eq. 17 from 49 taps, Gaussian-distributed over a 40 x 40 texel
// window of each light's map around the texel x projects to. Each tap is weighted by the
// inverse of its sampling density, so the taps estimate the window's sum; nothing outside the
// window is counted. Needs light_maps.glsl and dipole.glsl.

uniform sampler2D mapPoint;   // xyz: point (local mm), w: summed power over its channels
uniform sampler2D mapPower;   // rgb: E dA, w: lit texels
uniform sampler2D mapNormal;  // xyz: unit normal (0 where no disc)
uniform vec3 paperTaps[49];   // offset in texels (xy), weight (z)

vec3 gatherB(vec3 x)
{
  vec3 sum = vec3(0.0);
  for (int light = 0; light < lightCount; ++light)
  {
    ivec4 rect = ivec4(levelRect[light * SSS_MAX_LEVELS]);
    vec2 plane = vec2(dot(mapAxisU[light], x), dot(mapAxisV[light], x));
    vec2 centre = (plane - mapCorner[light]) / texelSize[light];
    for (int k = 0; k < 49; ++k)
    {
      ivec2 texel = ivec2(floor(centre + paperTaps[k].xy));
      if (any(lessThan(texel, ivec2(0))) || any(greaterThanEqual(texel, rect.zw)))
      {
        continue;
      }
      vec4 point = texelFetch(mapPoint, rect.xy + texel, 0);
      if (point.w <= 0.0)
      {
        continue;
      }
      vec3 normal = texelFetch(mapNormal, rect.xy + texel, 0).xyz;
      vec3 power = texelFetch(mapPower, rect.xy + texel, 0).rgb;
      sum += paperTaps[k].z * power * dipoleRd(point.xyz, normal, x);
    }
  }
  return sum / PI;
}
