// Dipole diffusion (Jensen et al. 2001; the paper's eq. 3-13) and Fresnel transmittance,
// per RGB channel. Lengths in mm. Shared by every stage that sums the kernel.

uniform vec3 zR;          // eq. 7: 1 / sigma_t'
uniform vec3 zV;          // eq. 10: z_r + 4 A D
uniform vec3 sTr;         // eq. 6: sqrt(3 sigma_a sigma_t')
uniform vec3 rdFactor;    // alpha' / (4 pi)
uniform vec3 eta;         // relative index of refraction

const float PI = 3.14159265358979;

// Eq. 3 for a source at p with normal n and a receiver at x; distances are clamped at their
// planar minima (d_r >= z_r, d_v >= z_v), as in the CPU reference.
vec3 dipoleRd(vec3 p, vec3 n, vec3 x)
{
  vec3 rd;
  for (int c = 0; c < 3; ++c)
  {
    float dR = max(length(p - zR[c] * n - x), zR[c]);
    float dV = max(length(p + zV[c] * n - x), zV[c]);
    float real = zR[c] * (1.0 + sTr[c] * dR) * exp(-sTr[c] * dR) / (dR * dR * dR);
    float virt = zV[c] * (1.0 + sTr[c] * dV) * exp(-sTr[c] * dV) / (dV * dV * dV);
    rd[c] = rdFactor[c] * (real + virt);
  }
  return rd;
}

// One pole's term of eq. 3 (z (1 + s d) e^(-s d) / d^3) at the pole's distance from x,
// averaged over sources with covariance `cov` around the pole by its second-order Taylor
// expansion; inside the planar minimum distance the term is flat and taken as it is.
float poleTermSecondOrder(vec3 pole, vec3 x, float z, float s, mat3 cov)
{
  vec3 offset = pole - x;
  float d = length(offset);
  if (d <= z)
  {
    return (1.0 + s * z) * exp(-s * z) / (z * z);
  }
  float sd = s * d;
  float e = exp(-sd);
  float d3 = d * d * d;
  float value = z * (1.0 + sd) * e / d3;
  float d1 = -z * e * (3.0 + 3.0 * sd + sd * sd) / (d3 * d);
  float d2 = z * e * (12.0 + 12.0 * sd + 5.0 * sd * sd + sd * sd * sd) / (d3 * d * d);
  vec3 u = offset / d;
  float along = dot(u, cov * u);
  float trace = cov[0][0] + cov[1][1] + cov[2][2];
  return value + 0.5 * (d2 * along + d1 / d * (trace - along));
}

// Eq. 3 summed over a group of sources with mean point p, normal n and point covariance cov.
vec3 dipoleRdSecondOrder(vec3 p, vec3 n, mat3 cov, vec3 x)
{
  vec3 rd;
  for (int c = 0; c < 3; ++c)
  {
    rd[c] = rdFactor[c] * (poleTermSecondOrder(p - zR[c] * n, x, zR[c], sTr[c], cov) +
      poleTermSecondOrder(p + zV[c] * n, x, zV[c], sTr[c], cov));
  }
  return rd;
}

// 1 - Fresnel reflectance of an unpolarised ray (exact dielectric formula), from the side of
// index 1 into the medium of index etaIn, at incidence cosine cosI.
float fresnelTransmittance(float etaIn, float cosI)
{
  if (etaIn == 1.0)
  {
    return 1.0;  // no boundary
  }
  cosI = min(abs(cosI), 1.0);
  float sinT2 = (1.0 - cosI * cosI) / (etaIn * etaIn);
  if (sinT2 >= 1.0)
  {
    return 0.0;
  }
  float cosT = sqrt(1.0 - sinT2);
  float rs = (cosI - etaIn * cosT) / (cosI + etaIn * cosT);
  float rp = (etaIn * cosI - cosT) / (etaIn * cosI + cosT);
  return 1.0 - 0.5 * (rs * rs + rp * rp);
}

vec3 fresnelTransmittanceRGB(float cosI)
{
  return vec3(fresnelTransmittance(eta.r, cosI), fresnelTransmittance(eta.g, cosI),
    fresnelTransmittance(eta.b, cosI));
}
