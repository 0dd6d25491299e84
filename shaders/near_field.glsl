// The near field of eq. 17 at a receiver, on its local surface (core/near_field.h is the same
// on the CPU): B_near = 1/pi Sum_q W_q C_q E(y_q) over rings of nodes on the receiver's
// osculating paraboloid, each ring holding an equal share of the kernel's near integral. A node
// is lit where the local surface of the disc the light's map sees at its texel passes within
// the receiver's surface thickness (along the normal) of it; its irradiance is the seen
// texel's E_light times albedo with the node's own Ft(eta, theta) cos(theta). C = 1 + b1 kappa
// + b2 kappa^2 bends a ring's planar weight with the surface. Needs the illumination maps'
// samplers and uniforms of gather_tree.glsl.

uniform int ringCount;
uniform float ringRadius[SSS_MAX_RINGS];   // mm
uniform int ringNodes[SSS_MAX_RINGS];
uniform vec3 ringWeight[SSS_MAX_RINGS];    // per node: its share of the near integral
uniform vec3 ringBend1[SSS_MAX_RINGS];     // 1/mm
uniform vec3 ringBend2[SSS_MAX_RINGS];     // mm^-2 ... mm^2 (per kappa^2)
uniform float kappaLimit;                  // 1/mm: |kappa| at most one over the reach
uniform vec3 lightDirection[SSS_MAX_LIGHTS];
uniform sampler2D fresnelTable;            // Ft per channel for cos(theta) in [0, 1]
uniform int fresnelTableSize;

vec3 fresnelFt(float cosI)
{
  float x = clamp(cosI, 0.0, 1.0) * float(fresnelTableSize - 1) + 0.5;
  return texture(fresnelTable, vec2(x / float(fresnelTableSize), 0.5)).rgb;
}

vec3 nearFieldB(vec3 x, vec3 normal, float kappaGiven, float thickness, float rotation)
{
  vec3 sum = vec3(0.0);
  float kappaSurface = clamp(kappaGiven, -kappaLimit, kappaLimit);
  for (int light = 0; light < lightCount; ++light)
  {
    vec3 l = lightDirection[light];
    float side = dot(normal, l) < 0.0 ? -1.0 : 1.0;
    vec3 n = side * normal;
    float kappa = side * kappaSurface;
    vec3 helper = abs(n.x) < 0.7 ? vec3(1.0, 0.0, 0.0) : vec3(0.0, 1.0, 0.0);
    vec3 t1 = normalize(cross(n, helper));
    vec3 t2 = cross(n, t1);
    vec4 rect = levelRect[light * SSS_MAX_LEVELS];
    float texel = texelSize[light];
    vec3 u = mapAxisU[light];
    vec3 v = mapAxisV[light];
    vec2 corner = mapCorner[light];
    float texelArea = texel * texel;
    for (int k = 0; k < ringCount; ++k)
    {
      float r = ringRadius[k];
      vec3 weight = ringWeight[k] * (1.0 + kappa * ringBend1[k] + kappa * kappa * ringBend2[k]);
      float offset = rotation + 0.6180339887 * float(k);
      int nodes = ringNodes[k];
      for (int a = 0; a < nodes; ++a)
      {
        float angle = 6.283185307 * (float(a) + offset) / float(nodes);
        vec3 d = r * (cos(angle) * t1 + sin(angle) * t2);
        vec3 y = x + d - 0.5 * kappa * r * r * n;
        vec3 ny = normalize(n + kappa * d);
        float cosI = dot(ny, l);
        if (cosI <= 0.0)
        {
          continue;
        }
        vec2 at = (vec2(dot(y, u), dot(y, v)) - corner) / texel;
        if (at.x < 0.0 || at.y < 0.0 || at.x >= rect.z || at.y >= rect.w)
        {
          continue;
        }
        ivec2 t = ivec2(rect.xy) + ivec2(at);
        vec3 seenNormal = texelFetch(mapNormal, t, 0).xyz;
        if (dot(seenNormal, seenNormal) < 0.25)
        {
          continue;  // the light sees no disc there: the surface ends
        }
        vec3 seenPoint = texelFetch(mapPoint, t, 0).xyz;
        float seenCos = abs(dot(seenNormal, l));
        float along = dot(seenPoint - y, seenNormal) / max(seenCos, 0.05);
        if (abs(along) > thickness / max(cosI, 0.1))
        {
          continue;  // shadowed, or another surface
        }
        vec3 seenFt = fresnelFt(seenCos);
        vec3 lightAlbedo = texelFetch(mapPower, t, 0).rgb / (texelArea * max(seenFt, vec3(1e-4)));
        sum += weight * lightAlbedo * fresnelFt(cosI) * cosI;
      }
    }
  }
  return sum / PI;
}
