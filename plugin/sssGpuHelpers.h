// Small GL helpers shared by the subsurface pass and its per-actor state.
#ifndef sssGpuHelpers_h
#define sssGpuHelpers_h

#include "vtkOpenGLState.h"
#include "vtkSmartPointer.h"

#include <memory>

class vtkOpenGLQuadHelper;
class vtkOpenGLRenderWindow;
class vtkShaderProgram;
class vtkTextureObject;

namespace sss
{

constexpr int kMaxLights = 4;   // lights that light translucent actors
constexpr int kMaxLevels = 15;  // pyramid levels per light (maps or surfel lists of 2^14)

// An RGBA32F (or, with 2 components, RG32F) texture with nearest filtering, clamped at the
// edges.
vtkSmartPointer<vtkTextureObject> float_texture_2d(
  vtkOpenGLRenderWindow* window, int w, int h, int components = 4);

// Creates the full-screen quad on first use and binds its program; nullptr if it did not
// compile.
vtkShaderProgram* ready_quad(
  std::unique_ptr<vtkOpenGLQuadHelper>& quad, vtkOpenGLRenderWindow* window, const char* fs);

// GL state of the passes that draw one GL point per output texel: no scissor, depth test or
// blending, point size from the shader, own viewport. Restores all of it on destruction.
class PointPassState
{
public:
  explicit PointPassState(vtkOpenGLState* state);

private:
  vtkOpenGLState::ScopedglViewport Viewport;
  vtkOpenGLState::ScopedglEnableDisable DepthTest, Blending, PointSize, Scissor;
};

}

#endif
