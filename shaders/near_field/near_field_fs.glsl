//VTK::System::Dec
// Step 2, at every surfel: the near field from its row of the table (one quad over the surfel
// list), then the far field when the kernel reaches past it, one quad per node of a source
// pyramid whose cells it sums (far_field.glsl), added by blending.

in vec2 texCoord;  // over the surfel list

uniform bool addNearField;
uniform bool addFarField;
uniform int walkPyramid;
uniform ivec2 walkRoot;  // a node of walkPyramid: its texel in level walkRootLevel
uniform int walkRootLevel;

//SSS::Gather::Dec

//VTK::Output::Dec

void main()
{
  ivec2 at = ivec2(texCoord * vec2(textureSize(surfelPoint, 0)));
  vec4 point = texelFetch(surfelPoint, at, 0);
  vec3 B = vec3(0.0);
  if (point.w > 0.0)
  {
    if (addNearField)
    {
      B = nearFieldB(at);
    }
    if (addFarField)
    {
      B += farFieldB(point.xyz, walkPyramid, ivec3(walkRoot, walkRootLevel));
    }
  }
  gl_FragData[0] = vec4(B, addNearField ? 1.0 : 0.0);
}
