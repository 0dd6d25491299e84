// The near field of eq. 17 at a receiver from its row of the near-field table (core/
// near_field.h, built on the CPU when the geometry or the material changes):
// B_near = 1/pi Sum_e w_e E(source_e), E summed over the lights on both sides of the source
// (surfel_irradiance_fs.glsl).

uniform sampler2D nearRows;     // per receiver (surfel list layout): first entry, entry count
uniform sampler2D nearEntries;  // x: the source's texel in the surfel list (y * width + x),
                                // yzw: its weight per channel
uniform sampler2D frontIrradiance;  // E per surfel (the list's layout), on its normal's side
uniform sampler2D backIrradiance;   // and on the other

vec3 nearFieldB(ivec2 at)
{
  vec2 row = texelFetch(nearRows, at, 0).xy;
  int first = int(row.x);
  int count = int(row.y);
  int entriesWidth = textureSize(nearEntries, 0).x;
  ivec2 listSize = textureSize(surfelPoint, 0);
  vec3 sum = vec3(0.0);
  for (int e = first; e < first + count; ++e)
  {
    vec4 entry = texelFetch(nearEntries, ivec2(e % entriesWidth, e / entriesWidth), 0);
    int source = int(entry.x);
    ivec2 s = ivec2(source % listSize.x, source / listSize.x);
    sum += entry.yzw *
      (texelFetch(frontIrradiance, s, 0).rgb + texelFetch(backIrradiance, s, 0).rgb);
  }
  return sum / PI;
}
