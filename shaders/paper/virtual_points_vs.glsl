//VTK::System::Dec
// Step 2: one kept virtual point per GL point, drawn into its texel of one slice of the 3-D
// radiance texture.

in vec3 gridIndex;         // i, j, k of the kept point
in vec2 gatheredTexel;     // its texel in the receivers' pass
uniform vec2 sliceSize;    // texels

flat out ivec2 gatheredAt;

void main()
{
  gatheredAt = ivec2(gatheredTexel);
  gl_Position = vec4((gridIndex.xy + 0.5) / sliceSize * 2.0 - 1.0, 0.0, 1.0);
  gl_PointSize = 1.0;
}
