//VTK::System::Dec
// Camera view of a surfel: the disc's colour, computed per surfel in surfel_vs.glsl.

in vec2 discCoord;
flat in vec4 colour;

//VTK::Output::Dec

void main()
{
  if (dot(discCoord, discCoord) > 1.0)
  {
    discard;
  }
  gl_FragData[0] = colour;
}
