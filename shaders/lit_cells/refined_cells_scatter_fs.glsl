//VTK::System::Dec
// Step 2: a refined cell's E (refined_cells_fs.glsl) over its first estimate, with the power and
// weight that follow from it (surfel_irradiance_fs.glsl's first three targets).

uniform sampler2D refinedE;

//SSS::Gather::Dec

flat in ivec2 cell;
flat in ivec2 refined;

//VTK::Output::Dec

void main()
{
  vec3 E = texelFetch(refinedE, refined, 0).rgb;
  vec3 power = E * texelFetch(surfelCell, cell, 0).y;
  float weight = power.r + power.g + power.b;
  gl_FragData[0] = vec4(E, 0.0);
  gl_FragData[1] = vec4(texelFetch(surfelPoint, cell, 0).xyz, weight);
  gl_FragData[2] = vec4(power, weight > 0.0 ? 1.0 : 0.0);
}
