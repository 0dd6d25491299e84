// The far field of eq. 17 at a receiver: a walk of a source pyramid (the lit cells of all lights,
// lit_cell_sources_fs.glsl, reduced by pyramid_reduce_fs.glsl) over the cells whose surfel lies
// farther than farFrom (the near-field table holds the nearer ones whole), taking a group of
// cells as one source, each dipole pole by its own mean and covariance (dipole.glsl), once its
// spread (twice the RMS distance of its points from their mean) is below openingAngle times its
// distance from x, its radius spans at most maxGroupDiffusionLengths of every channel whose
// kernel still carries a share of its integral there (the group's nearest point within
// sizeBoundReach), and x lies beyond the clamp of every pole by the poles' spread
// (secondOrderHolds); a cell wider than a quarter of its distance from x (where the spacing is
// coarse for the near-field table's reach, as in the far rows of a Kinect scan)
// by a ring rule over its disc (cellRd). x is a surfel, so no other surfel's cell reaches
// nearer to x than to its own surfel (cells are Voronoi cells): a disc is taken only on its
// surfel's side of the bisector with x, and a cell beyond twice supportRadius adds nothing. The
// GPU form of the CPU reference's source tree (core/far_field/source_tree.h). Needs dipole.glsl.

uniform sampler2D sourcePoint;        // xyz: power-weighted mean point, w: summed power
uniform sampler2D sourcePower;        // rgb: E dA
uniform sampler2D sourceNormal;       // xyz: power-weighted mean normal (not normalised), w: radius of the group (mm)
uniform sampler2D sourceCovariance0;  // points: xx, yy, zz, xy (pyramid_reduce_fs.glsl)
uniform sampler2D sourceCovariance1;  // points: xz, yz; S: xx, yy
uniform sampler2D sourceCovariance2;  // S: zz, xy, xz, yz
uniform sampler2D sourceCovariance3;  // normals: xx, yy, zz, xy
uniform sampler2D sourceCovariance4;  // normals: xz, yz
uniform vec4 sourceLevelRect[SSS_MAX_PYRAMIDS * SSS_MAX_LEVELS];  // atlas origin xy, size zw
uniform float openingAngle;
uniform float maxGroupDiffusionLengths;
uniform float supportRadius;  // mm: beyond it Rd has lost all but 1e-7 of its integral
uniform float farFrom;        // mm
uniform vec3 sizeBoundReach;  // mm, per channel: beyond it a group's size is bound by the
                              // opening angle alone (sssFarField.h)

const int cellRulePieces = 64;  // cellRd's pieces are at least a 64th of the disc's area
const int wideCellsPerWalk = 16;  // most cells a walk sums by cellRd; the rest by expansion

// Eq. 3 over a cell's disc (centre p, unit normal n, radius r) at distance d from x by equal-area
// rings about a piece wide (max(z_r / 2, d / 4), and no finer than the disc's area over
// cellRulePieces), each with points a piece apart at even angles: a rule whose first moment
// vanishes and whose second is the disc's (at most about 100 points), as the CPU reference sums a
// near source (core/far_field/source_tree.cpp add_sample). Points nearer to x than to p are not
// the cell's: the others share its power. For the cells near x whose disc is too wide for the
// second-order expansion.
vec3 cellRd(vec3 p, vec3 n, float r, vec3 x, float d)
{
  float piece = max(max(0.5 * min(zR.r, min(zR.g, zR.b)), 0.25 * d),
    r * sqrt(PI / float(cellRulePieces)));
  vec3 helper = abs(n.x) < 0.7 ? vec3(1.0, 0.0, 0.0) : vec3(0.0, 1.0, 0.0);
  vec3 u = normalize(cross(n, helper));
  vec3 v = cross(n, u);
  int rings = max(1, int(ceil(r / piece)));
  vec3 sum = vec3(0.0);
  float kept = 0.0;  // the shares of the points on p's side
  bool clipped = false;
  for (int ring = 0; ring < rings; ++ring)
  {
    float rho = r * sqrt((float(ring) + 0.5) / float(rings));
    int m = max(3, int(ceil(6.283185307 * rho / piece)));
    float share = 1.0 / (float(rings) * float(m));
    for (int j = 0; j < m; ++j)
    {
      float angle = 6.283185307 * (float(j) + 0.5 * float(ring % 2)) / float(m);
      vec3 q = p + rho * (cos(angle) * u + sin(angle) * v);
      if (distance(q, x) >= rho)
      {
        sum += share * dipoleRd(q, n, x);
        kept += share;
      }
      else
      {
        clipped = true;
      }
    }
  }
  return clipped && kept > 0.0 ? sum / kept : sum;
}

// A node (xy: texel in its level, z: level) in one word for the walk's stack, a third of the
// memory an ivec3 stack moves per push and pop: levels below SSS_MAX_LEVELS (15), texels below
// 2^14 (sssSurfelList.cxx caps a list at 16384 a side).
uint packNode(ivec3 node)
{
  return (uint(node.z) << 28) | (uint(node.y) << 14) | uint(node.x);
}

ivec3 unpackNode(uint word)
{
  return ivec3(int(word & 16383u), int((word >> 14) & 16383u), int(word >> 28));
}

// The part of the far field at x from the cells under one node `root` (xy: texel in its
// level, z: level) of pyramid `pyramid` (sssLitCells.h). Step 2 sums it over the nodes of a
// level low enough that no walk visits more than 21,845 nodes: llvmpipe ends a shader invocation's
// loops after 65,535 iterations in all, which a walk of a whole large pyramid can exceed. A
// node costs one iteration of the walk and, when opened, four of the loop over its children:
// at most 21,845 + 4 x 5,461 = 43,689; the wide cells' rings add at most 16 x (5 rings +
// about 100 points), under 1,700. The loops over the three channels that a node would
// add are spelled out instead (dipole.glsl).
vec3 farFieldB(vec3 x, int pyramid, ivec3 root)
{
  vec3 sum = vec3(0.0);
  uint stack[64];  // nodes packed by packNode
  int base = pyramid * SSS_MAX_LEVELS;
  int depth = 0;
  stack[depth++] = packNode(root);
  // Cells wider than a quarter of their distance from x, summed by cellRd after the walk so
  // that its rings do not run inside the walk's loop.
  ivec2 wideCell[wideCellsPerWalk];
  int wideCells = 0;
  while (depth > 0)
  {
    ivec3 node = unpackNode(stack[--depth]);
    int level = node.z;
    ivec2 texel = ivec2(sourceLevelRect[base + level].xy) + node.xy;
    vec4 point = texelFetch(sourcePoint, texel, 0);
    if (point.w <= 0.0)
    {
      continue;
    }
    vec4 normal = texelFetch(sourceNormal, texel, 0);
    float size = normal.w;
    float d = distance(x, point.xyz);
    if (d - size > supportRadius || d + size < farFrom ||
      (level == 0 && (d < farFrom || 0.5 * d > supportRadius)))
    {
      continue;
    }
    if (level == 0 && size > 0.25 * d && wideCells < wideCellsPerWalk)
    {
      wideCell[wideCells++] = texel;
      continue;
    }
    bool straddles = d - size < farFrom;  // holds cells nearer than farFrom: open it
    // The fastest decay among the channels whose size bound still holds here (no loop: see
    // dipole.glsl).
    vec3 significant = step(vec3(d - size), sizeBoundReach) * sTr;
    float sTrSignificant = max(max(significant.r, significant.g), significant.b);
    vec4 c0 = texelFetch(sourceCovariance0, texel, 0);
    vec4 c1 = texelFetch(sourceCovariance1, texel, 0);
    vec4 c2 = texelFetch(sourceCovariance2, texel, 0);
    vec4 c3 = texelFetch(sourceCovariance3, texel, 0);
    vec4 c4 = texelFetch(sourceCovariance4, texel, 0);
    SourceGroup group;
    group.p = point.xyz;
    group.n = normal.xyz;
    group.reach = level == 0 ? size : 0.0;  // a cell's disc; a group passed secondOrderHolds
    group.Cpp = mat3(c0.x, c0.w, c1.x, c0.w, c0.y, c1.y, c1.x, c1.y, c0.z);
    group.S = mat3(c1.z, c2.y, c2.z, c2.y, c1.w, c2.w, c2.z, c2.w, c2.x);
    group.Cnn = mat3(c3.x, c3.w, c4.x, c3.w, c3.y, c4.y, c4.x, c4.y, c3.z);
    group.traces = vec3(c0.x + c0.y + c0.z, c1.z + c1.w + c2.x, c3.x + c3.y + c3.z);
    float spread = 2.0 * sqrt(max(group.traces.x, 0.0));
    bool smallEnough = spread < openingAngle * d &&
      size * sTrSignificant < maxGroupDiffusionLengths && secondOrderHolds(group, x);
    if (level == 0 || (smallEnough && !straddles) || depth > 60)
    {
      vec3 power = texelFetch(sourcePower, texel, 0).rgb;
      sum += power * dipoleRdSecondOrder(group, x);
      continue;
    }
    ivec2 childSize = ivec2(sourceLevelRect[base + level - 1].zw);
    for (int k = 3; k >= 0; --k)
    {
      ivec2 child = 2 * node.xy + ivec2(k & 1, k >> 1);
      if (child.x < childSize.x && child.y < childSize.y)
      {
        stack[depth++] = packNode(ivec3(child, level - 1));
      }
    }
  }
  for (int k = 0; k < wideCells; ++k)
  {
    vec4 point = texelFetch(sourcePoint, wideCell[k], 0);
    vec4 normal = texelFetch(sourceNormal, wideCell[k], 0);
    sum += texelFetch(sourcePower, wideCell[k], 0).rgb *
      cellRd(point.xyz, normalize(normal.xyz), normal.w, x, distance(x, point.xyz));
  }
  return sum / PI;
}
