#include "sssGpuHelpers.h"

#include "vtkOpenGLQuadHelper.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkTextureObject.h"
#include "vtk_glew.h"

namespace sss
{

vtkSmartPointer<vtkTextureObject> float_texture_2d(
  vtkOpenGLRenderWindow* window, int w, int h, int components)
{
  auto tex = vtkSmartPointer<vtkTextureObject>::New();
  tex->SetContext(window);
  tex->SetInternalFormat(components == 2 ? GL_RG32F : GL_RGBA32F);
  tex->SetFormat(components == 2 ? GL_RG : GL_RGBA);
  tex->SetDataType(GL_FLOAT);
  tex->SetMinificationFilter(vtkTextureObject::Nearest);
  tex->SetMagnificationFilter(vtkTextureObject::Nearest);
  tex->SetWrapS(vtkTextureObject::ClampToEdge);
  tex->SetWrapT(vtkTextureObject::ClampToEdge);
  tex->Allocate2D(w, h, components, VTK_FLOAT);
  return tex;
}

vtkShaderProgram* ready_quad(
  std::unique_ptr<vtkOpenGLQuadHelper>& quad, vtkOpenGLRenderWindow* window, const char* fs)
{
  if (!quad)
  {
    quad = std::make_unique<vtkOpenGLQuadHelper>(window, nullptr, fs, "");
  }
  else
  {
    window->GetShaderCache()->ReadyShaderProgram(quad->Program);
  }
  return quad->Program;
}

PointPassState::PointPassState(vtkOpenGLState* state)
  : Viewport(state)
  , DepthTest(state, GL_DEPTH_TEST)
  , Blending(state, GL_BLEND)
  , PointSize(state, GL_PROGRAM_POINT_SIZE)
  , Scissor(state, GL_SCISSOR_TEST)
{
  state->vtkglDisable(GL_SCISSOR_TEST);
  state->vtkglDisable(GL_DEPTH_TEST);
  state->vtkglDisable(GL_BLEND);
  glEnable(GL_PROGRAM_POINT_SIZE);
}

}
