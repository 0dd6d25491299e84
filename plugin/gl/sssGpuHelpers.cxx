#include "sssGpuHelpers.h"

#include "sss_dipole.h"

#include "vtkOpenGLBufferObject.h"
#include "vtkOpenGLQuadHelper.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkShaderProgram.h"
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

vtkSmartPointer<vtkTextureObject> upload_float_texture(
  vtkOpenGLRenderWindow* window, int w, int h, const std::vector<float>& texels)
{
  vtkSmartPointer<vtkTextureObject> t = float_texture_2d(window, w, h);
  t->Create2DFromRaw(w, h, 4, VTK_FLOAT, const_cast<float*>(texels.data()));
  return t;
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

std::string shader_with_pieces(std::string source, const std::string& gather)
{
  vtkShaderProgram::Substitute(source, "//SSS::Gather::Dec", gather, true);
  vtkShaderProgram::Substitute(source, "//SSS::Dipole::Dec", sss_dipole, true);
  vtkShaderProgram::Substitute(source, "SSS_MAX_LIGHTS", std::to_string(kMaxLights), true);
  vtkShaderProgram::Substitute(source, "SSS_MAX_LEVELS", std::to_string(kMaxLevels), true);
  vtkShaderProgram::Substitute(source, "SSS_MAX_PYRAMIDS", std::to_string(kMaxPyramids), true);
  return source;
}

void finish_if(bool finish)
{
  if (finish)
  {
    glFinish();
  }
}

void ProgramVAO::bind_attributes(vtkShaderProgram* p, vtkOpenGLBufferObject* buffer,
  const char* name, int components, vtkOpenGLBufferObject* buffer2, const char* name2)
{
  vao->Bind();
  if (needs(p))
  {
    vao->ReleaseGraphicsResources();
    vao->Bind();
    vao->AddAttributeArray(p, buffer, name, 0, 4 * components, VTK_FLOAT, components, false);
    if (buffer2)
    {
      vao->AddAttributeArray(p, buffer2, name2, 0, 8, VTK_FLOAT, 2, false);
    }
    program = p;
  }
}

void ProgramVAO::release()
{
  vao->ReleaseGraphicsResources();
  program = nullptr;
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
