//VTK::System::Dec
// Step 2, at every surfel: the near field from its row of the table, plus the far field by a
// walk of the lights' source pyramids when the kernel reaches past the near field. Drawn as
// one quad over the surfel list.

in vec2 texCoord;  // over the surfel list

uniform bool addFarField;

//SSS::Gather::Dec

//VTK::Output::Dec

void main()
{
  ivec2 at = ivec2(texCoord * vec2(textureSize(surfelPoint, 0)));
  vec4 point = texelFetch(surfelPoint, at, 0);
  vec3 B = vec3(0.0);
  if (point.w > 0.0)
  {
    B = nearFieldB(at);
    if (addFarField)
    {
      B += farFieldB(point.xyz);
    }
  }
  gl_FragData[0] = vec4(B, 1.0);
}
