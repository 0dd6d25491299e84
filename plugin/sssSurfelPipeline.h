// Step 2 on the GPU (the NEAR_FAR strategy), in order: the surfel list (sssSurfelList), each
// surfel's cell lit through the light maps with its source pyramid (sssLitCells), the near
// field from a table the light does not change (sssNearFieldTable) and the far field by a walk
// of the lit cells' pyramid (sssFarField). The same model as the CPU reference
// (core/reference_renderer.h): the bake (cells, the near-field table, the surfel list) runs on
// the CPU when the geometry, the material or a setting changes; a light move runs three GPU
// passes per light and the near and far field's passes over all surfels.
#ifndef sssSurfelPipeline_h
#define sssSurfelPipeline_h

#include "dipole.h"
#include "local_surfels.h"
#include "material.h"
#include "near_far_split.h"
#include "quality_settings.h"
#include "sssLightMaps.h"

#include "vtkNew.h"
#include "vtkSmartPointer.h"

#include <Eigen/Core>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

class vtkOpenGLBufferObject;
class vtkOpenGLFramebufferObject;
class vtkOpenGLQuadHelper;
class vtkOpenGLRenderWindow;
class vtkShaderProgram;
class vtkTextureObject;
class vtkWindow;

namespace sss
{

struct SurfelPipelineReport
{
  double near_reach_mm = 0, far_from_mm = 0;  // near field out to, far field from (0: none)
  std::size_t near_entries = 0;               // table entries, all receivers
  std::size_t lit_cells = 0;                  // surfels with light, summed over the lights
  // With `finish`: seconds of the lit cells (irradiance and pyramid) and of B (near and far).
  double seconds_cells = 0, seconds_B = 0;
};

class SurfelPipeline
{
public:
  SurfelPipeline();
  ~SurfelPipeline();

  // The CPU bake and its uploads; `local` must carry its surface fit (and its albedo, or none
  // for white).
  bool bake(vtkOpenGLRenderWindow* window, const LocalSurfels& local, const Material& material,
    const QualitySettings& settings, SurfelPipelineReport& report, std::string& error);

  // Irradiance, source pyramids and B at every surfel for the given light maps.
  bool light(vtkOpenGLRenderWindow* window, const LightMapAtlas& maps, bool finish,
    SurfelPipelineReport& report, std::string& error);

  // B per surfel in the surfel list's layout, and each input surfel's texel in it (a vec2
  // attribute buffer, input order).
  vtkTextureObject* radiance() const;
  vtkOpenGLBufferObject* list_texel() const;

  void release(vtkWindow* window);

private:
  struct Gpu;
  std::unique_ptr<Gpu> gpu_;
};

}

#endif
