// Dipole diffusion (Jensen et al. 2001; the paper's eq. 3-13) and Fresnel transmittance,
// per RGB channel. Lengths in mm. Shared by every stage that sums the kernel.

uniform vec3 zR;          // eq. 7: 1 / sigma_t'
uniform vec3 zV;          // eq. 10: z_r + 4 A D
uniform vec3 sTr;         // eq. 6: sqrt(3 sigma_a sigma_t')
uniform vec3 rdFactor;    // alpha' / (4 pi)
uniform vec3 eta;         // relative index of refraction

const float PI = 3.14159265358979;

// One channel of eq. 3 for a source at p with normal n and a receiver at x; distances are
// clamped at their planar minima (d_r >= z_r, d_v >= z_v), as in the CPU reference.
float channelRd(vec3 p, vec3 n, vec3 x, float zr, float zv, float s, float factor)
{
  float dR = max(length(p - zr * n - x), zr);
  float dV = max(length(p + zv * n - x), zv);
  return factor *
    (zr * (1.0 + s * dR) * exp(-s * dR) / (dR * dR * dR) +
      zv * (1.0 + s * dV) * exp(-s * dV) / (dV * dV * dV));
}

// Eq. 3 in the three channels, spelled out rather than looped (see secondOrderHolds).
vec3 dipoleRd(vec3 p, vec3 n, vec3 x)
{
  return vec3(channelRd(p, n, x, zR.r, zV.r, sTr.r, rdFactor.r),
    channelRd(p, n, x, zR.g, zV.g, sTr.g, rdFactor.g),
    channelRd(p, n, x, zR.b, zV.b, sTr.b, rdFactor.b));
}

// One pole's term of eq. 3 (z (1 + s d) e^(-s d) / d^3) at the pole's distance from x,
// averaged over sources with covariance `cov` around the pole by its second-order Taylor
// expansion. The sources lie within `reach` of the pole in the plane normal to n; where that
// disc comes nearer to x than the planar minimum distance z (inside it the term is flat, a
// kink the expansion cannot follow), the term at the pole as it is.
float poleTermSecondOrder(vec3 pole, vec3 n, float reach, vec3 x, float z, float s, mat3 cov)
{
  vec3 offset = pole - x;
  float d = length(offset);
  float h = dot(offset, n);
  float off = max(length(offset - h * n) - reach, 0.0);
  if (h * h + off * off <= z * z)
  {
    float dc = max(d, z);
    return z * (1.0 + s * dc) * exp(-s * dc) / (dc * dc * dc);
  }
  float trace = cov[0][0] + cov[1][1] + cov[2][2];
  float sd = s * d;
  float e = exp(-sd);
  float d3 = d * d * d;
  float value = z * (1.0 + sd) * e / d3;
  float d1 = -z * e * (3.0 + 3.0 * sd + sd * sd) / (d3 * d);
  float d2 = z * e * (12.0 + 12.0 * sd + 5.0 * sd * sd + sd * sd * sd) / (d3 * d * d);
  vec3 u = offset / d;
  float along = dot(u, cov * u);
  return value + 0.5 * (d2 * along + d1 / d * (trace - along));
}

// The sources of a group as their poles see them: points p_i with normals n_i have poles at
// p_i + t n_i (t = -z_r for the real one, z_v for the virtual one), with mean p + t n (p, n
// the group's mean point and unnormalised mean normal) and covariance Cpp + t S + t^2 Cnn.
struct SourceGroup
{
  vec3 p;
  vec3 n;
  float reach;  // the sources lie within it of p (a cell: its disc radius)
  mat3 Cpp, S, Cnn;
  vec3 traces;  // of Cpp, S and Cnn
};

float poleSpread(SourceGroup g, float t)
{
  float trace = g.traces.x + t * g.traces.y + t * t * g.traces.z;
  return 2.0 * sqrt(max(trace, 0.0));
}

// Whether poleTermSecondOrder expands both poles of every channel at x: each pole's mean
// farther from x than its planar minimum distance plus the poles' spread (twice their RMS
// distance from the mean), so that no pole of the group reaches the clamp. The far field's
// walk calls this and dipoleRdSecondOrder at every node; they spell out the three channels
// instead of looping over them, because llvmpipe counts every loop iteration of an invocation
// against its limit of 65,535 (far_field.glsl).
bool polesClear(SourceGroup g, vec3 x, float zr, float zv)
{
  return length(g.p - zr * g.n - x) > zr + poleSpread(g, -zr) &&
    length(g.p + zv * g.n - x) > zv + poleSpread(g, zv);
}

bool secondOrderHolds(SourceGroup g, vec3 x)
{
  return polesClear(g, x, zR.r, zV.r) && polesClear(g, x, zR.g, zV.g) &&
    polesClear(g, x, zR.b, zV.b);
}

// Eq. 3 summed over a group of sources in one channel, each pole by its own mean and
// covariance.
float groupRd(SourceGroup g, vec3 x, float zr, float zv, float s, float factor)
{
  return factor *
    (poleTermSecondOrder(g.p - zr * g.n, g.n, g.reach, x, zr, s, g.Cpp - zr * g.S + zr * zr * g.Cnn) +
      poleTermSecondOrder(g.p + zv * g.n, g.n, g.reach, x, zv, s, g.Cpp + zv * g.S + zv * zv * g.Cnn));
}

vec3 dipoleRdSecondOrder(SourceGroup g, vec3 x)
{
  return vec3(groupRd(g, x, zR.r, zV.r, sTr.r, rdFactor.r), groupRd(g, x, zR.g, zV.g, sTr.g, rdFactor.g),
    groupRd(g, x, zR.b, zV.b, sTr.b, rdFactor.b));
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
