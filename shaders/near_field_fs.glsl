//VTK::System::Dec
// Step 2, the near field at every surfel, drawn as one quad over the surfels' list (Morton
// order, as for the pyramid walk): each fragment is one receiver.

uniform sampler2D receivers;       // xyz: local mm, w: the surface thickness (mm), 0: none
uniform sampler2D receiverShape;   // xyz: unit normal, w: mean curvature (1/mm)

in vec2 texCoord;  // over the list

//SSS::Gather::Dec

//VTK::Output::Dec

void main()
{
  ivec2 at = ivec2(texCoord * vec2(textureSize(receivers, 0)));
  vec4 receiver = texelFetch(receivers, at, 0);
  vec3 B = vec3(0.0);
  if (receiver.w > 0.0)
  {
    vec4 shape = texelFetch(receiverShape, at, 0);
    // A fraction per receiver that turns its rings, so that neighbours' nodes do not line up.
    float rotation = fract(sin(dot(vec2(at), vec2(12.9898, 78.233))) * 43758.5453);
    B = nearFieldB(receiver.xyz, shape.xyz, shape.w, receiver.w, rotation);
  }
  gl_FragData[0] = vec4(B, 1.0);
}
