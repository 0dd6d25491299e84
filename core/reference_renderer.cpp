#include "reference_renderer.h"

#include "parallel_points.h"
#include "stopwatch.h"

namespace sss {

void RadianceStats::record_sources(const IlluminationSamples& samples, std::size_t surfel_count) {
  surfels = surfel_count;
  lit_samples = samples.size();
  if (!samples.maps.empty()) {
    texel_mm = samples.maps[0].pixel;
    map_width = samples.maps[0].width;
    map_height = samples.maps[0].height;
  }
}

ReferenceSolver::ReferenceSolver(const SurfelCloud& cloud, const Material& material,
                                 const std::vector<DirectionalLight>& lights,
                                 const IlluminationSettings& illumination,
                                 const SourceTreeSettings& tree) {
  const Dipole dipole(material);
  Stopwatch clock;
  surfels_ = LocalSurfels::from(cloud, material.mm_per_unit);
  samples_ = illuminate(surfels_, material, lights, illumination);
  stats_.seconds_illumination = clock.lap();
  tree_ = std::make_unique<SourceTree>(samples_, dipole, tree);
  stats_.seconds_tree = clock.lap();
  stats_.record_sources(samples_, surfels_.size());
}

Rgb ReferenceSolver::B_at(const Eigen::Vector3d& scene_point, const KernelWindow& window) const {
  return tree_->B(surfels_.frame.to_mm(scene_point), window);
}

SurfelRadiance render_reference(const SurfelCloud& cloud, const Material& material,
                                const std::vector<DirectionalLight>& lights,
                                const ReferenceSettings& settings) {
  const ReferenceSolver solver(cloud, material, lights, settings.illumination, settings.tree);
  SurfelRadiance result;
  result.stats = solver.stats();
  Stopwatch clock;
  result.B = evaluate_points(
      solver.surfels().positions,
      [&](const Eigen::Vector3d& x) { return solver.tree().B(x); }, settings.progress);
  result.stats.seconds_surfels = clock.lap();
  return result;
}

}  // namespace sss
