//VTK::System::Dec
// Copies the pass's float image to the output: translucent pixels (alpha 2 to 3) hold linear
// radiance and are tone mapped (exposure, clamp, sRGB curve); the rest pass unchanged. A
// translucent pixel that surfels cover only in part (a silhouette of blended splats, alpha
// 3 - coverage, surfel_normalise_fs.glsl) is faded by its coverage into the mean of its
// neighbours that hold no translucent surfel: the scene behind it, which that pixel no longer
// holds.

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
    c = vec3(srgbEncode(c.r), srgbEncode(c.g), srgbEncode(c.b));
    float coverage = clamp(3.0 - colour.a, 0.0, 1.0);
    if (coverage < 1.0)
    {
      ivec2 size = textureSize(colourTexture, 0);
      ivec2 at = ivec2(texCoord * vec2(size));
      vec4 behind = vec4(0.0);
      for (int k = 0; k < 9; ++k)
      {
        ivec2 q = clamp(at + ivec2(k % 3 - 1, k / 3 - 1), ivec2(0), size - 1);
        vec4 neighbour = texelFetch(colourTexture, q, 0);
        if (neighbour.a <= 1.5)
        {
          behind += vec4(neighbour.rgb, 1.0);
        }
      }
      if (behind.w > 0.0)
      {
        c = mix(behind.rgb / behind.w, c, coverage);
      }
    }
    colour = vec4(c, 1.0);
  }
  gl_FragData[0] = colour;
  gl_FragDepth = texture(depthTexture, texCoord).r;
}
