// Step 1: the light maps. Each light sees the actor's surfels in an orthographic map along its
// direction, all lights' maps side by side in one atlas. For the surfel pipeline a texel holds
// the list texel of the surfel the light sees first there; for the paper's method, the point,
// power and normal of eq. 15 (illumination_fs.glsl).
#ifndef sssLightMaps_h
#define sssLightMaps_h

#include "disc_raster.h"
#include "material.h"
#include "sssGpuHelpers.h"

#include "vtkNew.h"
#include "vtkSmartPointer.h"

#include <Eigen/Core>
#include <string>
#include <vector>

class vtkOpenGLBufferObject;
class vtkOpenGLFramebufferObject;
class vtkOpenGLRenderWindow;
class vtkTextureObject;
class vtkWindow;

namespace sss
{

struct LocalSurfels;
struct SurfelBuffers;

// A directional light in the actor's local frame.
struct GpuLight
{
  Eigen::Vector3d towards_light;  // unit
  Rgb irradiance;
  bool operator==(const GpuLight& o) const
  {
    return towards_light == o.towards_light && irradiance == o.irradiance;
  }
};

// What step 1 hands to step 2: the light maps (one atlas) and their lights.
struct LightMapAtlas
{
  vtkTextureObject* surfel = nullptr;  // the seen surfel's list texel; x < 0: none
  struct Map
  {
    int x = 0, y = 0, width = 0, height = 0;  // where it lies in the atlas
    double texel = 0;                         // mm
    Eigen::Vector3d u, v;                     // image axes, local frame
    Eigen::Vector2d corner;                   // plane coordinates of its lower-left corner
    Eigen::Vector3d towards_light;            // unit
    Rgb irradiance{};
  };
  std::vector<Map> maps;
};

// What the maps hold and how fine they are.
struct LightMapRequest
{
  bool paper = false;            // the paper's maps: 512 texels a side, eq. 15 per texel
  double texel_per_radius = 0;   // otherwise: texel over the disc radius ...
  int max_map_size = 0;          // ... at most this many texels a side
  vtkOpenGLBufferObject* list_texel = nullptr;  // each surfel's list texel (not the paper)
};

struct LightMapReport
{
  int map_width = 0, map_height = 0;  // the first light's map
  double texel_mm = 0;
};

class LightMaps
{
public:
  bool render(vtkOpenGLRenderWindow* window, const SurfelBuffers& buffers,
    const LocalSurfels& local, const std::vector<GpuLight>& lights,
    const LightMapRequest& request, const Material& material, bool albedo_from_colour,
    LightMapReport& report, std::string& error);

  LightMapAtlas atlas() const;
  // The paper's maps: point, power and normal per texel.
  vtkTextureObject* point() const { return point_; }
  vtkTextureObject* power() const { return power_; }
  vtkTextureObject* normal() const { return normal_; }

  // The surfels' buffers were uploaded again: their attributes are bound anew.
  void buffers_changed() { vao_.program = nullptr; }
  void release(vtkWindow* window);

private:
  // Keeps the atlas while it is large enough and at most four times the area needed.
  void allocate(vtkOpenGLRenderWindow* window, bool paper, int width, int height);

  std::vector<OrthoView> maps_;
  std::vector<GpuLight> lights_;
  std::vector<int> map_x_;  // where each light's map starts in the atlas
  int width_ = 0, height_ = 0;
  vtkSmartPointer<vtkTextureObject> point_, power_, normal_, surfel_, depth_;
  vtkNew<vtkOpenGLFramebufferObject> fbo_;
  ProgramVAO vao_;
};

}

#endif
