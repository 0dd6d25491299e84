//VTK::System::Dec
// Copies the pass's float image to the output: translucent pixels (alpha 2) hold linear
// radiance and are tone mapped (exposure, clamp, sRGB curve); the rest pass unchanged.

in vec2 texCoord;
uniform sampler2D colourTexture;
uniform sampler2D depthTexture;
uniform float exposure;

//VTK::Output::Dec

float srgbEncode(float linear)
{
  return linear <= 0.0031308 ? 12.92 * linear : 1.055 * pow(linear, 1.0 / 2.4) - 0.055;
}

void main()
{
  vec4 colour = texture(colourTexture, texCoord);
  if (colour.a > 1.5)
  {
    vec3 c = clamp(exposure * colour.rgb, 0.0, 1.0);
    colour = vec4(srgbEncode(c.r), srgbEncode(c.g), srgbEncode(c.b), 1.0);
  }
  gl_FragData[0] = colour;
  gl_FragDepth = texture(depthTexture, texCoord).r;
}
