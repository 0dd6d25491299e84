//VTK::System::Dec
// Step 1, the illumination map (paper eq. 15): each texel keeps the point of the surfel the
// light sees, its normal turned towards the light, and E dA = E_light Ft(eta, theta_i) times
// the texel's area (the cosine of eq. 15 cancels against the surface a texel covers), and the
// covariance of the surface patch the texel covers (for the pyramid's second-order terms).

in vec2 discCoord;
in vec3 pointVC;
flat in vec3 normalVC;
flat in vec4 colour;

uniform mat3 viewToLocal;      // light view -> local mm frame
uniform vec3 towardsLight;     // local frame, unit
uniform vec3 irradianceArea;   // E_light per channel times the texel area (mm^2)
uniform bool albedoFromColour;
uniform vec3 mapAxisU;    // the map's image axes in the local frame
uniform vec3 mapAxisV;
uniform float texelEdge;  // mm

//SSS::Dipole::Dec

//VTK::Output::Dec

void main()
{
  if (dot(discCoord, discCoord) > 1.0)
  {
    discard;
  }
  vec3 n = viewToLocal * normalVC;
  if (dot(n, towardsLight) < 0.0)
  {
    n = -n;
  }
  vec3 power = irradianceArea * fresnelTransmittanceRGB(dot(n, towardsLight));
  if (albedoFromColour)
  {
    power *= colour.rgb;
  }
  gl_FragData[0] = vec4(viewToLocal * pointVC, power.r + power.g + power.b);
  gl_FragData[1] = vec4(power, 1.0);  // w counts lit texels
  gl_FragData[2] = vec4(n, 0.0);      // w: spread along the light (none for one texel)
  // The patch is the texel square lifted onto the disc's plane: its edges are the map axes
  // tilted by the slope along the light (clamped at grazing), each uniform over one texel.
  float cosL = max(dot(n, towardsLight), 0.1);
  vec3 edgeU = mapAxisU - dot(n, mapAxisU) / cosL * towardsLight;
  vec3 edgeV = mapAxisV - dot(n, mapAxisV) / cosL * towardsLight;
  float var = texelEdge * texelEdge / 12.0;
  mat3 cov = var * (outerProduct(edgeU, edgeU) + outerProduct(edgeV, edgeV));
  gl_FragData[3] = vec4(cov[0][0], cov[1][1], cov[2][2], cov[0][1]);
  gl_FragData[4] = vec4(cov[0][2], cov[1][2], 0.0, 0.0);
}
