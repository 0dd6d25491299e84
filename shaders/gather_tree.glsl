// B(x) of eq. 17 from the illumination maps' pyramids: a tree walk over the map texels that
// takes a texel group as one source, with its point covariance as a second-order term, once it
// subtends less than openingAngle seen from x and spans at most maxGroupDiffusionLengths of
// every channel whose kernel still matters there (over more, e^(-s_tr d) leaves its
// second-order expansion). The GPU form of the CPU reference's source tree. Needs
// light_maps.glsl, dipole.glsl and kernel_window.glsl.

uniform float openingAngle;
uniform float maxGroupDiffusionLengths;
uniform float supportRadius;  // mm: beyond it Rd has lost all but 1e-7 of its integral

vec3 gatherB(vec3 x)
{
  float reach = windowPart == 1 ? min(windowR1, supportRadius) : supportRadius;
  vec3 sum = vec3(0.0);
  ivec3 stack[64];
  for (int light = 0; light < lightCount; ++light)
  {
    int top = levelCount[light] - 1;
    int base = light * SSS_MAX_LEVELS;
    int depth = 0;
    stack[depth++] = ivec3(0, 0, top);
    while (depth > 0)
    {
      ivec3 node = stack[--depth];
      int level = node.z;
      ivec2 texel = ivec2(levelRect[base + level].xy) + node.xy;
      vec4 point = texelFetch(mapPoint, texel, 0);
      if (point.w <= 0.0)
      {
        continue;
      }
      vec4 normal = texelFetch(mapNormal, texel, 0);
      float lateral = texelSize[light] * float(1 << level) * 1.41421356;
      float size = length(vec2(lateral, normal.w));
      float d = distance(x, point.xyz);
      if (d - size > reach || (windowPart == 2 && d + size < windowR0))
      {
        continue;
      }
      bool straddlesWindow = windowPart != 0 && d + size > windowR0 && d - size < windowR1 &&
        size > 0.25 * (windowR1 - windowR0);
      float sTrSignificant = 0.0;  // fastest decay among channels not yet below e^-16
      for (int c = 0; c < 3; ++c)
      {
        if (sTr[c] * (d - size) < 16.0)
        {
          sTrSignificant = max(sTrSignificant, sTr[c]);
        }
      }
      bool smallEnough =
        size < openingAngle * d && size * sTrSignificant < maxGroupDiffusionLengths;
      if (level == 0 || (smallEnough && !straddlesWindow) || depth > 60)
      {
        vec3 power = texelFetch(mapPower, texel, 0).rgb;
        vec4 c0 = texelFetch(mapCovariance0, texel, 0);
        vec4 c1 = texelFetch(mapCovariance1, texel, 0);
        mat3 cov = mat3(c0.x, c0.w, c1.x, c0.w, c0.y, c1.y, c1.x, c1.y, c0.z);
        sum += power * dipoleRdSecondOrder(point.xyz, normal.xyz, cov, x) * kernelWindow(d);
        continue;
      }
      ivec2 childSize = ivec2(levelRect[base + level - 1].zw);
      for (int k = 3; k >= 0; --k)
      {
        ivec2 child = 2 * node.xy + ivec2(k & 1, k >> 1);
        if (child.x < childSize.x && child.y < childSize.y)
        {
          stack[depth++] = ivec3(child, level - 1);
        }
      }
    }
  }
  return sum / PI;
}
