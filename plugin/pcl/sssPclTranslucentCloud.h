// One call that shows a PCL cloud translucent in an existing PCLVisualizer, in the
// visualizer's own window, and the handle that changes it afterwards.
#pragma once

#include <pcl/point_cloud.h>
#include <vtkSmartPointer.h>
#include <vtkWeakPointer.h>

#include <Eigen/Core>
#include <chrono>
#include <memory>
#include <string>
#include <vector>

#include "sssPclSurfels.h"

class vtkActor;
class vtkLight;
class vtkRenderWindow;
class vtkRenderer;
class vtkSubsurfacePass;
class vtkSurfelMapper;
class vtkTranslucentMaterial;

namespace pcl::visualization {
class PCLVisualizer;
}

namespace sss {

// How B is summed when a light, the geometry or the material changes (the camera alone never
// re-runs it), trading accuracy for time. Costs and errors per setting are in
// docs/benchmark/bench.md. Each is vtkSubsurfacePass's quality preset of the same name
// (core/settings/quality_settings.h); Balanced is the pass's defaults.
enum class Quality { Interactive, Balanced, Accurate };
const char* qualityName(Quality quality);
// False for a name that is not a quality's.
bool qualityFromName(const std::string& name, Quality& quality);

struct TranslucentCloudOptions {
  std::string material;  // a vtkTranslucentMaterial preset; empty: its default (marble)
  double millimetres_per_unit = 1.0;
  Quality quality = Quality::Balanced;  // the pass's defaults
  SurfelOptions surfels;
  int viewport = 0;  // PCLVisualizer viewport; 0: every renderer of the window
};

class TranslucentCloud;
std::shared_ptr<TranslucentCloud> addTranslucentSurfels(pcl::visualization::PCLVisualizer& viewer,
                                                        Surfels surfels, const std::string& id,
                                                        const TranslucentCloudOptions& options);

class TranslucentCloud {
 public:
  using Ptr = std::shared_ptr<TranslucentCloud>;
  ~TranslucentCloud();  // leaves the cloud shown; remove() takes it away
  TranslucentCloud(const TranslucentCloud&) = delete;
  TranslucentCloud& operator=(const TranslucentCloud&) = delete;

  // Returns false, with a VTK error naming the known presets, for an unknown name.
  bool setMaterial(const std::string& preset);
  // Coefficients in 1/mm per RGB channel; false (and unchanged) when they are not physical.
  bool setCustomMaterial(const Eigen::Vector3d& sigma_a, const Eigen::Vector3d& sigma_s_prime,
                         double eta);
  void setMillimetresPerUnit(double millimetres_per_unit);
  // Point colours scale the light entering each point (on by default when the cloud has them).
  void setColoursAsAlbedo(bool on);
  // Replaces the lights of the handle's renderers by directional lights shining from the given
  // directions (towards the light, world frame) with the given irradiance each.
  void setLights(const std::vector<Eigen::Vector3d>& towards_light, double irradiance = 1.0);
  void setQuality(Quality quality);
  Quality quality() const { return quality_; }
  // Refinement (vtkSubsurfacePass::SetRefinement; off unless set): a change of the light or
  // the material is shown first from the 2005 paper's method, and once the input rests the
  // quality's B is computed in parts and shown (spinOnce below runs them). refinementPending():
  // a preview is on screen. refinementPreparing(): the bake's CPU part runs on a thread
  // meanwhile (vtkSubsurfacePass::GetRefinementPreparing). refinementPartDue(): a part would
  // take the refinement further now (the input has rested, no bake's thread is at work;
  // vtkSubsurfacePass::IsRefinementPartDue, read live).
  void setRefinement(bool on);
  bool refinementPending() const;
  bool refinementPreparing() const;
  bool refinementPartDue() const;
  // Runs the next part of a pending refinement without drawing a frame
  // (vtkSubsurfacePass::RunRefinementPart on the handle's renderers; the window's next Render
  // shows the refined B once the last part is done). Needs the window drawn once.
  void refinePart();
  // PCLVisualizer::spinOnce for a window that refines, to call in its place in the
  // application's loop. While a refinement is pending it handles the events already queued
  // (sssPclPendingEvents.h: PCL's spinOnce would wait up to a second between parts); when a
  // part is due it runs it (refinePart) and draws a frame only for the last, or when the last
  // frame is a second old (a status, an overlay); it draws one too when anything in the
  // viewer's renderers changed since the window's last frame (the handle's actor, material and
  // pass, a renderer, its camera, lights or props); otherwise it waits
  // `milliseconds`, so that neither the rest nor the bake's thread is spent redrawing the
  // preview. With nothing pending it is PCL's spinOnce.
  void spinOnce(pcl::visualization::PCLVisualizer& viewer, int milliseconds = 1);
  // The pass's rest before it refines (vtkSubsurfacePass::SetRefinementRestSeconds): an
  // application that knows when its input rests sets it large and sets it to 0 for the frame
  // that should refine.
  void setRefinementRest(double seconds);
  // sRGB(clamp(exposure * Lo)); autoExpose() renders once and sets it so that the 99.5th
  // percentile of the visible translucent pixels' radiance is white.
  void setExposure(double exposure);
  double exposure() const;
  double autoExpose();
  void setVisible(bool visible);
  // Takes the actor out of the renderers (and the pass, when no other translucent cloud uses
  // it). The id is also a PCLVisualizer shape id: viewer.removeShape(id) takes the actor out
  // too, and viewer.contains(id) is true while it is shown.
  void remove();

  const std::string& id() const { return id_; }
  const Surfels& surfels() const { return surfels_; }
  vtkActor* actor() const;
  vtkTranslucentMaterial* material() const;
  vtkSubsurfacePass* pass() const;
  // "marble, 1 mm/unit, quality accurate, 2 lights, exposure 3.1, light move 0.41 s (far
  // 0.30 s)": for overlays; the light move is the last, its largest step in brackets. With
  // refinement it begins with what is on screen: "preview, refining 40 %, 41 % off at the
  // last rest" or "refined".

  std::string settingsLine() const;

 private:
  friend std::shared_ptr<TranslucentCloud> addTranslucentSurfels(
    pcl::visualization::PCLVisualizer&, Surfels, const std::string&,
    const TranslucentCloudOptions&);
  TranslucentCloud(pcl::visualization::PCLVisualizer& viewer, std::string id, Surfels surfels,
                   const TranslucentCloudOptions& options);

  pcl::visualization::PCLVisualizer& viewer_;
  std::string id_;
  Surfels surfels_;
  std::vector<vtkSmartPointer<vtkRenderer>> renderers_;
  vtkSmartPointer<vtkSurfelMapper> mapper_;
  vtkSmartPointer<vtkActor> actor_;
  vtkSmartPointer<vtkTranslucentMaterial> material_;
  std::vector<vtkSmartPointer<vtkSubsurfacePass>> passes_;  // one per renderer
  std::vector<vtkSmartPointer<vtkLight>> lights_;
  // The latest modification time of the actor, its material, the passes, and the viewer's
  // renderers with their cameras, lights and props.
  vtkMTimeType inputsTime() const;
  // After each frame of the window: what it drew is of inputsTime().
  void frameDrawn();

  Quality quality_ = Quality::Balanced;
  bool attached_ = true;
  vtkMTimeType drawn_inputs_ = 0;  // inputsTime() at the window's last frame
  std::chrono::steady_clock::time_point drawn_at_;  // the window's last frame
  vtkWeakPointer<vtkRenderWindow> window_;  // the viewer's, observed for frameDrawn
  unsigned long frame_observer_ = 0;
};

// Makes `cloud` translucent in `viewer` (no subclassing; the visualizer's own window and
// renderers): builds surfels (normals kept or estimated, radius from coverage, colours as
// albedo), adds the actor and installs a vtkSubsurfacePass on the viewport's renderers.
// Throws InputError for a cloud with nothing to show and std::invalid_argument for an unknown
// material, a used id or a viewport the visualizer does not have. Instantiated for PointXYZ,
// PointNormal, PointXYZRGB, PointXYZRGBNormal and PointSurfel.
template <typename PointT>
TranslucentCloud::Ptr addTranslucentCloud(pcl::visualization::PCLVisualizer& viewer,
                                          const pcl::PointCloud<PointT>& cloud,
                                          const std::string& id,
                                          const TranslucentCloudOptions& options = {});

// The same for surfels made already (from a file: makeSurfels(loadPointCloud<T>(path))); the
// options' surfel settings are not used.
inline TranslucentCloud::Ptr addTranslucentSurfels(pcl::visualization::PCLVisualizer& viewer,
                                                   Surfels surfels, const std::string& id) {
  return addTranslucentSurfels(viewer, std::move(surfels), id, TranslucentCloudOptions{});
}

}  // namespace sss
