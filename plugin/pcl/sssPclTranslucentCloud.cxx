#include "sssPclTranslucentCloud.h"

#include <pcl/point_types.h>
#include <pcl/visualization/pcl_visualizer.h>

#include <vtkActor.h>
#include <vtkCamera.h>
#include <vtkCommand.h>
#include <vtkFloatArray.h>
#include <vtkLight.h>
#include <vtkLightCollection.h>
#include <vtkPolyData.h>
#include <vtkPropCollection.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkRendererCollection.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <iterator>
#include <stdexcept>
#include <thread>
#include <utility>

#include "sssPclPendingEvents.h"
#include "vtkSubsurfacePass.h"
#include "vtkSurfelMapper.h"
#include "vtkTranslucentMaterial.h"

namespace sss {
namespace {

// The renderers PCLVisualizer means by a viewport: all for 0, else the viewport-th one.
std::vector<vtkSmartPointer<vtkRenderer>> renderers_of(pcl::visualization::PCLVisualizer& viewer,
                                                       int viewport) {
  std::vector<vtkSmartPointer<vtkRenderer>> chosen;
  vtkRendererCollection* all = viewer.getRendererCollection();
  all->InitTraversal();
  int index = 0;
  while (vtkRenderer* renderer = all->GetNextItem()) {
    if (viewport == 0 || viewport == index) chosen.emplace_back(renderer);
    ++index;
  }
  return chosen;
}

bool has_translucent_actor(vtkRenderer* renderer) {
  vtkActorCollection* actors = renderer->GetActors();
  actors->InitTraversal();
  while (vtkActor* actor = actors->GetNextActor())
    if (vtkTranslucentMaterial::GetFrom(actor)) return true;
  return false;
}


}  // namespace

const char* qualityName(Quality quality) {
  switch (quality) {
    case Quality::Interactive: return "interactive";
    case Quality::Balanced: return "balanced";
    case Quality::Accurate: break;
  }
  return "accurate";
}

bool qualityFromName(const std::string& name, Quality& quality) {
  for (Quality q : {Quality::Interactive, Quality::Balanced, Quality::Accurate}) {
    if (name == qualityName(q)) {
      quality = q;
      return true;
    }
  }
  return false;
}

TranslucentCloud::TranslucentCloud(pcl::visualization::PCLVisualizer& viewer, std::string id,
                                   Surfels surfels, const TranslucentCloudOptions& options)
  : viewer_(viewer), id_(std::move(id)), surfels_(std::move(surfels)),
    renderers_(renderers_of(viewer, options.viewport)) {
  mapper_ = vtkSmartPointer<vtkSurfelMapper>::New();
  mapper_->SetInputData(surfels_.polydata);
  mapper_->SetScalarVisibility(surfels_.has_colours);
  actor_ = vtkSmartPointer<vtkActor>::New();
  actor_->SetMapper(mapper_);
  material_ = vtkSmartPointer<vtkTranslucentMaterial>::New();
  if (!options.material.empty() && !material_->SetPreset(options.material.c_str()))
    throw std::invalid_argument("unknown material \"" + options.material + "\"");
  material_->SetMillimetresPerUnit(options.millimetres_per_unit);
  material_->SetColoursAsAlbedo(surfels_.has_colours);
  const std::string problem = material_->Validate();
  if (!problem.empty()) throw std::invalid_argument(problem);
  material_->ApplyTo(actor_);

  for (const auto& renderer : renderers_) {
    vtkSmartPointer<vtkSubsurfacePass> pass = vtkSubsurfacePass::SafeDownCast(renderer->GetPass());
    if (!pass) {
      if (renderer->GetPass())
        vtkGenericWarningMacro("Renderer's own render pass replaced by a vtkSubsurfacePass");
      pass = vtkSmartPointer<vtkSubsurfacePass>::New();
      pass->MeasureStepTimesOn();
      renderer->SetPass(pass);
    }
    passes_.push_back(pass);
    renderer->AddActor(actor_);
  }
  viewer_.getShapeActorMap()->emplace(id_, actor_);
  setQuality(options.quality);
  window_ = viewer_.getRenderWindow();
  frame_observer_ = window_->AddObserver(vtkCommand::EndEvent, this, &TranslucentCloud::frameDrawn);
}

TranslucentCloud::~TranslucentCloud() {
  if (window_) window_->RemoveObserver(frame_observer_);
}

void TranslucentCloud::frameDrawn() {
  drawn_inputs_ = inputsTime();
  drawn_at_ = std::chrono::steady_clock::now();
}

bool TranslucentCloud::setMaterial(const std::string& preset) {
  if (!material_->SetPreset(preset.c_str())) return false;
  actor_->Modified();
  return true;
}

bool TranslucentCloud::setCustomMaterial(const Eigen::Vector3d& sigma_a,
                                         const Eigen::Vector3d& sigma_s_prime, double eta) {
  vtkNew<vtkTranslucentMaterial> candidate;
  candidate->SetSigmaA(sigma_a.x(), sigma_a.y(), sigma_a.z());
  candidate->SetSigmaSPrime(sigma_s_prime.x(), sigma_s_prime.y(), sigma_s_prime.z());
  candidate->SetEta(eta);
  candidate->SetMillimetresPerUnit(material_->GetMillimetresPerUnit());
  const std::string problem = candidate->Validate();
  if (!problem.empty()) {
    vtkGenericWarningMacro("Material not changed: " << problem);
    return false;
  }
  material_->SetSigmaA(sigma_a.x(), sigma_a.y(), sigma_a.z());
  material_->SetSigmaSPrime(sigma_s_prime.x(), sigma_s_prime.y(), sigma_s_prime.z());
  material_->SetEta(eta);
  return true;
}

void TranslucentCloud::setMillimetresPerUnit(double millimetres_per_unit) {
  material_->SetMillimetresPerUnit(millimetres_per_unit);
}

void TranslucentCloud::setColoursAsAlbedo(bool on) {
  material_->SetColoursAsAlbedo(on && surfels_.has_colours);
}

void TranslucentCloud::setLights(const std::vector<Eigen::Vector3d>& towards_light,
                                 double irradiance) {
  for (const auto& renderer : renderers_) {
    renderer->RemoveAllLights();  // PCLVisualizer's own light included
    renderer->AutomaticLightCreationOff();
  }
  lights_.clear();
  for (const Eigen::Vector3d& d : towards_light) {
    auto light = vtkSmartPointer<vtkLight>::New();
    light->SetLightTypeToSceneLight();
    light->SetPositional(false);
    light->SetFocalPoint(0, 0, 0);
    light->SetPosition(d.x(), d.y(), d.z());
    light->SetIntensity(irradiance);
    lights_.push_back(light);
    for (const auto& renderer : renderers_) renderer->AddLight(light);
  }
}

void TranslucentCloud::setQuality(Quality quality) {
  quality_ = quality;
  for (const auto& pass : passes_) pass->SetQualityPreset(qualityName(quality));
}

void TranslucentCloud::setRefinement(bool on) {
  for (const auto& pass : passes_) pass->SetRefinement(on);
}

void TranslucentCloud::setRefinementRest(double seconds) {
  for (const auto& pass : passes_) pass->SetRefinementRestSeconds(seconds);
}

bool TranslucentCloud::refinementPending() const {
  for (const auto& pass : passes_)
    if (pass->GetRefinementPending()) return true;
  return false;
}

bool TranslucentCloud::refinementPreparing() const {
  for (const auto& pass : passes_)
    if (pass->GetRefinementPreparing()) return true;
  return false;
}

bool TranslucentCloud::refinementPartDue() const {
  for (const auto& pass : passes_)
    if (pass->IsRefinementPartDue()) return true;
  return false;
}

void TranslucentCloud::refinePart() {
  for (std::size_t i = 0; i < passes_.size(); ++i) passes_[i]->RunRefinementPart(renderers_[i]);
}

vtkMTimeType TranslucentCloud::inputsTime() const {
  vtkMTimeType latest = std::max(actor_->GetMTime(), material_->GetMTime());
  for (const auto& pass : passes_) latest = std::max(latest, pass->GetMTime());
  vtkRendererCollection* renderers = viewer_.getRendererCollection();
  vtkCollectionSimpleIterator it;
  renderers->InitTraversal(it);
  while (vtkRenderer* renderer = renderers->GetNextRenderer(it)) {
    latest = std::max(latest, renderer->GetMTime());
    if (renderer->IsActiveCameraCreated())
      latest = std::max(latest, renderer->GetActiveCamera()->GetMTime());
    vtkCollectionSimpleIterator light_it;
    renderer->GetLights()->InitTraversal(light_it);
    while (vtkLight* light = renderer->GetLights()->GetNextLight(light_it))
      latest = std::max(latest, light->GetMTime());
    vtkCollectionSimpleIterator prop_it;
    renderer->GetViewProps()->InitTraversal(prop_it);
    while (vtkProp* prop = renderer->GetViewProps()->GetNextProp(prop_it))
      latest = std::max(latest, prop->GetMTime());
  }
  return latest;
}

void TranslucentCloud::spinOnce(pcl::visualization::PCLVisualizer& viewer, int milliseconds) {
  if (!refinementPending()) {
    viewer.spinOnce(milliseconds);
    return;
  }
  processPendingEvents(viewer.getRenderWindow()->GetInteractor());
  if (viewer.wasStopped()) return;  // not a closed window again
  if (inputsTime() > drawn_inputs_) {
    viewer.getRenderWindow()->Render();
  } else if (refinementPartDue()) {
    refinePart();
    const bool status_due = std::chrono::steady_clock::now() - drawn_at_ >= std::chrono::seconds(1);
    if (!refinementPending() || status_due)
      viewer.getRenderWindow()->Render();
  } else {
    std::this_thread::sleep_for(std::chrono::milliseconds(std::max(milliseconds, 1)));
  }
}

void TranslucentCloud::setExposure(double exposure) {
  for (const auto& pass : passes_) pass->SetExposure(exposure);
}

double TranslucentCloud::exposure() const { return passes_.front()->GetExposure(); }

double TranslucentCloud::autoExpose() {
  vtkSubsurfacePass* p = pass();
  const bool capturing = p->GetCaptureLinearImage();
  p->CaptureLinearImageOn();
  viewer_.getRenderWindow()->Render();
  const double white = p->GetLinearImageQuantile(0.995);
  p->SetCaptureLinearImage(capturing);
  if (white > 0.0 && std::isfinite(white)) setExposure(1.0 / white);
  return exposure();
}

void TranslucentCloud::setVisible(bool visible) { actor_->SetVisibility(visible); }

void TranslucentCloud::remove() {
  if (!attached_) return;
  attached_ = false;
  viewer_.getShapeActorMap()->erase(id_);
  for (const auto& renderer : renderers_) {
    renderer->RemoveActor(actor_);
    if (renderer->GetPass() && !has_translucent_actor(renderer)) renderer->SetPass(nullptr);
    for (const auto& light : lights_) renderer->RemoveLight(light);
  }
}

vtkActor* TranslucentCloud::actor() const { return actor_; }
vtkTranslucentMaterial* TranslucentCloud::material() const { return material_; }
vtkSubsurfacePass* TranslucentCloud::pass() const { return passes_.front(); }

std::string TranslucentCloud::settingsLine() const {
  vtkSubsurfacePass* p = passes_.front();
  const double light_move = p->GetLastIlluminationSeconds() + p->GetLastSurfelSeconds();
  // The light move's largest step, so that where its time goes shows in one line.
  const std::pair<double, const char*> steps[] = {
      {p->GetLastIlluminationSeconds(), "map"}, {p->GetLastCellSeconds(), "cells"},
      {p->GetLastPyramidSeconds(), "pyramid"}, {p->GetLastNearFieldSeconds(), "near"},
      {p->GetLastFarFieldSeconds(), "far"}, {p->GetLastHandOverSeconds(), "hand-over"}};
  const auto largest = *std::max_element(std::begin(steps), std::end(steps));
  const std::string lights = lights_.empty() ? "headlight"
                             : lights_.size() == 1 ? "1 light"
                                                   : std::to_string(lights_.size()) + " lights";
  std::string shown;
  if (p->GetRefinementPending()) {
    shown = "preview, ";
    if (p->GetRefinementPreparing())
      shown += "preparing the bake, ";
    else if (p->GetRefinedShare() > 0.0)
      shown += "refining " + std::to_string(std::lround(100.0 * p->GetRefinedShare())) + " %, ";
    const double error = p->GetLastPreviewError();
    if (error >= 0.0) {
      char off[64];
      std::snprintf(off, sizeof off, "%.0f %% off at the last rest, ", 100.0 * error);
      shown += off;
    }
  } else if (p->GetRefinementFailed()) {
    shown = "preview, not refined (see the error), ";
  } else if (p->GetRefinement()) {
    shown = "refined, ";
  }
  char line[256];
  std::snprintf(line, sizeof line, "%s, %g mm/unit, %s, %s, exposure %.3g",
                material_->GetName(), material_->GetMillimetresPerUnit(), qualityName(quality_),
                lights.c_str(), p->GetExposure());
  char move[96] = "";
  if (p->GetIlluminationRuns() > 0)  // none before the first settled light move
    std::snprintf(move, sizeof move, ", light move %.2f s (%s %.2f s)", light_move, largest.second,
                  largest.first);
  return shown + line + move;
}

TranslucentCloud::Ptr addTranslucentSurfels(pcl::visualization::PCLVisualizer& viewer,
                                            Surfels surfels, const std::string& id,
                                            const TranslucentCloudOptions& options) {
  if (viewer.contains(id)) throw std::invalid_argument("the visualizer already shows \"" + id + "\"");
  if (renderers_of(viewer, options.viewport).empty())
    throw std::invalid_argument("the visualizer has no viewport " +
                                std::to_string(options.viewport));
  if (!surfels.polydata || surfels.size() == 0) throw InputError("\"" + id + "\": no surfels");
  return TranslucentCloud::Ptr(new TranslucentCloud(viewer, id, std::move(surfels), options));
}

template <typename PointT>
TranslucentCloud::Ptr addTranslucentCloud(pcl::visualization::PCLVisualizer& viewer,
                                          const pcl::PointCloud<PointT>& cloud,
                                          const std::string& id,
                                          const TranslucentCloudOptions& options) {
  return addTranslucentSurfels(viewer, makeSurfels(cloud, options.surfels), id, options);
}

#define SSS_INSTANTIATE_ONE_CALL(PointT)                                          \
  template TranslucentCloud::Ptr addTranslucentCloud<PointT>(                     \
    pcl::visualization::PCLVisualizer&, const pcl::PointCloud<PointT>&,           \
    const std::string&, const TranslucentCloudOptions&);
SSS_INSTANTIATE_ONE_CALL(pcl::PointXYZ)
SSS_INSTANTIATE_ONE_CALL(pcl::PointNormal)
SSS_INSTANTIATE_ONE_CALL(pcl::PointXYZRGB)
SSS_INSTANTIATE_ONE_CALL(pcl::PointXYZRGBNormal)
SSS_INSTANTIATE_ONE_CALL(pcl::PointSurfel)
#undef SSS_INSTANTIATE_ONE_CALL

}  // namespace sss
