// The scene sss_render and sss_bench draw: one surfel cloud as a translucent actor under
// its lights, with the subsurface pass, in a given window; and its frame timings.
#pragma once

#include <vtkActor.h>
#include <vtkNew.h>
#include <vtkPolyData.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkSmartPointer.h>
#include <vtkSubsurfacePass.h>
#include <vtkSurfelMapper.h>
#include <vtkTranslucentMaterial.h>

#include <string>
#include <vector>

#include "light_map.h"
#include "material.h"
#include "surfel_cloud.h"

namespace sss::cli {

// Points (moved by `shift`), normals, per-point radii (when the cloud has them, as
// kRadiusArray) and (when the cloud has albedo) 8-bit colours.
constexpr const char* kRadiusArray = "Radius";
vtkSmartPointer<vtkPolyData> to_polydata(const SurfelCloud& cloud,
                                         const Eigen::Vector3d& shift = Eigen::Vector3d::Zero());

// The lights as scene lights of `renderer`: directional ones from their direction towards the
// origin, positional ones with their position, spot cone, exponent and attenuation.
void add_lights(vtkRenderer* renderer, const std::vector<Light>& lights);

struct TranslucentScene {
  vtkSmartPointer<vtkRenderWindow> window;
  vtkSmartPointer<vtkPolyData> polydata;
  vtkNew<vtkRenderer> renderer;
  vtkNew<vtkSurfelMapper> mapper;
  vtkNew<vtkActor> actor;
  vtkNew<vtkTranslucentMaterial> material;
  vtkNew<vtkSubsurfacePass> pass;

  // The cloud (validated) as a translucent actor lit by `lights`; colours as albedo when the
  // cloud has albedo. The pass measures its step times exactly.
  TranslucentScene(vtkRenderWindow* window, const SurfelCloud& cloud, const Material& m,
                   const std::vector<Light>& lights);
  void set_material(const Material& m);
  // Camera looking back along `view_dir`; `fit_all`: at the bounds centre, fitted to every
  // point (vtkRenderer::ResetCamera); otherwise framing 99 % of the points (frame_points).
  void aim_camera(const std::vector<Eigen::Vector3d>& points, const Eigen::Vector3d& view_dir,
                  const Eigen::Vector3d& up, bool orthographic, bool fit_all = false);
};

// Mean seconds per frame: the camera orbiting (light static), the first light turning about
// the view's z axis (steps 1-2 every frame), and plain VTK points of the same cloud (vertex
// cells, point size 2, the same camera and window).
// The renderer's camera, looking along its direction with its up and view angle, moved (and
// its orthographic scale set) so that its frame holds 99 % of `points`, centred on them
// (core/view/view_fit.h); then its clipping range reset.
void frame_points(vtkRenderer* renderer, const std::vector<Eigen::Vector3d>& points);

double time_light_static(TranslucentScene& scene, int frames);
double time_light_moving(TranslucentScene& scene, int frames);
double time_plain_points(TranslucentScene& scene, int frames);

}  // namespace sss::cli
