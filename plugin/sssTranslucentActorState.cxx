#include "sssTranslucentActorState.h"

#include "sssPaperVirtualPoints.h"
#include "sssSurfelBuffers.h"
#include "sssSurfelResolve.h"

#include "local_surfels.h"
#include "stopwatch.h"

#include "vtkOpenGLBufferObject.h"
#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkTextureObject.h"

#include <memory>

namespace sss
{

struct TranslucentActorState::Gpu
{
  LocalSurfels local;
  std::unique_ptr<Dipole> dipole;
  SurfelBuffers buffers;
  GpuLightMaps maps;            // step 1
  SurfelPipeline pipeline;   // step 2, NEAR_FAR
  PaperVirtualPoints paper;  // step 2, PAPER
  SurfelResolve resolve;     // B per surfel for the camera view

  void release(vtkWindow* window)
  {
    buffers.release();
    maps.release(window);
    pipeline.release(window);
    paper.release(window);
    resolve.release(window);
  }
};

TranslucentActorState::TranslucentActorState()
  : gpu_(new Gpu)
{
}

TranslucentActorState::~TranslucentActorState()
{
  delete gpu_;
}

vtkTextureObject* TranslucentActorState::surfel_radiance() const
{
  return gpu_->resolve.texture();
}

int TranslucentActorState::list_width() const
{
  return gpu_->resolve.width();
}

void TranslucentActorState::release(vtkWindow* window)
{
  gpu_->release(window);
  valid_ = false;
  geometry_time_ = 0;
}

bool TranslucentActorState::update(vtkOpenGLRenderWindow* window, const PreparedSurfels& surfels,
  vtkMTimeType surfels_time, const Material& material, bool albedo_from_colour,
  const std::vector<GpuLight>& lights, const QualitySettings& settings, bool finish,
  StepReport& report, std::string& error)
{
  std::vector<double> key;
  for (int c = 0; c < 3; ++c)
  {
    key.insert(key.end(), { material.sigma_a[c], material.sigma_s_prime[c], material.eta[c] });
  }
  key.push_back(material.mm_per_unit);
  const bool geometry_changed = !valid_ || surfels_time != geometry_time_ ||
    key != material_key_ || !(settings == geometry_settings_) ||
    albedo_from_colour != geometry_albedo_;
  const bool light_changed = geometry_changed || !(lights == lights_);
  report.surfel_count = surfels.cloud.size();
  if (!light_changed)
  {
    return true;
  }
  material_ = material;
  valid_ = false;
  Gpu& g = *gpu_;
  Stopwatch clock;
  if (geometry_changed)
  {
    if (!bake(window, surfels, albedo_from_colour, settings, report, error))
    {
      return false;
    }
    material_key_ = key;
    geometry_time_ = surfels_time;
    geometry_settings_ = settings;
    geometry_albedo_ = albedo_from_colour;
    report.bake = true;
    report.seconds_bake = clock.lap();
  }

  const bool paper = settings.strategy == KernelStrategy::Paper;
  LightMapRequest request;
  request.paper = paper;
  request.texel_per_radius = settings.texel_per_radius;
  request.max_map_size = settings.max_map_size;
  request.list_texel = paper ? nullptr : g.pipeline.list_texel();
  LightMapReport maps;
  if (!g.maps.render(window, g.buffers, g.local, lights, request, material_,
        albedo_from_colour, maps, error))
  {
    return false;
  }
  finish_if(finish);
  report.illumination = true;
  report.seconds_illumination = clock.lap();
  report.map_width = maps.map_width;
  report.map_height = maps.map_height;
  report.texel_mm = maps.texel_mm;
  report.notes = maps.notes;

  if (paper)
  {
    if (!g.paper.gather(window, g.maps, *g.dipole, error) ||
      !g.resolve.from_grid(window, g.buffers.points, g.paper, error))
    {
      return false;
    }
  }
  else
  {
    SurfelPipelineReport step;
    if (!g.pipeline.light(window, g.maps.atlas(), finish, step, error) ||
      !g.resolve.from_list(
        window, g.buffers.points, g.pipeline.list_texel(), g.pipeline.radiance(), error))
    {
      return false;
    }
    report.lit_cells = step.lit_cells;
    report.seconds_cells = step.seconds_cells;
    report.seconds_B = step.seconds_B;
  }
  finish_if(finish);
  report.surfels = true;
  report.seconds_surfels = clock.lap();
  lights_ = lights;
  valid_ = true;
  return true;
}

bool TranslucentActorState::bake(vtkOpenGLRenderWindow* window, const PreparedSurfels& surfels,
  bool albedo_from_colour, const QualitySettings& settings, StepReport& report, std::string& error)
{
  Gpu& g = *gpu_;
  g.local = LocalSurfels::from(surfels.cloud, material_.mm_per_unit);
  g.dipole = std::make_unique<Dipole>(material_);
  const std::size_t n = g.local.size();
  g.buffers.upload(g.local, surfels.rgba);
  g.maps.buffers_changed();
  g.resolve.allocate(window, n);
  if (settings.strategy == KernelStrategy::Paper)
  {
    VirtualPointReport grid;
    if (!g.paper.bake(window, g.local, *g.dipole, settings.grid_level, grid, error))
    {
      return false;
    }
    report.virtual_point_count = grid.virtual_point_count;
    report.grid_level = grid.grid_level;
    report.grid_spacing_mm = grid.grid_spacing_mm;
    return true;
  }
  g.paper.release(window);
  // Colours as albedo, as the light maps' fragments take them.
  g.local.albedo.clear();
  if (albedo_from_colour)
  {
    g.local.albedo.resize(n);
    for (std::size_t i = 0; i < n; ++i)
    {
      for (int c = 0; c < 3; ++c)
      {
        g.local.albedo[i][c] = surfels.rgba[4 * i + c] / 255.0;
      }
    }
  }
  SurfelPipelineReport step;
  if (!g.pipeline.bake(window, g.local, material_, settings, step, error))
  {
    return false;
  }
  report.near_reach_mm = step.near_reach_mm;
  report.far_from_mm = step.far_from_mm;
  report.near_entries = step.near_entries;
  return true;
}

bool TranslucentActorState::show_radiance(vtkOpenGLRenderWindow* window,
  const PreparedSurfels& surfels, const Material& material, const std::vector<Rgb>& B,
  std::string& error)
{
  if (B.size() != surfels.cloud.size())
  {
    error = "the given radiance has " + std::to_string(B.size()) + " values for " +
      std::to_string(surfels.cloud.size()) + " surfels";
    return false;
  }
  material_ = material;
  gpu_->resolve.set(window, B);
  valid_ = true;
  geometry_time_ = 0;  // the next update() runs every step
  material_key_.clear();
  return true;
}

bool TranslucentActorState::read_surfel_radiance(vtkOpenGLRenderWindow* window, std::vector<Rgb>& B)
{
  return valid_ && gpu_->resolve.read(window, B);
}

}
