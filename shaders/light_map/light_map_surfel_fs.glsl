//VTK::System::Dec
// Step 1 for the surfel pipeline: which surfel the light sees at each texel (the nearest disc,
// by the depth test), as its texel in the surfel list; light_visibility.glsl lifts the seen
// point onto that surfel's local surface, as core/light_map/light_map.cpp does.

in vec2 discCoord;
flat in vec4 colour;  // xy: the surfel's list texel (surfel_vs.glsl's shape hook)

//VTK::Output::Dec

void main()
{
  if (dot(discCoord, discCoord) > 1.0)
  {
    discard;
  }
  gl_FragData[0] = vec4(colour.xy, 0.0, 0.0);
}
