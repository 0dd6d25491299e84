//VTK::System::Dec
// The paper's step 2: B (eq. 17) by its 49 taps (gather_paper.glsl) at every kept virtual
// point, drawn as one quad over the points' list (Hilbert order of position, 16 to a 4 x 4
// texel block, so that the rasteriser shades neighbours side by side).

uniform sampler2D receivers;  // xyz: local mm, w: 1 where a point

in vec2 texCoord;  // over the list

//SSS::Gather::Dec

//VTK::Output::Dec

void main()
{
  vec4 receiver = texelFetch(receivers, ivec2(texCoord * vec2(textureSize(receivers, 0))), 0);
  gl_FragData[0] = vec4(receiver.w > 0.0 ? gatherB(receiver.xyz) : vec3(0.0), 1.0);
}
