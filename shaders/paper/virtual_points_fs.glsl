//VTK::System::Dec
// Step 2: B (eq. 17) at a virtual point, from the receivers' pass; w = 1 marks a kept point,
// so trilinear filtering of (B, 1) divided by its w leaves pruned corners out.

flat in ivec2 gatheredAt;  // the point's texel in the receivers' pass

uniform sampler2D gathered;

//VTK::Output::Dec

void main()
{
  gl_FragData[0] = vec4(texelFetch(gathered, gatheredAt, 0).rgb, 1.0);
}
