// Test support for the GPU path: a headless (EGL) scene with one translucent surfel actor,
// built from the programs' shared pieces (programs/support).
#pragma once

#include <vtkActor.h>
#include <vtkEGLSurfacelessRenderWindow.h>
#include <vtkFloatArray.h>
#include <vtkNew.h>
#include <vtkPolyData.h>
#include <vtkRenderer.h>
#include <vtkSubsurfacePass.h>
#include <vtkSurfelMapper.h>
#include <vtkTranslucentMaterial.h>

#include <vector>

#include "light_map.h"
#include "surfel_cloud.h"
#include "translucent_scene.h"

namespace sss::test {

using cli::to_polydata;

struct GpuScene {
  vtkNew<vtkEGLSurfacelessRenderWindow> window;
  vtkNew<vtkRenderer> renderer;
  vtkNew<vtkSurfelMapper> mapper;
  vtkNew<vtkActor> actor;
  vtkNew<vtkTranslucentMaterial> material;
  vtkNew<vtkSubsurfacePass> pass;

  // The cloud (validated, scene units) shifted by `shift`, lit by `lights`, seen along
  // `view` (from the object towards the camera), orthographic, with the pass's defaults. A
  // cloud with albedo passes it as 8-bit point colours with ColoursAsAlbedo on.
  GpuScene(const SurfelCloud& cloud, const Material& m, const std::vector<Light>& lights,
           const Eigen::Vector3d& view = Eigen::Vector3d(0, 0, 1), int size = 256,
           const Eigen::Vector3d& shift = Eigen::Vector3d::Zero());
  void set_lights(const std::vector<Light>& lights);
  // Renders one frame and returns each surfel's B (NaN for points the mapper left out).
  std::vector<Rgb> render_B();
};

}  // namespace sss::test
