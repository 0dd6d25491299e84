#include "gpu_scene.h"

#include <vtkCamera.h>
#include <vtkLight.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkUnsignedCharArray.h>

#include <cmath>

namespace sss::test {

GpuScene::GpuScene(const SurfelCloud& cloud, const Material& m,
                   const std::vector<Light>& lights, const Eigen::Vector3d& view,
                   int size, const Eigen::Vector3d& shift) {
  window->SetSize(size, size);
  window->AddRenderer(renderer);
  renderer->AutomaticLightCreationOff();
  mapper->SetInputData(to_polydata(cloud, shift));
  mapper->SetRadius(cloud.radius);
  mapper->SetRadiusArrayName(cloud.radii.empty() ? "" : cli::kRadiusArray);
  mapper->SetScalarVisibility(!cloud.albedo.empty());
  actor->SetMapper(mapper);
  material->SetSigmaA(m.sigma_a[0], m.sigma_a[1], m.sigma_a[2]);
  material->SetSigmaSPrime(m.sigma_s_prime[0], m.sigma_s_prime[1], m.sigma_s_prime[2]);
  material->SetEta(m.eta[0]);
  material->SetMillimetresPerUnit(m.mm_per_unit);
  material->SetColoursAsAlbedo(!cloud.albedo.empty());
  material->ApplyTo(actor);
  renderer->AddActor(actor);
  renderer->SetPass(pass);
  set_lights(lights);
  const Eigen::Vector3d c = cloud.bounds().center() + shift;
  vtkCamera* camera = renderer->GetActiveCamera();
  camera->SetFocalPoint(c.data());
  camera->SetPosition(c.x() + view.x(), c.y() + view.y(), c.z() + view.z());
  const bool steep = std::abs(view.normalized().z()) > 0.9;
  camera->SetViewUp(0, steep ? 1 : 0, steep ? 0 : 1);
  camera->ParallelProjectionOn();
  renderer->ResetCamera();
}

void GpuScene::set_lights(const std::vector<Light>& lights) {
  renderer->RemoveAllLights();
  cli::add_lights(renderer, lights);
}

std::vector<Rgb> GpuScene::render_B() {
  window->Render();
  vtkNew<vtkFloatArray> B;
  std::vector<Rgb> out;
  if (!pass->GetSurfelRadiance(actor, B)) return out;
  out.resize(static_cast<std::size_t>(B->GetNumberOfTuples()));
  for (std::size_t i = 0; i < out.size(); ++i)
    for (int c = 0; c < 3; ++c) out[i][c] = B->GetValue(static_cast<vtkIdType>(3 * i + c));
  return out;
}

}  // namespace sss::test
