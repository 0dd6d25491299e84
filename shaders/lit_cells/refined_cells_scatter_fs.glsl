//VTK::System::Dec
// Step 2: a refined cell's E on each side (refined_cells_fs.glsl) over its first estimate.

uniform sampler2D refinedFront;
uniform sampler2D refinedBack;

flat in ivec2 cell;
flat in ivec2 refined;

//VTK::Output::Dec

void main()
{
  gl_FragData[0] = vec4(texelFetch(refinedFront, refined, 0).rgb, 0.0);
  gl_FragData[1] = vec4(texelFetch(refinedBack, refined, 0).rgb, 0.0);
}
