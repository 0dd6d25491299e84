//VTK::System::Dec
// Builds one level of a source pyramid (the lit cells of step 2) from the level below: summed
// power, power-weighted mean point, normal and covariance of the points, and a radius that
// holds every child's group.

uniform sampler2D mapPoint;   // xyz point (local mm), w: weight (sum of the power's channels)
uniform sampler2D mapPower;   // rgb: E dA, w: lit cells
uniform sampler2D mapNormal;  // xyz: unit normal, w: radius of the group (mm)
uniform sampler2D mapCovariance0;  // xx, yy, zz, xy (mm^2)
uniform sampler2D mapCovariance1;  // xz, yz
uniform ivec2 sourceOrigin;
uniform ivec2 sourceSize;
uniform ivec2 targetSize;

in vec2 texCoord;  // over the target level's rectangle

//VTK::Output::Dec

void main()
{
  ivec2 target = ivec2(texCoord * vec2(targetSize));
  vec4 point[4];
  vec4 normal[4];
  mat3 cov[4];
  float weight = 0.0;
  vec3 pointSum = vec3(0.0);
  vec3 normalSum = vec3(0.0);
  vec4 power = vec4(0.0);
  for (int k = 0; k < 4; ++k)
  {
    ivec2 child = 2 * target + ivec2(k & 1, k >> 1);
    point[k] = vec4(0.0);
    normal[k] = vec4(0.0);
    cov[k] = mat3(0.0);
    if (child.x >= sourceSize.x || child.y >= sourceSize.y)
    {
      continue;
    }
    point[k] = texelFetch(mapPoint, sourceOrigin + child, 0);
    normal[k] = texelFetch(mapNormal, sourceOrigin + child, 0);
    vec4 c0 = texelFetch(mapCovariance0, sourceOrigin + child, 0);
    vec4 c1 = texelFetch(mapCovariance1, sourceOrigin + child, 0);
    cov[k] = mat3(c0.x, c0.w, c1.x, c0.w, c0.y, c1.y, c1.x, c1.y, c0.z);
    power += texelFetch(mapPower, sourceOrigin + child, 0);
    weight += point[k].w;
    pointSum += point[k].w * point[k].xyz;
    normalSum += point[k].w * normal[k].xyz;
  }
  vec3 mean = weight > 0.0 ? pointSum / weight : vec3(0.0);
  float radius = 0.0;
  mat3 covariance = mat3(0.0);
  for (int k = 0; k < 4; ++k)
  {
    if (point[k].w > 0.0)
    {
      vec3 offset = point[k].xyz - mean;
      radius = max(radius, length(offset) + normal[k].w);
      covariance += point[k].w * (cov[k] + outerProduct(offset, offset));
    }
  }
  if (weight > 0.0)
  {
    covariance /= weight;
  }
  float normalLength = length(normalSum);
  gl_FragData[0] = vec4(mean, weight);
  gl_FragData[1] = power;
  gl_FragData[2] = vec4(normalLength > 0.0 ? normalSum / normalLength : vec3(0.0), radius);
  gl_FragData[3] = vec4(covariance[0][0], covariance[1][1], covariance[2][2], covariance[0][1]);
  gl_FragData[4] = vec4(covariance[0][2], covariance[1][2], 0.0, 0.0);
}
