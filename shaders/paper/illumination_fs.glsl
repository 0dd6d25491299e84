//VTK::System::Dec
// Step 1, the illumination map (paper eq. 15): each texel keeps the point the light sees,
// lifted off its flat disc onto the disc's local surface (core/surfels/local_surface.h: the point
// kappa |d|^2 / 2 below the disc's plane at offset d from its centre, the normal tilted by
// kappa d), that normal turned towards the light, E dA = E_light Ft(eta, theta_i) times the
// texel's area (the cosine of eq. 15 cancels against the surface a texel covers; none where
// the lifted normal turns away from the light; the paper's taps read it). A unit normal marks
// a texel that sees a disc (the visibility test of light_maps.glsl), lit or not.

in vec2 discCoord;
in vec3 pointVC;
flat in vec3 normalVC;
flat in vec4 colour;
flat in vec3 centreVC;
flat in float curvature;

uniform mat3 viewToLocal;      // light view -> local mm frame
uniform vec3 towardsLight;     // local frame, unit
uniform vec3 irradianceArea;   // E_light per channel times the texel area (mm^2)
uniform bool albedoFromColour;

//SSS::Dipole::Dec

//VTK::Output::Dec

void main()
{
  if (dot(discCoord, discCoord) > 1.0)
  {
    discard;
  }
  vec3 d = pointVC - centreVC;  // on the disc's plane
  vec3 lifted = viewToLocal * (pointVC - 0.5 * curvature * dot(d, d) * normalVC);
  vec3 n = normalize(viewToLocal * (normalVC + curvature * d));
  if (dot(viewToLocal * normalVC, towardsLight) < 0.0)
  {
    n = -n;  // the side of the disc the light sees
  }
  float cosI = dot(n, towardsLight);
  vec3 power = cosI > 0.0 ? irradianceArea * fresnelTransmittanceRGB(cosI) : vec3(0.0);
  if (albedoFromColour)
  {
    power *= colour.rgb;
  }
  float lit = cosI > 0.0 ? 1.0 : 0.0;
  gl_FragData[0] = vec4(lifted, power.r + power.g + power.b);
  gl_FragData[1] = vec4(power, lit);  // w counts lit texels
  gl_FragData[2] = vec4(n, 0.0);
}
