// Step 2's surfel list (surfel_list.glsl): the surfels in Hilbert order of position, laid out
// in 2-D Morton order too, so that every 2^k x 2^k square of texels holds surfels that lie
// close together (the source pyramid reduces such squares, sssLitCells). Per texel: the
// surfel's point and surface thickness, normal and curvature, cell and albedo.
#ifndef sssSurfelList_h
#define sssSurfelList_h

#include "vtkNew.h"
#include "vtkSmartPointer.h"

#include <cstddef>
#include <string>
#include <vector>

class vtkOpenGLBufferObject;
class vtkOpenGLRenderWindow;
class vtkShaderProgram;
class vtkTextureObject;
class vtkWindow;

namespace sss
{

struct LocalSurfels;
struct SurfelCells;

class SurfelList
{
public:
  SurfelList();
  ~SurfelList();

  // `local` must carry its surface fit (and its albedo, or none for white).
  bool upload(vtkOpenGLRenderWindow* window, const LocalSurfels& local, const SurfelCells& cells,
    std::string& error);

  int width() const { return width_; }
  int height() const { return height_; }
  // Input surfel i's texel as y * width + x.
  std::size_t texel_of(std::size_t i) const { return texel_of_[i]; }
  // The same as a vec2 attribute per input surfel.
  vtkOpenGLBufferObject* texel_buffer() const { return texel_; }

  void activate() const;
  void deactivate() const;
  void set(vtkShaderProgram* program) const;  // surfel_list.glsl's samplers; active
  void release(vtkWindow* window);

private:
  int width_ = 1, height_ = 1;
  std::vector<std::size_t> texel_of_;
  vtkSmartPointer<vtkTextureObject> point_, shape_, cell_, albedo_;
  vtkNew<vtkOpenGLBufferObject> texel_;
};

}

#endif
