//VTK::System::Dec
// Each surfel's B into its input-order texel for the camera view: from the surfel pipeline's
// list (NEAR_FAR), or interpolated trilinearly from the paper's virtual points.

flat in vec3 receiver;
flat in ivec2 gatheredAt;  // the surfel's texel in the surfel list

uniform bool useGrid;
uniform sampler3D gridRadiance;  // (B, 1) at kept points, 0 at pruned ones
uniform vec3 gridOrigin;         // local mm
uniform float gridSpacing;       // mm
uniform vec3 gridDims;
uniform sampler2D gathered;      // B per surfel, surfel list layout

//VTK::Output::Dec

void main()
{
  vec3 B = vec3(0.0);
  if (useGrid)
  {
    vec4 grid = texture(gridRadiance, ((receiver - gridOrigin) / gridSpacing + 0.5) / gridDims);
    if (grid.w > 1e-6)
    {
      B = grid.rgb / grid.w;
    }
  }
  else
  {
    B = texelFetch(gathered, gatheredAt, 0).rgb;
  }
  gl_FragData[0] = vec4(B, 1.0);
}
