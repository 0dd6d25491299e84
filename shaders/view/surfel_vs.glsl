//VTK::System::Dec
// Surfels: each point is the centre of a disc, of one radius or its own, expanded by
// surfel_gs.glsl. The same stage serves the camera view and the view from a light.

in vec3 positionMC;  // model coordinates relative to the cloud's bounds centre
in vec3 normalMC;
in vec4 colourMC;
in float radiusMC;  // scene units, with perPointRadius

uniform mat4 modelToView;  // shifted model coordinates -> view (eye or light) coordinates
uniform mat3 normalToView;
uniform bool orthographic;
uniform vec3 ambientDiffuse;  // ambient, diffuse, opacity of the plain (non-translucent) look
uniform float radiusVC;       // the uniform disc radius in view units
uniform bool perPointRadius;
uniform float modelToViewScale;
uniform bool viewFactorPerPixel;  // blended splats: the view factor from the blended normal

out vec3 centreVC_gs;
out vec3 normalVC_gs;
flat out vec4 colour_gs;
out float radius_gs;     // view units
out float curvature_gs;  // mean curvature, 1/mm (the view from a light lifts its texels with it)

//SSS::Radiance::Dec
//SSS::Shape::Dec

void main()
{
  vec4 centre = modelToView * vec4(positionMC, 1.0);
  centreVC_gs = centre.xyz;
  radius_gs = perPointRadius ? modelToViewScale * radiusMC : radiusVC;
  normalVC_gs = normalize(normalToView * normalMC);
  vec3 towardsViewer = orthographic ? vec3(0.0, 0.0, 1.0) : normalize(-centre.xyz);
  float cosOut = abs(dot(normalVC_gs, towardsViewer));
  // The surfel's colour and the factor the view direction puts on it: for the plain look,
  // Lambert under a headlight, two-sided; the subsurface pass's hook replaces both.
  vec4 colour = vec4(colourMC.rgb, colourMC.a * ambientDiffuse.z);
  vec3 viewFactor = vec3(ambientDiffuse.x + ambientDiffuse.y * cosOut);
  //SSS::Radiance::Impl
  colour_gs = viewFactorPerPixel ? colour : vec4(colour.rgb * viewFactor, colour.a);
  curvature_gs = 0.0;
  //SSS::Shape::Impl
}
