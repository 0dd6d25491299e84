// The CPU reference: eq. 16 evaluated at every surfel, in double precision and in parallel;
// the ground truth for the GPU path. B = near field + far field, split by NearFarSplit: the
// near field integrated on each receiver's local surface with a fine quadrature against the
// light's map (near_field.h), the far field summed over every lit texel of the light's map,
// lifted onto its disc's local surface, by the source tree (source_tree.h).
#pragma once

#include <memory>
#include <mutex>
#include <vector>

#include "illumination.h"
#include "local_surfels.h"
#include "near_far_split.h"
#include "near_field.h"
#include "progress.h"
#include "source_tree.h"
#include "surfel_cloud.h"

namespace sss {

// The reference's near-field quadrature: refining it further changes B by well under 0.1 %
// (tests/test_reference.cpp).
inline NearFieldSettings reference_near_field() {
  NearFieldSettings s;
  s.quadrature.rings = 24;
  s.quadrature.min_nodes = 8;
  s.quadrature.max_nodes = 48;
  return s;
}

struct ReferenceSettings {
  IlluminationSettings illumination;
  SourceTreeSettings tree;
  NearFieldSettings near = reference_near_field();
  // The near field's r0 in mm; 0 takes NearFarSplit::minimum_r0 of the cloud and map.
  double r0_mm = 0.0;
  // Empty: B at every surfel. Otherwise only at these surfels (indices into the validated
  // cloud); the others are NaN. Large scans are compared on a sample of their points.
  std::vector<std::size_t> receivers;
  Progress progress;  // optional
};

struct RadianceStats {
  std::size_t surfels = 0;
  std::size_t lit_samples = 0;
  double texel_mm = 0.0;           // illumination-map texel of the first light
  int map_width = 0, map_height = 0;
  std::size_t near_nodes = 0;      // per receiver and light
  double split_r0_mm = 0.0;        // 0 when the near field takes the whole kernel
  double split_r1_mm = 0.0;        // the near field's reach
  double seconds_illumination = 0, seconds_tree = 0, seconds_geometry = 0,
         seconds_surfels = 0;

  void record_sources(const IlluminationSamples& samples, std::size_t surfel_count);
};

// Per-surfel radiance before the outgoing Fresnel factor: Lo(x, wo) = Ft(eta, wo) * B(x).
struct SurfelRadiance {
  std::vector<Rgb> B;  // one per surfel of the validated cloud
  RadianceStats stats;
};

// The light's map, its samples and the near-far split for one cloud, material and set of
// lights: B at any surfel.
class ReferenceSolver {
 public:
  // The cloud must have been validated (SurfelCloud::validate); throws std::invalid_argument
  // for a bad material, light or setting.
  ReferenceSolver(const SurfelCloud& cloud, const Material& material,
                  const std::vector<DirectionalLight>& lights,
                  const ReferenceSettings& settings = {});

  // B (eq. 17) at surfel `index`: near field plus far field.
  Rgb B(std::size_t index) const;
  // The light's samples alone, summed by the source tree over the part of the kernel `window`
  // keeps, at a point in scene units (the far field's sum, open to tests).
  Rgb sources_B_at(const Eigen::Vector3d& scene_point, const KernelWindow& window) const;

  const LocalSurfels& surfels() const { return surfels_; }
  const IlluminationSamples& samples() const { return samples_; }
  const NearFarSplit& split() const { return split_; }
  const NearField& near_field() const { return *near_; }
  const SourceTree& tree() const;
  const RadianceStats& stats() const { return stats_; }

 private:
  LocalSurfels surfels_;
  IlluminationSamples samples_;
  NearFarSplit split_;
  Dipole dipole_;
  SourceTreeSettings tree_settings_;
  std::unique_ptr<NearField> near_;
  mutable std::once_flag tree_built_;
  mutable std::unique_ptr<SourceTree> tree_;
  RadianceStats stats_;
};

SurfelRadiance render_reference(const SurfelCloud& cloud, const Material& material,
                                const std::vector<DirectionalLight>& lights,
                                const ReferenceSettings& settings = {});

}  // namespace sss
