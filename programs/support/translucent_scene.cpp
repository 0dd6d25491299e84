#include "translucent_scene.h"

#include <vtkCamera.h>
#include <vtkFloatArray.h>
#include <vtkLight.h>
#include <vtkLightCollection.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkUnsignedCharArray.h>
#include <vtkVertexGlyphFilter.h>

#include <cmath>

#include "stopwatch.h"
#include "view_fit.h"

namespace sss::cli {

vtkSmartPointer<vtkPolyData> to_polydata(const SurfelCloud& cloud, const Eigen::Vector3d& shift) {
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(static_cast<vtkIdType>(cloud.size()));
  vtkNew<vtkFloatArray> normals;
  normals->SetNumberOfComponents(3);
  normals->SetNumberOfTuples(static_cast<vtkIdType>(cloud.size()));
  normals->SetName("Normals");
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    const Eigen::Vector3d p = cloud.positions[i] + shift;
    points->SetPoint(static_cast<vtkIdType>(i), p.data());
    normals->SetTuple3(static_cast<vtkIdType>(i), cloud.normals[i].x(), cloud.normals[i].y(),
                       cloud.normals[i].z());
  }
  auto polydata = vtkSmartPointer<vtkPolyData>::New();
  polydata->SetPoints(points);
  polydata->GetPointData()->SetNormals(normals);
  if (!cloud.radii.empty()) {
    vtkNew<vtkFloatArray> radii;
    radii->SetName(kRadiusArray);
    radii->SetNumberOfTuples(static_cast<vtkIdType>(cloud.size()));
    for (std::size_t i = 0; i < cloud.size(); ++i) radii->SetValue(static_cast<vtkIdType>(i), cloud.radii[i]);
    polydata->GetPointData()->AddArray(radii);
  }
  if (!cloud.albedo.empty()) {  // the albedo back as the colours the mapper passes on
    vtkNew<vtkUnsignedCharArray> colours;
    colours->SetName("Colors");
    colours->SetNumberOfComponents(3);
    colours->SetNumberOfTuples(static_cast<vtkIdType>(cloud.size()));
    for (std::size_t i = 0; i < cloud.size(); ++i)
      for (int c = 0; c < 3; ++c)
        colours->SetValue(static_cast<vtkIdType>(3 * i + c),
                          static_cast<unsigned char>(std::lround(255.0 * cloud.albedo[i][c])));
    polydata->GetPointData()->SetScalars(colours);
  }
  return polydata;
}

void add_lights(vtkRenderer* renderer, const std::vector<Light>& lights) {
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

TranslucentScene::TranslucentScene(vtkRenderWindow* w, const SurfelCloud& cloud,
                                   const Material& m, const std::vector<Light>& lights)
  : window(w), polydata(to_polydata(cloud)) {
  window->AddRenderer(renderer);
  renderer->SetBackground(0, 0, 0);
  renderer->AutomaticLightCreationOff();
  add_lights(renderer, lights);
  mapper->SetInputData(polydata);
  mapper->SetRadius(cloud.radius);
  mapper->SetRadiusArrayName(cloud.radii.empty() ? "" : kRadiusArray);
  mapper->SetScalarVisibility(!cloud.albedo.empty());
  actor->SetMapper(mapper);
  set_material(m);
  material->SetColoursAsAlbedo(!cloud.albedo.empty());
  material->ApplyTo(actor);
  renderer->AddActor(actor);
  pass->MeasureStepTimesOn();
  renderer->SetPass(pass);
}

void TranslucentScene::set_material(const Material& m) {
  material->SetSigmaA(m.sigma_a[0], m.sigma_a[1], m.sigma_a[2]);
  material->SetSigmaSPrime(m.sigma_s_prime[0], m.sigma_s_prime[1], m.sigma_s_prime[2]);
  material->SetEta(m.eta[0]);
  material->SetMillimetresPerUnit(m.mm_per_unit);
}

void TranslucentScene::aim_camera(const std::vector<Eigen::Vector3d>& points,
                                  const Eigen::Vector3d& view_dir, const Eigen::Vector3d& up,
                                  bool orthographic, bool fit_all) {
  Bounds bounds;
  for (const Eigen::Vector3d& p : points) bounds.extend(p);
  const Eigen::Vector3d centre = bounds.center();
  vtkCamera* camera = renderer->GetActiveCamera();
  const Eigen::Vector3d v = view_dir.normalized();
  camera->SetFocalPoint(centre.data());
  camera->SetPosition(centre.x() + v.x(), centre.y() + v.y(), centre.z() + v.z());
  camera->SetViewUp(up.data());
  camera->SetParallelProjection(orthographic);
  renderer->ResetCamera();
  camera->OrthogonalizeViewUp();
  if (!fit_all) frame_points(renderer, points);
}

void frame_points(vtkRenderer* renderer, const std::vector<Eigen::Vector3d>& points) {
  vtkCamera* camera = renderer->GetActiveCamera();
  double direction[3], up[3];
  camera->GetDirectionOfProjection(direction);
  camera->GetViewUp(up);
  ViewFitRequest request;
  request.view_dir = -Eigen::Vector3d(direction[0], direction[1], direction[2]);
  request.up = Eigen::Vector3d(up[0], up[1], up[2]);
  request.view_angle_degrees = camera->GetViewAngle();
  request.orthographic = camera->GetParallelProjection() != 0;
  const int* size = renderer->GetSize();
  if (size[0] > 0 && size[1] > 0) request.aspect = static_cast<double>(size[0]) / size[1];
  const ViewFit fit = fit_view(points, request);
  camera->SetFocalPoint(fit.focal_point.data());
  camera->SetPosition(fit.position.data());
  camera->SetViewUp(up);
  camera->SetParallelScale(fit.parallel_scale);
  renderer->ResetCameraClippingRange();
}

double time_light_static(TranslucentScene& scene, int frames) {
  vtkCamera* camera = scene.renderer->GetActiveCamera();
  Stopwatch clock;
  for (int i = 0; i < frames; ++i) {
    camera->Azimuth(360.0 / frames);
    scene.window->Render();
  }
  return clock.lap() / frames;
}

double time_light_moving(TranslucentScene& scene, int frames) {
  vtkLight* light = vtkLight::SafeDownCast(scene.renderer->GetLights()->GetItemAsObject(0));
  double p[3];
  light->GetPosition(p);
  Stopwatch clock;
  for (int i = 0; i < frames; ++i) {
    const double a = 2.0 * M_PI * (i + 1) / frames;
    light->SetPosition(p[0] * std::cos(a) - p[1] * std::sin(a),
                       p[0] * std::sin(a) + p[1] * std::cos(a), p[2]);
    scene.window->Render();
  }
  const double seconds = clock.lap() / frames;
  light->SetPosition(p);  // back where it was (a full turn may not be exact)
  return seconds;
}

double time_plain_points(TranslucentScene& scene, int frames) {
  vtkNew<vtkRenderer> plain;
  plain->SetActiveCamera(scene.renderer->GetActiveCamera());
  vtkNew<vtkVertexGlyphFilter> vertices;
  vertices->SetInputData(scene.polydata);
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputConnection(vertices->GetOutputPort());
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  actor->GetProperty()->SetPointSize(2);
  plain->AddActor(actor);
  scene.window->RemoveRenderer(scene.renderer);
  scene.window->AddRenderer(plain);
  scene.window->Render();  // upload outside the timing
  vtkCamera* camera = plain->GetActiveCamera();
  Stopwatch clock;
  for (int i = 0; i < frames; ++i) {
    camera->Azimuth(360.0 / frames);
    scene.window->Render();
  }
  const double seconds = clock.lap() / frames;
  scene.window->RemoveRenderer(plain);
  scene.window->AddRenderer(scene.renderer);
  return seconds;
}

}  // namespace sss::cli
