//VTK::System::Dec
// The normalisation pass of blended splatting (vtkSurfelMapper): the weighted sums of the
// accumulation pass (surfel_fs.glsl) over their weight, the depth of the front surface (the
// visibility pass's, brought forward by the push), and the view factor from the blended
// normal: for the plain look, Lambert under a headlight; for translucent surfels (B from the
// subsurface pass), Ft(eta, wo) of eq. 14. Plain pixels the splats cover in part
// (a silhouette) are blended over the scene by their coverage. Translucent ones hold linear
// radiance the pass's composite tone maps, so they carry their coverage instead, as alpha
// 3 - coverage (composite_fs.glsl fades them into their neighbours). Pixels no splat reached
// are left as they were. The pass that gives the radiance fills the Outgoing hook below: it
// defines SSS_TRANSLUCENT and fresnelTransmittanceRGB (dipole.glsl).

in vec2 texCoord;
uniform sampler2D weightedColour;  // sum of w rgb, sum of w
uniform sampler2D weightedNormal;  // sum of w n (n turned towards the viewer), largest coverage
uniform sampler2D splatDepth;      // the visibility pass's: the scene's where no disc covers
uniform vec3 ambientDiffuse;       // the plain look's ambient and diffuse coefficients
uniform bool orthographic;
uniform mat4 clipToView;
uniform mat4 viewToClip;
uniform float blendDepthVC;  // how far surfel_gs.glsl pushed the visibility pass back

//SSS::Outgoing::Dec

//VTK::Output::Dec

void main()
{
  vec4 sums = texture(weightedColour, texCoord);
  vec4 normal = texture(weightedNormal, texCoord);
  float coverage = min(normal.w, 1.0);
  if (sums.a <= 0.0 || coverage <= 0.0)
  {
    discard;
  }
  vec3 base = sums.rgb / sums.a;
  // Where a disc covers the pixel centre, the visibility pass holds the front surface pushed
  // back along the view ray; elsewhere the scene's depth, which stays.
  float depth = texture(splatDepth, texCoord).r;
  vec4 back = clipToView * vec4(2.0 * texCoord - 1.0, 2.0 * depth - 1.0, 1.0);
  vec3 p = back.xyz / back.w;
  if (coverage >= 0.5)
  {
    p = orthographic ? p + vec3(0.0, 0.0, blendDepthVC)
                     : p * max(length(p) - blendDepthVC, 0.0) / length(p);
    vec4 clip = viewToClip * vec4(p, 1.0);
    depth = 0.5 * clip.z / clip.w + 0.5;
  }
  vec3 towardsViewer = orthographic ? vec3(0.0, 0.0, 1.0) : normalize(-p);
  vec3 n = normal.xyz;
  float length_n = length(n);
  float cosOut = length_n > 0.0 ? abs(dot(n / length_n, towardsViewer)) : 1.0;
#ifdef SSS_TRANSLUCENT
  gl_FragData[0] = vec4(fresnelTransmittanceRGB(cosOut) * base, 3.0 - coverage);
#else
  gl_FragData[0] = vec4(base * (ambientDiffuse.x + ambientDiffuse.y * cosOut), coverage);
#endif
  gl_FragDepth = depth;
}
