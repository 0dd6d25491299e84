//VTK::System::Dec
// The normalisation pass of blended splatting (vtkSurfelMapper): the weighted sums of the
// accumulation pass (surfel_fs.glsl) over their weight, colour and depth; pixels no splat
// reached are left as they were.

in vec2 texCoord;
uniform sampler2D weightedColour;  // sum of w rgba
uniform sampler2D weightedDepth;   // x: sum of w, y: sum of w z

//VTK::Output::Dec

void main()
{
  vec4 sums = texture(weightedDepth, texCoord);
  if (sums.x <= 0.0)
  {
    discard;
  }
  gl_FragData[0] = texture(weightedColour, texCoord) / sums.x;
  gl_FragDepth = sums.y / sums.x;
}
