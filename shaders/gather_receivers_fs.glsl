//VTK::System::Dec
// Step 2: B (eq. 17) at every receiver of a list (surfels or kept virtual points), drawn as
// one quad over the list. The list holds the receivers in Morton order of position, 16 to a
// 4 x 4 texel block, so that the fragments the rasteriser shades side by side walk nearly
// the same tree.

uniform sampler2D receivers;  // xyz: local mm, w: 1 where a receiver

in vec2 texCoord;  // over the list

//SSS::Gather::Dec

//VTK::Output::Dec

void main()
{
  vec4 receiver = texelFetch(receivers, ivec2(texCoord * vec2(textureSize(receivers, 0))), 0);
  gl_FragData[0] = vec4(receiver.w > 0.0 ? gatherB(receiver.xyz) : vec3(0.0), 1.0);
}
