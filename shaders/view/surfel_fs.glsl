//VTK::System::Dec
// Camera view of a surfel, computed per surfel in surfel_vs.glsl. SPLAT_PASS (set by
// vtkSurfelMapper) picks the pass: 0 a hard disc; 1 the visibility pass of blended splatting
// (the depth alone, pushed back by surfel_gs.glsl); 2 the accumulation pass: colour and
// normal weighted by a Gaussian of the distance to the centre, the weight, and the pixel's
// coverage by the disc (surfel_normalise_fs.glsl divides by the weights and shades with the
// normal).
//SSS::Splat::Dec

in vec2 discCoord;
in vec3 pointVC;
flat in vec3 normalVC;
flat in vec4 colour;
flat in float rimMargin;

uniform bool orthographic;
uniform bool coverageOnly;  // pass 2, ghost surfels: coverage alone (vtkSurfelMapper)

//VTK::Output::Dec

void main()
{
  float r2 = dot(discCoord, discCoord);
#if SPLAT_PASS == 2
  // Coverage of the pixel by the disc, from the distance to the rim in pixels: 1 a pixel
  // inside, 1/2 on the rim, 0 a pixel outside (the quad reaches that far, surfel_gs.glsl).
  float r = sqrt(r2);
  float perPixel = max(length(vec2(dFdx(r), dFdy(r))), 1e-6);
  float coverage = clamp(0.5 + (1.0 - r) / perPixel, 0.0, 1.0);
  if (r > 1.0 + rimMargin || coverage <= 0.0)
  {
    discard;
  }
  float w = exp(-2.0 * r2);  // e^-2 at the rim
  vec3 towardsViewer = orthographic ? vec3(0.0, 0.0, 1.0) : normalize(-pointVC);
  vec3 n = dot(normalVC, towardsViewer) < 0.0 ? -normalVC : normalVC;  // shading is two-sided
  gl_FragData[0] = coverageOnly ? vec4(0.0) : vec4(w * colour.rgb, w);
  // alpha blended by its maximum (vtkSurfelMapper)
  gl_FragData[1] = coverageOnly ? vec4(0.0, 0.0, 0.0, coverage) : vec4(w * n, coverage);
#else
  if (r2 > 1.0)
  {
    discard;
  }
#if SPLAT_PASS == 1
  gl_FragData[0] = vec4(0.0);
#else
  gl_FragData[0] = colour;
#endif
#endif
}
