//VTK::System::Dec
// Step 2, per surfel: one GL point per surfel, drawn into texel gl_VertexID of a list
// texture that the camera view reads.

in vec3 positionMC;  // scene units relative to the bounds centre (sssSurfelBuffers)
in vec2 gatheredTexel;  // its texel in the receivers' pass
uniform float mmPerUnit;  // scene units to the local frame's mm
uniform int listWidth;
uniform vec2 listSize;

flat out vec3 receiver;
flat out ivec2 gatheredAt;

void main()
{
  receiver = positionMC * mmPerUnit;
  gatheredAt = ivec2(gatheredTexel);
  vec2 texel = vec2(gl_VertexID % listWidth, gl_VertexID / listWidth) + 0.5;
  gl_Position = vec4(texel / listSize * 2.0 - 1.0, 0.0, 1.0);
  gl_PointSize = 1.0;
}
