#include "sssSurfelResolve.h"

#include "sss_surfel_resolve_fs.h"
#include "sss_surfel_resolve_vs.h"

#include "virtual_grid.h"

#include "vtkOpenGLBufferObject.h"
#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkOpenGLState.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"
#include "vtkTextureUnitManager.h"
#include "vtk_glew.h"

#include <algorithm>

namespace sss
{

void SurfelResolve::allocate(vtkOpenGLRenderWindow* window, std::size_t count, double mm_per_unit)
{
  count_ = count;
  mm_per_unit_ = mm_per_unit;
  height_ = std::max(1, static_cast<int>((count + kListWidth - 1) / kListWidth));
  list_ = float_texture_2d(window, kListWidth, height_);
  vao_.program = nullptr;
}

void SurfelResolve::release(vtkWindow* window)
{
  release_held(window, list_);
  no_texel_->ReleaseGraphicsResources();
  no_texel_count_ = 0;
  vao_.release();
  fbo_->ReleaseGraphicsResources(window);
  count_ = 0;
}

bool SurfelResolve::from_list(vtkOpenGLRenderWindow* window, vtkOpenGLBufferObject* points,
  vtkOpenGLBufferObject* list_texel, vtkTextureObject* radiance, std::string& error)
{
  return draw(window, points, list_texel, radiance, nullptr, error);
}

bool SurfelResolve::from_grid(vtkOpenGLRenderWindow* window, vtkOpenGLBufferObject* points,
  const GridRadiance& grid, std::string& error)
{
  if (no_texel_count_ != count_)
  {
    no_texel_count_ = count_;
    no_texel_->Upload(std::vector<float>(2 * count_, 0.0f), vtkOpenGLBufferObject::ArrayBuffer);
    vao_.program = nullptr;
  }
  return draw(window, points, no_texel_, grid.gathered, &grid, error);
}

bool SurfelResolve::draw(vtkOpenGLRenderWindow* window, vtkOpenGLBufferObject* points,
  vtkOpenGLBufferObject* texel, vtkTextureObject* gathered, const GridRadiance* grid,
  std::string& error)
{
  vtkShaderProgram* program = window->GetShaderCache()->ReadyShaderProgram(
    sss_surfel_resolve_vs, sss_surfel_resolve_fs, "");
  if (!program)
  {
    error = "the per-surfel shaders did not compile";
    return false;
  }
  vtkOpenGLState* state = window->GetState();
  PointPassState point_pass(state);
  vao_.bind(program, points, "positionMC", texel, "gatheredTexel");
  program->SetUniformf("mmPerUnit", static_cast<float>(mm_per_unit_));
  gathered->Activate();
  program->SetUniformi("gathered", gathered->GetTextureUnit());
  program->SetUniformi("useGrid", grid ? 1 : 0);
  // A sampler3D must not share a texture unit with the sampler2D, even unused.
  vtkTextureUnitManager* units = window->GetTextureUnitManager();
  const int spare_unit = grid ? -1 : units->Allocate();
  program->SetUniformi("gridRadiance", spare_unit);
  if (grid)
  {
    const VirtualGrid& g = *grid->grid;
    grid->radiance->Activate();
    program->SetUniformi("gridRadiance", grid->radiance->GetTextureUnit());
    const float origin[3] = { static_cast<float>(g.origin().x()),
      static_cast<float>(g.origin().y()), static_cast<float>(g.origin().z()) };
    program->SetUniform3f("gridOrigin", origin);
    program->SetUniformf("gridSpacing", static_cast<float>(g.spacing()));
    const float dims[3] = { float(g.dims()[0]), float(g.dims()[1]), float(g.dims()[2]) };
    program->SetUniform3f("gridDims", dims);
  }
  program->SetUniformi("listWidth", kListWidth);
  const float list_size[2] = { float(kListWidth), float(height_) };
  program->SetUniform2f("listSize", list_size);

  state->PushFramebufferBindings();
  fbo_->SetContext(window);
  fbo_->Bind();
  fbo_->AddColorAttachment(0, list_);
  fbo_->ActivateDrawBuffers(1);
  state->vtkglViewport(0, 0, kListWidth, height_);
  state->vtkglClearColor(0, 0, 0, 0);
  state->vtkglClear(GL_COLOR_BUFFER_BIT);
  glDrawArrays(GL_POINTS, 0, static_cast<GLsizei>(count_));
  fbo_->RemoveColorAttachments(1);
  state->PopFramebufferBindings();
  vao_.vao->Release();
  if (grid)
  {
    grid->radiance->Deactivate();
  }
  else
  {
    units->Free(spare_unit);
  }
  gathered->Deactivate();
  return true;
}

void SurfelResolve::set(vtkOpenGLRenderWindow* window, const std::vector<Rgb>& B)
{
  allocate(window, B.size(), mm_per_unit_);
  std::vector<float> texels(4 * static_cast<std::size_t>(kListWidth) * height_, 0.0f);
  for (std::size_t i = 0; i < B.size(); ++i)
  {
    for (int c = 0; c < 3; ++c)
    {
      texels[4 * i + c] = static_cast<float>(B[i][c]);
    }
  }
  list_->Create2DFromRaw(kListWidth, height_, 4, VTK_FLOAT, texels.data());
}

bool SurfelResolve::read(vtkOpenGLRenderWindow* window, std::vector<Rgb>& B)
{
  if (!list_)
  {
    return false;
  }
  std::vector<float> texels(4 * static_cast<std::size_t>(kListWidth) * height_);
  vtkOpenGLState* state = window->GetState();
  state->PushFramebufferBindings();
  fbo_->SetContext(window);
  fbo_->Bind();
  fbo_->AddColorAttachment(0, list_);
  fbo_->ActivateReadBuffer(0);
  glReadPixels(0, 0, kListWidth, height_, GL_RGBA, GL_FLOAT, texels.data());
  fbo_->RemoveColorAttachments(1);
  state->PopFramebufferBindings();
  B.resize(count_);
  for (std::size_t i = 0; i < B.size(); ++i)
  {
    B[i] = { texels[4 * i], texels[4 * i + 1], texels[4 * i + 2] };
  }
  return true;
}

}
