//VTK::System::Dec
// The normalisation pass of blended splatting (vtkSurfelMapper): the weighted sums of the
// accumulation pass (surfel_fs.glsl) over their weight, and the view factor from the blended
// normal: for the plain look, Lambert under a headlight; for translucent surfels (alpha 2,
// B from the subsurface pass), Ft(eta, wo) of eq. 14. Plain pixels the splats cover in part
// (a silhouette) are blended over the scene by their coverage. Translucent ones hold linear
// radiance the pass's composite tone maps, so they carry their coverage instead, as alpha
// 3 - coverage (composite_fs.glsl fades them into their neighbours). Pixels no splat reached
// are left as they were. Needs dipole.glsl.

in vec2 texCoord;
uniform sampler2D weightedColour;  // sum of w rgba
uniform sampler2D weightedDepth;   // sum of w, sum of w z
uniform sampler2D weightedNormal;  // sum of w n (n turned towards the viewer), largest coverage
uniform sampler2D splatDepth;      // the visibility pass's: the scene's where no disc covers
uniform bool translucentPixels;    // this draw resolves the translucent pixels, or the plain ones
uniform vec3 ambientDiffuse;       // the plain look's ambient and diffuse coefficients
uniform bool orthographic;
uniform mat4 clipToView;

//SSS::Dipole::Dec

//VTK::Output::Dec

void main()
{
  vec4 sums = texture(weightedDepth, texCoord);
  if (sums.x <= 0.0)
  {
    discard;
  }
  vec4 base = texture(weightedColour, texCoord) / sums.x;
  bool translucent = base.a > 1.5;
  vec4 normal = texture(weightedNormal, texCoord);
  float coverage = min(normal.w, 1.0);
  if (translucent != translucentPixels || coverage <= 0.0)
  {
    discard;
  }
  float depth = sums.y / sums.x;
  vec3 towardsViewer = vec3(0.0, 0.0, 1.0);
  if (!orthographic)
  {
    vec4 p = clipToView * vec4(2.0 * texCoord - 1.0, 2.0 * depth - 1.0, 1.0);
    towardsViewer = normalize(-p.xyz / p.w);
  }
  vec3 n = normal.xyz;
  float length_n = length(n);
  float cosOut = length_n > 0.0 ? abs(dot(n / length_n, towardsViewer)) : 1.0;
  if (translucent)
  {
    gl_FragData[0] = vec4(fresnelTransmittanceRGB(cosOut) * base.rgb, 3.0 - coverage);
  }
  else
  {
    gl_FragData[0] = vec4(base.rgb * (ambientDiffuse.x + ambientDiffuse.y * cosOut), coverage);
  }
  gl_FragDepth = coverage >= 0.5 ? depth : texture(splatDepth, texCoord).r;
}
