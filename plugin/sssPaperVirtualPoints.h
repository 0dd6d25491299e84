// Step 2 of the paper's method (the PAPER strategy): a grid of virtual points kept where the
// surface is (core/virtual_grid.h), B at each from 49 Gaussian taps of the light maps
// (paper_taps_fs.glsl, gather_paper.glsl), stored in a 3-D texture that each surfel samples
// trilinearly.
#ifndef sssPaperVirtualPoints_h
#define sssPaperVirtualPoints_h

#include "sssGpuHelpers.h"

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
class GpuLightMaps;
class VirtualGrid;
struct LocalSurfels;
struct ReceiverList;

struct VirtualPointReport
{
  std::size_t virtual_point_count = 0;
  int grid_level = 0;
  double grid_spacing_mm = 0;
};

class PaperVirtualPoints
{
public:
  PaperVirtualPoints();
  ~PaperVirtualPoints();

  // The grid for these surfels: 2^level points per axis, 0 for the paper's 64.
  bool bake(vtkOpenGLRenderWindow* window, const LocalSurfels& local, const Dipole& dipole,
    int level, VirtualPointReport& report, std::string& error);
  // B at every virtual point from the paper's light maps, into the 3-D texture.
  bool gather(vtkOpenGLRenderWindow* window, const GpuLightMaps& maps, const Dipole& dipole,
    std::string& error);

  const VirtualGrid& grid() const { return *grid_; }
  vtkTextureObject* radiance() const { return radiance_; }  // 3-D, linear filtering
  vtkTextureObject* gathered() const;  // B per virtual point, in their list's layout
  void release(vtkWindow* window);

private:
  std::unique_ptr<VirtualGrid> grid_;
  std::unique_ptr<ReceiverList> receivers_;
  vtkNew<vtkOpenGLBufferObject> grid_index_;
  std::vector<std::pair<int, int>> slice_range_;  // first, count per k
  vtkSmartPointer<vtkTextureObject> radiance_;
  std::unique_ptr<vtkOpenGLQuadHelper> taps_quad_;
  vtkNew<vtkOpenGLFramebufferObject> taps_fbo_, grid_fbo_;
  ProgramVAO grid_vao_;
};

}

#endif
