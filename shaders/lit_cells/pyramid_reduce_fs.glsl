//VTK::System::Dec
// Builds one level of a source pyramid (the lit cells of step 2) from the level below: summed
// power, power-weighted mean point, normal and covariance of the points, and a radius that
// holds every child's group; and the moments that give each dipole pole's covariance: a pole
// at q = p + t n (t = -z_r or z_v) has cov(q) = C_pp + t S + t^2 C_nn, with S = C_pn + C_np.
// The mean normal is not normalised, so the mean of the poles is exactly mean p + t mean n.

uniform sampler2D mapPoint;   // xyz point (local mm), w: weight (sum of the power's channels)
uniform sampler2D mapPower;   // rgb: E dA, w: lit cells
uniform sampler2D mapNormal;  // xyz: mean normal (unit for a cell), w: radius of the group (mm)
uniform sampler2D mapCovariance0;  // points: xx, yy, zz, xy (mm^2)
uniform sampler2D mapCovariance1;  // points: xz, yz; normal-point cross term S: xx, yy
uniform sampler2D mapCovariance2;  // S: zz, xy, xz, yz (mm)
uniform sampler2D mapCovariance3;  // normals: xx, yy, zz, xy
uniform sampler2D mapCovariance4;  // normals: xz, yz
uniform ivec2 sourceOrigin;
uniform ivec2 sourceSize;
uniform ivec2 targetSize;

in vec2 texCoord;  // over the target level's rectangle

//VTK::Output::Dec

mat3 symmetric(float xx, float yy, float zz, float xy, float xz, float yz)
{
  return mat3(xx, xy, xz, xy, yy, yz, xz, yz, zz);
}

void main()
{
  ivec2 target = ivec2(texCoord * vec2(targetSize));
  vec4 point[4];
  vec4 normal[4];
  mat3 cpp[4], cpn[4], cnn[4];
  float weight = 0.0;
  vec3 pointSum = vec3(0.0);
  vec3 normalSum = vec3(0.0);
  vec4 power = vec4(0.0);
  for (int k = 0; k < 4; ++k)
  {
    ivec2 child = 2 * target + ivec2(k & 1, k >> 1);
    point[k] = vec4(0.0);
    normal[k] = vec4(0.0);
    cpp[k] = mat3(0.0);
    cpn[k] = mat3(0.0);
    cnn[k] = mat3(0.0);
    if (child.x >= sourceSize.x || child.y >= sourceSize.y)
    {
      continue;
    }
    ivec2 at = sourceOrigin + child;
    point[k] = texelFetch(mapPoint, at, 0);
    normal[k] = texelFetch(mapNormal, at, 0);
    vec4 c0 = texelFetch(mapCovariance0, at, 0);
    vec4 c1 = texelFetch(mapCovariance1, at, 0);
    vec4 c2 = texelFetch(mapCovariance2, at, 0);
    vec4 c3 = texelFetch(mapCovariance3, at, 0);
    vec4 c4 = texelFetch(mapCovariance4, at, 0);
    cpp[k] = symmetric(c0.x, c0.y, c0.z, c0.w, c1.x, c1.y);
    cpn[k] = symmetric(c1.z, c1.w, c2.x, c2.y, c2.z, c2.w);
    cnn[k] = symmetric(c3.x, c3.y, c3.z, c3.w, c4.x, c4.y);
    power += texelFetch(mapPower, at, 0);
    weight += point[k].w;
    pointSum += point[k].w * point[k].xyz;
    normalSum += point[k].w * normal[k].xyz;
  }
  vec3 mean = weight > 0.0 ? pointSum / weight : vec3(0.0);
  vec3 meanNormal = weight > 0.0 ? normalSum / weight : vec3(0.0);
  float radius = 0.0;
  mat3 Cpp = mat3(0.0), S = mat3(0.0), Cnn = mat3(0.0);
  for (int k = 0; k < 4; ++k)
  {
    if (point[k].w > 0.0)
    {
      vec3 dp = point[k].xyz - mean;
      vec3 dn = normal[k].xyz - meanNormal;
      radius = max(radius, length(dp) + normal[k].w);
      Cpp += point[k].w * (cpp[k] + outerProduct(dp, dp));
      S += point[k].w * (cpn[k] + outerProduct(dp, dn) + outerProduct(dn, dp));
      Cnn += point[k].w * (cnn[k] + outerProduct(dn, dn));
    }
  }
  if (weight > 0.0)
  {
    Cpp /= weight;
    S /= weight;
    Cnn /= weight;
  }
  gl_FragData[0] = vec4(mean, weight);
  gl_FragData[1] = power;
  gl_FragData[2] = vec4(meanNormal, radius);
  gl_FragData[3] = vec4(Cpp[0][0], Cpp[1][1], Cpp[2][2], Cpp[0][1]);
  gl_FragData[4] = vec4(Cpp[0][2], Cpp[1][2], S[0][0], S[1][1]);
  gl_FragData[5] = vec4(S[2][2], S[0][1], S[0][2], S[1][2]);
  gl_FragData[6] = vec4(Cnn[0][0], Cnn[1][1], Cnn[2][2], Cnn[0][1]);
  gl_FragData[7] = vec4(Cnn[0][2], Cnn[1][2], 0.0, 0.0);
}
