// The CPU reference: eq. 16 evaluated at every surfel over all lit source elements, in double
// precision and in parallel; the ground truth for the grid method and the GPU path.
#pragma once

#include <memory>
#include <vector>

#include "illumination.h"
#include "local_surfels.h"
#include "progress.h"
#include "source_tree.h"
#include "surfel_cloud.h"

namespace sss {

struct ReferenceSettings {
  IlluminationSettings illumination;
  SourceTreeSettings tree;
  Progress progress;  // optional
};

struct RadianceStats {
  std::size_t surfels = 0;
  std::size_t lit_samples = 0;
  double texel_mm = 0.0;           // illumination-map texel of the first light
  int map_width = 0, map_height = 0;
  std::size_t virtual_points = 0;  // grid method only
  int grid_level = 0;              // grid method only: 2^level points per axis
  double grid_spacing_mm = 0.0;    // grid method only
  double seconds_illumination = 0, seconds_tree = 0, seconds_virtual_points = 0,
         seconds_surfels = 0;

  void record_sources(const IlluminationSamples& samples, std::size_t surfel_count);
};

// Per-surfel radiance before the outgoing Fresnel factor: Lo(x, wo) = Ft(eta, wo) * B(x).
struct SurfelRadiance {
  std::vector<Rgb> B;  // one per surfel of the validated cloud
  RadianceStats stats;
};

// Lit sources and their tree for one cloud, material and set of lights: B anywhere.
class ReferenceSolver {
 public:
  // The cloud must have been validated (SurfelCloud::validate); throws std::invalid_argument
  // for a bad material, light or setting.
  ReferenceSolver(const SurfelCloud& cloud, const Material& material,
                  const std::vector<DirectionalLight>& lights,
                  const IlluminationSettings& illumination, const SourceTreeSettings& tree);

  // B at a point given in scene units.
  Rgb B_at(const Eigen::Vector3d& scene_point,
           const KernelWindow& window = KernelWindow::all()) const;

  const LocalSurfels& surfels() const { return surfels_; }
  const IlluminationSamples& samples() const { return samples_; }
  const SourceTree& tree() const { return *tree_; }
  const RadianceStats& stats() const { return stats_; }

 private:
  LocalSurfels surfels_;
  IlluminationSamples samples_;
  std::unique_ptr<SourceTree> tree_;
  RadianceStats stats_;
};

SurfelRadiance render_reference(const SurfelCloud& cloud, const Material& material,
                                const std::vector<DirectionalLight>& lights,
                                const ReferenceSettings& settings = {});

}  // namespace sss
