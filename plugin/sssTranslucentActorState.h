// GPU state of one translucent actor in a vtkSubsurfacePass: the illumination maps with their
// pyramid (step 1), the virtual points' 3-D radiance texture (step 2) and each surfel's B
// (step 2, per surfel), rebuilt only when what they depend on changed.
#ifndef sssTranslucentActorState_h
#define sssTranslucentActorState_h

#include "dipole.h"
#include "material.h"
#include "sssSurfelPreparation.h"

#include "vtkNew.h"
#include "vtkSmartPointer.h"
#include "vtkType.h"

#include <Eigen/Core>
#include <string>
#include <vector>

class vtkOpenGLBufferObject;
class vtkOpenGLFramebufferObject;
class vtkOpenGLRenderWindow;
class vtkOpenGLVertexArrayObject;
class vtkShaderProgram;
class vtkTextureObject;
class vtkWindow;

namespace sss
{

enum class KernelStrategy
{
  Paper = 0,     // 512 map, 49 Gaussian taps in a 40 x 40 window, grid only
  Grid = 1,      // tree walk at the virtual points' surface anchors, grid only
  GridNear = 2,  // far part on the grid, near part per surfel
  Surfel = 3,    // tree walk at every surfel, no grid
  NearFar = 4    // near field on each surfel's local surface, far field by the walk
};

struct GpuSettings
{
  KernelStrategy strategy = KernelStrategy::NearFar;
  double opening_angle = 2.0;
  double max_group_diffusion_lengths = 1000.0;
  double near_field_cells = 2.0;
  int grid_level = 0;
  double texel_per_z_r = 0.25;
  int max_map_size = 512;
  int near_rings = 8;  // near-field quadrature: rings, and at most this many nodes on each
  int near_nodes = 8;
  bool operator==(const GpuSettings& o) const
  {
    return strategy == o.strategy && opening_angle == o.opening_angle &&
      max_group_diffusion_lengths == o.max_group_diffusion_lengths &&
      near_field_cells == o.near_field_cells && grid_level == o.grid_level &&
      texel_per_z_r == o.texel_per_z_r && max_map_size == o.max_map_size &&
      near_rings == o.near_rings && near_nodes == o.near_nodes;
  }
};

struct GpuLight
{
  Eigen::Vector3d towards_light;  // local frame, unit
  Rgb irradiance;
  bool operator==(const GpuLight& o) const
  {
    return towards_light == o.towards_light && irradiance == o.irradiance;
  }
};

struct StepReport
{
  bool illumination = false, virtual_points = false, surfels = false;
  double seconds_illumination = 0, seconds_virtual_points = 0, seconds_surfels = 0;
  std::size_t lit_samples = 0, virtual_point_count = 0, surfel_count = 0;
  int map_width = 0, map_height = 0, grid_level = 0;
  double texel_mm = 0, grid_spacing_mm = 0;
  double near_reach_mm = 0, far_from_mm = 0;  // near field out to, far field from (0: none)
  int near_nodes = 0;                          // per surfel and light
};

struct ReceiverList;

constexpr int kMaxLights = 4;
constexpr int kMaxLevels = 15;
constexpr int kMaxRings = 32;

class TranslucentActorState
{
public:
  TranslucentActorState();
  ~TranslucentActorState();

  // Runs steps 1-2 where their inputs changed. `finish` waits for the GPU after each step so
  // that the reported times are real. Returns false with `error` set when it cannot run.
  bool update(vtkOpenGLRenderWindow* window, const PreparedSurfels& surfels,
    vtkMTimeType surfels_time, const Material& material, bool albedo_from_colour,
    const std::vector<GpuLight>& lights, const GpuSettings& settings, bool finish,
    StepReport& report, std::string& error);

  // The per-surfel B texture (RGBA32F, surfel i at texel (i % width, i / width)).
  vtkTextureObject* surfel_radiance() const;
  int list_width() const { return list_width_; }
  const Material& material() const { return material_; }

  // Shows B given per surfel (e.g. the CPU reference's) instead of running steps 1-2.
  bool show_radiance(vtkOpenGLRenderWindow* window, const PreparedSurfels& surfels,
    const Material& material, const std::vector<Rgb>& B, std::string& error);

  // B of every surfel, read back from the GPU (for baking and tests).
  bool read_surfel_radiance(vtkOpenGLRenderWindow* window, std::vector<Rgb>& B);

  void release(vtkWindow* window);

private:
  struct Gpu;
  bool upload_geometry(vtkOpenGLRenderWindow* window, const PreparedSurfels& surfels,
    const GpuSettings& settings, std::string& error);
  bool run_illumination(vtkOpenGLRenderWindow* window, const std::vector<GpuLight>& lights,
    const GpuSettings& settings, bool albedo_from_colour, StepReport& report, std::string& error);
  bool run_virtual_points(vtkOpenGLRenderWindow* window, const GpuSettings& settings,
    std::string& error);
  bool run_surfels(vtkOpenGLRenderWindow* window, const GpuSettings& settings, std::string& error);
  // The near field at every surfel into the surfel receivers' B texture.
  bool run_near_field(vtkOpenGLRenderWindow* window, const GpuSettings& settings,
    std::string& error);
  // B (eq. 17) at every receiver of the list into `output` (the list's B texture when null),
  // by one quad over the list.
  bool gather_at_receivers(vtkOpenGLRenderWindow* window, const GpuSettings& settings,
    ReceiverList& receivers, int part, double r0, double r1, std::string& error,
    vtkTextureObject* output = nullptr);
  void set_near_field_uniforms(vtkShaderProgram* program);
  void set_gather_uniforms(vtkShaderProgram* program, const GpuSettings& settings, int part,
    double r0, double r1);
  std::string gather_source(const GpuSettings& settings) const;

  Gpu* gpu_;
  Material material_;
  std::vector<double> material_key_;
  vtkMTimeType geometry_time_ = 0;
  GpuSettings geometry_settings_;
  std::vector<GpuLight> lights_;
  GpuSettings settings_;
  bool albedo_from_colour_ = false;
  bool valid_ = false;
  int list_width_ = 1;
};

}

#endif
