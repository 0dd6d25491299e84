//VTK::System::Dec
// Step 2: B (eq. 17) at a virtual point; w = 1 marks a kept point, so trilinear filtering
// of (B, 1) divided by its w leaves pruned corners out.

flat in vec3 pointLocal;

//SSS::Gather::Dec

//VTK::Output::Dec

void main()
{
  gl_FragData[0] = vec4(gatherB(pointLocal), 1.0);
}
