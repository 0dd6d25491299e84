#include "gpu_scene.h"

#include <vtkCamera.h>
#include <vtkLight.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkUnsignedCharArray.h>

#include <cmath>

namespace sss::test {

vtkSmartPointer<vtkPolyData> to_polydata(const SurfelCloud& cloud, const Eigen::Vector3d& shift) {
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  vtkNew<vtkFloatArray> normals;
  normals->SetNumberOfComponents(3);
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    const Eigen::Vector3d p = cloud.positions[i] + shift;
    points->InsertNextPoint(p.data());
    normals->InsertNextTuple3(cloud.normals[i].x(), cloud.normals[i].y(), cloud.normals[i].z());
  }
  auto polydata = vtkSmartPointer<vtkPolyData>::New();
  polydata->SetPoints(points);
  polydata->GetPointData()->SetNormals(normals);
  if (!cloud.radii.empty()) {  // each disc's own radius in the views, as sss_render passes it
    vtkNew<vtkFloatArray> radii;
    radii->SetName("Radius");
    for (double r : cloud.radii) radii->InsertNextValue(static_cast<float>(r));
    polydata->GetPointData()->AddArray(radii);
  }
  if (!cloud.albedo.empty()) {  // albedo as 8-bit colours, the form scans carry it in
    vtkNew<vtkUnsignedCharArray> colours;
    colours->SetNumberOfComponents(3);
    for (const Rgb& a : cloud.albedo)
      colours->InsertNextTuple3(std::round(255 * a[0]), std::round(255 * a[1]), std::round(255 * a[2]));
    polydata->GetPointData()->SetScalars(colours);
  }
  return polydata;
}

GpuScene::GpuScene(const SurfelCloud& cloud, const Material& m,
                   const std::vector<Light>& lights, const Eigen::Vector3d& view,
                   int size, const Eigen::Vector3d& shift) {
  window->SetSize(size, size);
  window->AddRenderer(renderer);
  renderer->AutomaticLightCreationOff();
  mapper->SetInputData(to_polydata(cloud, shift));
  mapper->SetRadius(cloud.radius);
  mapper->SetRadiusArrayName(cloud.radii.empty() ? "" : "Radius");
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
  for (const Light& l : lights) {
    vtkNew<vtkLight> light;
    light->SetLightTypeToSceneLight();
    light->SetPositional(l.positional);
    if (l.positional) {
      light->SetPosition(l.position.data());
      light->SetFocalPoint(Eigen::Vector3d(l.position - l.direction).data());
      light->SetAttenuationValues(l.attenuation.data());
      light->SetConeAngle(l.cone_angle);
      light->SetExponent(l.exponent);
    } else {
      light->SetFocalPoint(0, 0, 0);
      light->SetPosition(l.direction.data());
    }
    light->SetIntensity(l.irradiance);
    renderer->AddLight(light);
  }
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
