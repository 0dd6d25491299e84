//VTK::System::Dec
// Expands each surfel into a quad in the plane of its disc: the quad's depth is the disc's
// own, so depth testing is exact, and there is no point-size limit at close zoom. With
// SPLAT_PUSH_BACK (vtkSurfelMapper's visibility pass) the depth is pushed back. With
// SPLAT_RIM (its accumulation pass) the quad reaches half a pixel past the disc on screen
// (rimMargin), where the pass fades the rim out (surfel_fs.glsl).

//SSS::Splat::Dec
layout(points) in;
layout(triangle_strip, max_vertices = 4) out;

in vec3 centreVC_gs[];
in vec3 normalVC_gs[];
flat in vec4 colour_gs[];
in float radius_gs[];
in float curvature_gs[];

uniform mat4 viewToClip;
uniform bool orthographic;
uniform float blendDepthVC;  // SPLAT_PUSH_BACK: how far back along the view ray
// SPLAT_RIM: a pixel's size in view units; orthographic, as it is; perspective, per unit of
// distance.
uniform float pixelSpanVC;

out vec2 discCoord;  // position on the disc, in radii
out vec3 pointVC;    // the point on the disc, view coordinates
flat out vec3 normalVC;
flat out vec4 colour;
flat out vec3 centreVC;
flat out float curvature;
flat out float rimMargin;  // in radii

void main()
{
  vec3 n = normalVC_gs[0];
  vec3 helper = abs(n.x) < 0.7 ? vec3(1.0, 0.0, 0.0) : vec3(0.0, 1.0, 0.0);
  vec3 t1 = normalize(cross(n, helper));
  vec3 t2 = cross(n, t1);
  const vec2 corners[4] = vec2[4](vec2(-1.0, -1.0), vec2(1.0, -1.0), vec2(-1.0, 1.0),
                                  vec2(1.0, 1.0));
  float margin = 0.0;
#ifdef SPLAT_RIM
  // Half a pixel, which spans more of the disc's plane where the disc turns away (up to 5x;
  // at most half a radius in all).
  vec3 towardsViewer = orthographic ? vec3(0.0, 0.0, 1.0) : normalize(-centreVC_gs[0]);
  float pixel = orthographic ? pixelSpanVC : pixelSpanVC * length(centreVC_gs[0]);
  margin = min(0.5 * pixel / (radius_gs[0] * max(abs(dot(n, towardsViewer)), 0.2)), 0.5);
#endif
  for (int i = 0; i < 4; ++i)
  {
    vec2 corner = (1.0 + margin) * corners[i];
    vec3 p = centreVC_gs[0] + radius_gs[0] * (corner.x * t1 + corner.y * t2);
#ifdef SPLAT_PUSH_BACK
    // The visibility pass of blended splatting: the same footprint on screen (the corner moves
    // along its view ray), the depth of a point blendDepthVC behind the disc.
    vec3 back = orthographic ? p - vec3(0.0, 0.0, blendDepthVC) : p * (1.0 + blendDepthVC / length(p));
    gl_Position = viewToClip * vec4(back, 1.0);
#else
    gl_Position = viewToClip * vec4(p, 1.0);
#endif
    discCoord = corner;
    rimMargin = margin;
    pointVC = p;
    normalVC = n;
    colour = colour_gs[0];
    centreVC = centreVC_gs[0];
    curvature = curvature_gs[0];
    EmitVertex();
  }
  EndPrimitive();
}
