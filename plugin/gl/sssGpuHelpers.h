// Small GL helpers shared by the subsurface pass and the rooms of its steps.
#ifndef sssGpuHelpers_h
#define sssGpuHelpers_h

#include "vtkNew.h"
#include "vtkOpenGLState.h"
#include "vtkOpenGLVertexArrayObject.h"
#include "vtkSmartPointer.h"

#include <memory>
#include <string>
#include <vector>

class vtkOpenGLBufferObject;
class vtkOpenGLQuadHelper;
class vtkOpenGLRenderWindow;
class vtkShaderProgram;
class vtkTextureObject;
class vtkWindow;

namespace sss
{

constexpr int kMaxLights = 5;   // lights that light translucent actors: ParaView's five by default
constexpr int kMaxLevels = 15;  // levels of a light map or a source pyramid (up to 2^14 a side)
constexpr int kMaxPyramids = 2;  // source pyramids the lights share: cells' more lit side, other
constexpr int kListWidth = 256;  // of list textures: squarish keeps the rasteriser's tiles busy

// An RGBA32F (or, with 2 components, RG32F) texture with nearest filtering, clamped at the
// edges.
vtkSmartPointer<vtkTextureObject> float_texture_2d(
  vtkOpenGLRenderWindow* window, int w, int h, int components = 4);

// The same holding `texels` (RGBA, w x h).
vtkSmartPointer<vtkTextureObject> upload_float_texture(
  vtkOpenGLRenderWindow* window, int w, int h, const std::vector<float>& texels);

// Creates the full-screen quad on first use and binds its program; nullptr if it did not
// compile.
vtkShaderProgram* ready_quad(
  std::unique_ptr<vtkOpenGLQuadHelper>& quad, vtkOpenGLRenderWindow* window, const char* fs);

// `source` with its hooks filled: //SSS::Gather::Dec by `gather`, //SSS::Dipole::Dec by
// dipole.glsl, and the SSS_MAX_LIGHTS and SSS_MAX_LEVELS constants.
std::string shader_with_pieces(std::string source, const std::string& gather);

// Releases the graphics resources of each texture or quad held (vtkSmartPointer or
// std::unique_ptr; those not held are skipped) and lets go of it.
template <typename... Held>
void release_held(vtkWindow* window, Held&... held)
{
  const auto one = [window](auto& object) {
    if (object)
    {
      object->ReleaseGraphicsResources(window);
      object = nullptr;
    }
  };
  (one(held), ...);
}

// Waits for the GPU when `finish` is set, so that a step's reported time is real.
void finish_if(bool finish);

// A VAO bound to one program's attribute locations, rebuilt when the program changes.
struct ProgramVAO
{
  vtkNew<vtkOpenGLVertexArrayObject> vao;
  vtkShaderProgram* program = nullptr;
  bool needs(vtkShaderProgram* p) const { return p != program; }
  // Binds the VAO with one vec3 attribute and, if given, one vec2 attribute, re-linked when
  // the program changed.
  void bind(vtkShaderProgram* p, vtkOpenGLBufferObject* buffer, const char* name,
    vtkOpenGLBufferObject* buffer2 = nullptr, const char* name2 = nullptr)
  {
    bind_attributes(p, buffer, name, 3, buffer2, name2);
  }
  // The same with one vec2 attribute alone.
  void bind_vec2(vtkShaderProgram* p, vtkOpenGLBufferObject* buffer, const char* name)
  {
    bind_attributes(p, buffer, name, 2, nullptr, nullptr);
  }
  void release();

private:
  // The first attribute has `components` floats, the second (if given) two.
  void bind_attributes(vtkShaderProgram* p, vtkOpenGLBufferObject* buffer, const char* name,
    int components, vtkOpenGLBufferObject* buffer2, const char* name2);
};

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
