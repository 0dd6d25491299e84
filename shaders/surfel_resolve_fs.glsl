//VTK::System::Dec
// Step 2, per surfel: B at the surfel = its own gather (all of the kernel, or the near part,
// from the receivers' pass) plus the far part: gathered at the surfel too, or interpolated
// trilinearly from the virtual points.

flat in vec3 receiver;
flat in ivec2 gatheredAt;  // the surfel's texel in the receivers' pass

uniform bool useGrid;
uniform sampler3D gridRadiance;  // (B, 1) at kept points, 0 at pruned ones
uniform vec3 gridOrigin;         // local mm
uniform float gridSpacing;       // mm
uniform vec3 gridDims;
uniform bool gatherAtSurfel;
uniform sampler2D gathered;  // B of the receivers' pass
uniform bool addFar;
uniform sampler2D gatheredFar;  // the far part at the same texels

//VTK::Output::Dec

void main()
{
  vec3 B = gatherAtSurfel ? texelFetch(gathered, gatheredAt, 0).rgb : vec3(0.0);
  if (addFar)
  {
    B += texelFetch(gatheredFar, gatheredAt, 0).rgb;
  }
  if (useGrid)
  {
    vec4 far = texture(gridRadiance, ((receiver - gridOrigin) / gridSpacing + 0.5) / gridDims);
    if (far.w > 1e-6)
    {
      B += far.rgb / far.w;
    }
  }
  gl_FragData[0] = vec4(B, 1.0);
}
