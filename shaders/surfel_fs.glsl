//VTK::System::Dec
// Camera view of a surfel: the disc's colour, computed per surfel in surfel_vs.glsl. SPLAT_PASS
// (set by vtkSurfelMapper) picks the pass: 0 a hard disc; 1 the visibility pass of blended
// splatting (the depth alone, pushed back by surfel_gs.glsl); 2 the accumulation pass, colour and depth weighted by a Gaussian of the distance to the centre
// (surfel_normalise_fs.glsl divides by the weights).
//SSS::Splat::Dec

in vec2 discCoord;
flat in vec4 colour;

//VTK::Output::Dec

void main()
{
  float r2 = dot(discCoord, discCoord);
  if (r2 > 1.0)
  {
    discard;
  }
#if SPLAT_PASS == 1
  gl_FragData[0] = vec4(0.0);
#elif SPLAT_PASS == 2
  float w = exp(-2.0 * r2);  // e^-2 at the rim
  gl_FragData[0] = w * colour;
  gl_FragData[1] = vec4(w, w * gl_FragCoord.z, 0.0, 0.0);
#else
  gl_FragData[0] = colour;
#endif
}
