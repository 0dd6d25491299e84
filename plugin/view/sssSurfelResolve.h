// The hand-over from step 2 to the camera view: each surfel's B in a list texture in input
// order (surfel i at texel (i % kListWidth, i / kListWidth)), taken from the surfel pipeline's
// list or interpolated from the paper's virtual points (surfel_resolve_*.glsl), or given.
#ifndef sssSurfelResolve_h
#define sssSurfelResolve_h

#include "material.h"
#include "sssGpuHelpers.h"

#include "vtkNew.h"
#include "vtkSmartPointer.h"

#include <string>
#include <vector>

class vtkOpenGLBufferObject;
class vtkOpenGLFramebufferObject;
class vtkOpenGLRenderWindow;
class vtkTextureObject;
class vtkWindow;

namespace sss
{

class VirtualGrid;

// B on the paper's virtual points: the grid, its radiance (a 3-D texture over the grid) and
// the gathered texture the draw binds first.
struct GridRadiance
{
  const VirtualGrid* grid = nullptr;
  vtkTextureObject* radiance = nullptr;
  vtkTextureObject* gathered = nullptr;
};

class SurfelResolve
{
public:
  // A list for `count` surfels, its B not yet set; the local frame has `mm_per_unit`.
  void allocate(vtkOpenGLRenderWindow* window, std::size_t count, double mm_per_unit);
  // B from the surfel pipeline: `radiance` in its list layout, `list_texel` each surfel's texel
  // there (input order); `points` the surfels' positions (sssSurfelBuffers: scene units).
  bool from_list(vtkOpenGLRenderWindow* window, vtkOpenGLBufferObject* points,
    vtkOpenGLBufferObject* list_texel, vtkTextureObject* radiance, std::string& error);
  // B interpolated from the paper's virtual points at each surfel's position.
  bool from_grid(vtkOpenGLRenderWindow* window, vtkOpenGLBufferObject* points,
    const GridRadiance& grid, std::string& error);
  // B given per surfel (e.g. the CPU reference's).
  void set(vtkOpenGLRenderWindow* window, const std::vector<Rgb>& B);
  bool read(vtkOpenGLRenderWindow* window, std::vector<Rgb>& B);

  vtkTextureObject* texture() const { return list_; }
  int width() const { return kListWidth; }
  void release(vtkWindow* window);

private:
  bool draw(vtkOpenGLRenderWindow* window, vtkOpenGLBufferObject* points,
    vtkOpenGLBufferObject* texel, vtkTextureObject* gathered, const GridRadiance* grid,
    std::string& error);

  std::size_t count_ = 0;
  double mm_per_unit_ = 1.0;
  int height_ = 1;
  vtkSmartPointer<vtkTextureObject> list_;
  vtkNew<vtkOpenGLBufferObject> no_texel_;  // the texel attribute for the grid: unused
  std::size_t no_texel_count_ = 0;
  vtkNew<vtkOpenGLFramebufferObject> fbo_;
  ProgramVAO vao_;
};

}

#endif
