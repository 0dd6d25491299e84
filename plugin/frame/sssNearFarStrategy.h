// Step 2 on the GPU (the NEAR_FAR strategy), in order: the surfel list (sssSurfelList), each
// surfel's cell lit through the light maps and its source pyramid (sssLitCells), the near field
// from a table the light does not change (sssNearFieldTable) and the far field by a walk of the lit
// cells' pyramid (sssFarField). The same model as the CPU reference
// (core/reference/reference_renderer.h): the bake (cells, the near-field table, the surfel list)
// runs on the CPU when the geometry, the material or a setting changes; a light move lights the
// cells for all lights in one pass, reduces the lights' shared source pyramids (one, or two where
// cells are lit on both sides) where there is a far field, and runs the near and far field's
// passes over all surfels.
#ifndef sssNearFarStrategy_h
#define sssNearFarStrategy_h

#include "dipole.h"
#include "local_surfels.h"
#include "material.h"
#include "near_far_split.h"
#include "quality_settings.h"
#include "sssLightMaps.h"
#include "sssStrategy.h"

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

class NearFarStrategy : public Strategy
{
public:
  NearFarStrategy();
  ~NearFarStrategy() override;

  // The CPU bake (cells, the near-field table, the surfel list) and its uploads.
  bool bake(const StepContext& context, const LocalSurfels& local, const Material& material,
    const Dipole& dipole, StepReport& report, std::string& error) override;
  // The cells and the near-field table's weights (most of the bake's time).
  BakeWork bake_work(const LocalSurfels& local, const Dipole& dipole) const override;
  void adopt(std::unique_ptr<BakePreparation> prepared) override;
  // Maps of the surfel each texel sees, texels TexelPerRadius of a disc radius.
  LightMapRequest light_map_request(const QualitySettings& settings) const override;
  // Irradiance, source pyramids (where there is a far field) and B at every surfel for the
  // given light maps, handed to the view; with the context's `finish` the report's seconds of
  // each of these steps are exact.
  bool light(const StepContext& context, const GpuLightMaps& maps, const Dipole& dipole,
    SurfelResolve& resolve, vtkOpenGLBufferObject* positions, StepReport& report,
    std::string& error) override;
  void release(vtkWindow* window) override;

private:
  struct Gpu;
  struct Preparation;
  // bake_work's work. Throws std::exception.
  static std::unique_ptr<Preparation> prepare(
    const LocalSurfels& local, const Dipole& dipole, const CancelFlag* cancel = nullptr);
  std::unique_ptr<Gpu> gpu_;
};

}

#endif
