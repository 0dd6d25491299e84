// Step 2 of the paper's method (the PAPER strategy): a grid of virtual points kept where the
// surface is (core/paper/virtual_grid.h), B at each from 49 Gaussian taps of the light maps
// (paper_taps_fs.glsl, gather_paper.glsl), stored in a 3-D texture that each surfel samples
// trilinearly.
#ifndef sssPaperStrategy_h
#define sssPaperStrategy_h

#include "sssGpuHelpers.h"
#include "sssStrategy.h"

#include "vtkNew.h"
#include "vtkSmartPointer.h"

#include <memory>
#include <string>
#include <utility>
#include <vector>

class vtkOpenGLBufferObject;
class vtkOpenGLFramebufferObject;
class vtkOpenGLQuadHelper;
class vtkOpenGLRenderWindow;
class vtkTextureObject;
class vtkWindow;

namespace sss
{

class Dipole;
class VirtualGrid;
struct LocalSurfels;
struct ReceiverList;

class PaperStrategy : public Strategy
{
public:
  PaperStrategy();
  ~PaperStrategy() override;

  // The grid for these surfels: 2^GridLevel points per axis, 0 for the paper's 64.
  bool bake(const StepContext& context, const LocalSurfels& local, const Material& material,
    const Dipole& dipole, StepReport& report, std::string& error) override;
  // The paper's maps: 512 texels a side, eq. 15 per texel.
  LightMapRequest light_map_request(const QualitySettings& settings) const override;
  // B at every virtual point from the maps, into the 3-D texture, then at each surfel.
  bool light(const StepContext& context, const GpuLightMaps& maps, const Dipole& dipole,
    SurfelResolve& resolve, vtkOpenGLBufferObject* positions, StepReport& report,
    std::string& error) override;
  void release(vtkWindow* window) override;

private:
  std::unique_ptr<VirtualGrid> grid_;
  std::unique_ptr<ReceiverList> receivers_;
  vtkNew<vtkOpenGLBufferObject> grid_index_;
  std::vector<std::pair<int, int>> slice_range_;  // first, count per k
  vtkSmartPointer<vtkTextureObject> radiance_;  // B on the grid: 3-D, linear filtering
  std::unique_ptr<vtkOpenGLQuadHelper> taps_quad_;
  vtkNew<vtkOpenGLFramebufferObject> taps_fbo_, grid_fbo_;
  ProgramVAO grid_vao_;
};

}

#endif
