//VTK::System::Dec
// Step 2: the finest level of a source pyramid, a cell per surfel. Eq. 17 is linear in E, so
// the lights share their pyramids: each cell's major side (of front and back,
// surfel_irradiance_fs.glsl, the one with more power) goes to pyramid 0, its minor side to
// pyramid 1, each with the normal turned to its side, so that a cell's dipole stays exact
// (one light: all in pyramid 0, as a pyramid of its own). Per cell: its point and weight (the
// power's channels summed), its power E dA, its normal and radius, and the covariance of a disc
// of its area (variance r^2 / 4 along each tangent); the normals' moments and their cross
// term with the points are zero at this level.

uniform sampler2D frontIrradiance;  // rgb: E on the side the surfel's normal faces
uniform sampler2D backIrradiance;   // rgb: E on the other side
uniform int minorSide;              // 0: each cell's major side, 1: its minor side

in vec2 texCoord;  // over the surfel list

//SSS::Gather::Dec

//VTK::Output::Dec

void main()
{
  ivec2 at = ivec2(texCoord * vec2(textureSize(surfelPoint, 0)));
  vec4 point = texelFetch(surfelPoint, at, 0);
  vec3 front = texelFetch(frontIrradiance, at, 0).rgb;
  vec3 back = texelFetch(backIrradiance, at, 0).rgb;
  bool frontMajor = front.r + front.g + front.b >= back.r + back.g + back.b;
  bool takeFront = frontMajor == (minorSide == 0);
  vec4 cell = texelFetch(surfelCell, at, 0);
  vec3 n = (takeFront ? 1.0 : -1.0) * texelFetch(surfelShape, at, 0).xyz;
  vec3 power = point.w > 0.0 ? (takeFront ? front : back) * cell.y : vec3(0.0);
  float weight = power.r + power.g + power.b;
  mat3 cov = 0.25 * cell.x * cell.x * (mat3(1.0) - outerProduct(n, n));
  gl_FragData[0] = vec4(point.xyz, weight);
  gl_FragData[1] = vec4(power, weight > 0.0 ? 1.0 : 0.0);
  gl_FragData[2] = vec4(n, cell.x);
  gl_FragData[3] = vec4(cov[0][0], cov[1][1], cov[2][2], cov[0][1]);
  gl_FragData[4] = vec4(cov[0][2], cov[1][2], 0.0, 0.0);
}
