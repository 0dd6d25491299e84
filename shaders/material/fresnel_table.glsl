// Ft(eta, theta) per channel (core/material/fresnel.h, the exact dielectric formula) from a table
// over cos(theta) in [0, 1], filtered linearly.

uniform sampler2D fresnelTable;
uniform int fresnelTableSize;

vec3 fresnelFt(float cosI)
{
  float x = clamp(cosI, 0.0, 1.0) * float(fresnelTableSize - 1) + 0.5;
  return texture(fresnelTable, vec2(x / float(fresnelTableSize), 0.5)).rgb;
}
