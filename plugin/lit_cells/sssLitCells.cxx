#include "sssLitCells.h"

#include "sssGpuHelpers.h"
#include "sssLightMaps.h"
#include "sssSurfelList.h"
#include "sss_fresnel_table.h"
#include "sss_light_maps.h"
#include "sss_light_visibility.h"
#include "sss_cell_samples.h"
#include "sss_lit_cell_sources_fs.h"
#include "sss_pyramid_reduce_fs.h"
#include "sss_refined_cells_fs.h"
#include "sss_refined_cells_scatter_fs.h"
#include "sss_refined_cells_scatter_vs.h"
#include "sss_surfel_irradiance_fs.h"
#include "sss_surfel_list.h"

#include "fresnel.h"

#include "vtkOpenGLBufferObject.h"
#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLQuadHelper.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkOpenGLState.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"
#include "vtk_glew.h"

#include <algorithm>

namespace sss
{

namespace
{
constexpr int kFresnelTableSize = 256;
constexpr int kRefinedSamplesPerSample = 8;  // where a cell's samples disagree

void SetFloat3Array(vtkShaderProgram* program, const char* name, const std::vector<Eigen::Vector3d>& v)
{
  std::vector<float> f(3 * kMaxLights, 0.0f);
  for (std::size_t i = 0; i < v.size() && i < std::size_t(kMaxLights); ++i)
  {
    for (int c = 0; c < 3; ++c)
    {
      f[3 * i + c] = static_cast<float>(v[i][c]);
    }
  }
  program->SetUniform3fv(name, kMaxLights, f.data());
}

// The light maps' uniforms and samplers (light_maps.glsl); the maps must be active.
void SetMaps(vtkShaderProgram* program, const LightMapAtlas& maps)
{
  std::vector<float> rects(4 * kMaxLights * kMaxLevels, 0.0f), texel(kMaxLights, 0.0f),
    corner(2 * kMaxLights, 0.0f), spot(2 * kMaxLights, 0.0f);
  std::vector<int> positional(kMaxLights, 0);
  std::vector<Eigen::Vector3d> u, v, w, towards, position, attenuation, irradiance;
  for (std::size_t l = 0; l < maps.maps.size(); ++l)
  {
    const LightMapAtlas::Map& m = maps.maps[l];
    float* r = &rects[4 * l * kMaxLevels];
    r[0] = float(m.x);
    r[1] = float(m.y);
    r[2] = float(m.width());
    r[3] = float(m.height());
    const bool from_point = m.view.from_point;
    const OrthoView& o = m.view.ortho;
    const PerspectiveView& p = m.view.perspective;
    texel[l] = static_cast<float>(from_point ? p.pixel : o.pixel);
    const Eigen::Vector2d& c = from_point ? p.corner : o.corner;
    corner[2 * l] = static_cast<float>(c.x());
    corner[2 * l + 1] = static_cast<float>(c.y());
    u.push_back(from_point ? p.u : o.u);
    v.push_back(from_point ? p.v : o.v);
    w.push_back(from_point ? p.w : o.w);
    positional[l] = from_point ? 1 : 0;
    towards.push_back(m.light.direction);
    position.push_back(m.light.position);
    attenuation.push_back(m.light.attenuation);
    spot[2 * l] = static_cast<float>(m.light.cone_cos);
    spot[2 * l + 1] = static_cast<float>(m.light.exponent);
    irradiance.push_back(Eigen::Vector3d(m.irradiance[0], m.irradiance[1], m.irradiance[2]));
  }
  program->SetUniformi("lightCount", static_cast<int>(maps.maps.size()));
  program->SetUniform4fv("levelRect", kMaxLights * kMaxLevels, rects.data());
  program->SetUniform1fv("texelSize", kMaxLights, texel.data());
  program->SetUniform2fv("mapCorner", kMaxLights, corner.data());
  SetFloat3Array(program, "mapAxisU", u);
  SetFloat3Array(program, "mapAxisV", v);
  SetFloat3Array(program, "mapAxisW", w);
  program->SetUniform1iv("lightPositional", kMaxLights, positional.data());
  SetFloat3Array(program, "lightDirection", towards);
  SetFloat3Array(program, "lightPosition", position);
  SetFloat3Array(program, "lightAttenuation", attenuation);
  program->SetUniform2fv("lightSpot", kMaxLights, spot.data());
  SetFloat3Array(program, "lightIrradiance", irradiance);
  program->SetUniformi("mapSurfel", maps.surfel->GetTextureUnit());
}

// What the first pass and the refined cells' pass share: the light maps, the surfel list, the
// Fresnel table and the curvature clamp. All must be active.
void SetCellUniforms(vtkShaderProgram* program, const SurfelList& list, const LightMapAtlas& maps,
  vtkTextureObject* fresnel, double disc_radius)
{
  SetMaps(program, maps);
  program->SetUniformf("kappaLimitCell", static_cast<float>(1.0 / disc_radius));
  list.set(program);
  program->SetUniformi("fresnelTable", fresnel->GetTextureUnit());
  program->SetUniformi("fresnelTableSize", kFresnelTableSize);
}

void Barrier()
{
  if (GLEW_VERSION_4_5 || GLEW_ARB_texture_barrier)
  {
    glTextureBarrier();
  }
  else
  {
    glFinish();
  }
}
}

LitCells::LitCells() = default;
LitCells::~LitCells() = default;

void LitCells::release(vtkWindow* window)
{
  release_held(window, E_[0], E_[1], fresnel_, irradiance_quad_, refined_quad_, sources_quad_,
    reduce_quad_, refined_cell_, refined_E_[0], refined_E_[1]);
  refined_texels_->ReleaseGraphicsResources();
  scatter_vao_.release();
  for (auto& t : source_)
  {
    release_held(window, t);
  }
  fbo_->ReleaseGraphicsResources(window);
  atlas_pyramids_ = 0;
}

void LitCells::bake(vtkOpenGLRenderWindow* window, const Material& material)
{
  std::vector<float> table(4 * kFresnelTableSize, 1.0f);
  for (int k = 0; k < kFresnelTableSize; ++k)
  {
    for (int c = 0; c < 3; ++c)
    {
      table[4 * k + c] = static_cast<float>(
        fresnel_transmittance(material.eta[c], double(k) / (kFresnelTableSize - 1)));
    }
  }
  fresnel_ = float_texture_2d(window, kFresnelTableSize, 1);
  fresnel_->SetMinificationFilter(vtkTextureObject::Linear);
  fresnel_->SetMagnificationFilter(vtkTextureObject::Linear);
  fresnel_->Create2DFromRaw(kFresnelTableSize, 1, 4, VTK_FLOAT, table.data());
  // The pyramids' atlas goes with the old geometry or material: reduce() makes it anew where
  // the new one has a far field.
  for (auto& t : source_)
  {
    release_held(window, t);
  }
  levels_.clear();
  atlas_pyramids_ = 0;
}

void LitCells::allocate_irradiance(vtkOpenGLRenderWindow* window, int width, int height)
{
  if (E_[0] && E_[0]->GetWidth() == static_cast<unsigned>(width) &&
    E_[0]->GetHeight() == static_cast<unsigned>(height))
  {
    return;
  }
  for (auto& t : E_)
  {
    t = float_texture_2d(window, width, height);
  }
}

// Each pyramid: level 0 the list's size at (0, p * height), the coarser levels to its right.
void LitCells::allocate_pyramids(vtkOpenGLRenderWindow* window, int width, int height, int pyramids)
{
  levels_.assign(pyramids, {});
  for (int p = 0; p < pyramids; ++p)
  {
    std::vector<Rect>& r = levels_[p];
    r.push_back({ 0, p * height, width, height });
    int w = width, h = height, y = p * height;
    while (w > 1 || h > 1)
    {
      w = (w + 1) / 2;
      h = (h + 1) / 2;
      r.push_back({ width, y, w, h });
      y += h;
    }
  }
  if (atlas_pyramids_ == pyramids && atlas_width_ == width && atlas_height_ == height)
  {
    return;
  }
  for (auto& t : source_)
  {
    t = float_texture_2d(window, width + std::max(1, width / 2), height * pyramids);
  }
  atlas_pyramids_ = pyramids;
  atlas_width_ = width;
  atlas_height_ = height;
}

int LitCells::pyramids() const
{
  return static_cast<int>(levels_.size());
}

int LitCells::levels(int pyramid) const
{
  return static_cast<int>(levels_[pyramid].size());
}

int LitCells::level_width(int pyramid, int level) const
{
  return levels_[pyramid][level].width;
}

int LitCells::level_height(int pyramid, int level) const
{
  return levels_[pyramid][level].height;
}

void LitCells::activate_irradiance(vtkShaderProgram* program) const
{
  E_[0]->Activate();
  E_[1]->Activate();
  program->SetUniformi("frontIrradiance", E_[0]->GetTextureUnit());
  program->SetUniformi("backIrradiance", E_[1]->GetTextureUnit());
}

bool LitCells::light(vtkOpenGLRenderWindow* window, const SurfelList& list,
  const LightMapAtlas& maps, double disc_radius, int cell_samples, std::size_t& refined,
  std::string& error)
{
  lights_ = static_cast<int>(maps.maps.size());
  allocate_irradiance(window, list.width(), list.height());
  static const std::string pieces =
    std::string(sss_light_maps) + sss_surfel_list + sss_light_visibility + sss_fresnel_table +
    sss_cell_samples;
  static const std::string irradiance_fs = shader_with_pieces(sss_surfel_irradiance_fs, pieces);
  static const std::string refined_fs = shader_with_pieces(sss_refined_cells_fs, pieces);
  vtkShaderProgram* scatter = window->GetShaderCache()->ReadyShaderProgram(
    sss_refined_cells_scatter_vs, sss_refined_cells_scatter_fs, "");
  vtkShaderProgram* irradiance = ready_quad(irradiance_quad_, window, irradiance_fs.c_str());
  if (!scatter || !irradiance || !ready_quad(refined_quad_, window, refined_fs.c_str()))
  {
    error = "the irradiance or refined cells' shader did not compile";
    return false;
  }
  vtkOpenGLState* state = window->GetState();
  PointPassState pass_state(state);
  state->PushFramebufferBindings();
  fbo_->SetContext(window);
  fbo_->Bind();

  // Each cell's E on its front and back, summed over the lights.
  fbo_->AddColorAttachment(0, E_[0]);
  fbo_->AddColorAttachment(1, E_[1]);
  fbo_->ActivateDrawBuffers(2);
  window->GetShaderCache()->ReadyShaderProgram(irradiance);
  maps.surfel->Activate();
  list.activate();
  fresnel_->Activate();
  SetCellUniforms(irradiance, list, maps, fresnel_, disc_radius);
  const int refined_samples = kRefinedSamplesPerSample * cell_samples;
  irradiance->SetUniformi("cellSamples", cell_samples);
  irradiance->SetUniformi("cellRefinedSamples", refined_samples);
  state->vtkglViewport(0, 0, list.width(), list.height());
  irradiance_quad_->Render();
  fbo_->RemoveColorAttachments(2);
  refined = refine(window, list, maps, disc_radius, cell_samples, refined_samples, scatter);
  fresnel_->Deactivate();
  maps.surfel->Deactivate();
  list.deactivate();
  state->PopFramebufferBindings();
  return true;
}

std::size_t LitCells::refine(vtkOpenGLRenderWindow* window, const SurfelList& list,
  const LightMapAtlas& maps, double disc_radius, int cell_samples, int refined_samples,
  vtkShaderProgram* scatter)
{
  // The marked cells, from the front's alpha (the bits of the lights whose points disagree).
  const int list_width = list.width(), list_height = list.height();
  std::vector<float> E(4 * std::size_t(list_width) * std::size_t(list_height));
  fbo_->AddColorAttachment(0, E_[0]);
  fbo_->ActivateDrawBuffers(1);
  fbo_->ActivateReadBuffer(0);
  glReadPixels(0, 0, list_width, list_height, GL_RGBA, GL_FLOAT, E.data());
  fbo_->RemoveColorAttachments(1);
  struct Marked
  {
    int x, y, lights;
  };
  std::vector<Marked> marked;
  for (int y = 0; y < list_height; ++y)
  {
    for (int x = 0; x < list_width; ++x)
    {
      const float lights = E[4 * (std::size_t(y) * list_width + x) + 3];
      if (lights > 0.5f)
      {
        marked.push_back({ x, y, static_cast<int>(lights + 0.5f) });
      }
    }
  }
  const std::size_t count = marked.size();
  if (count == 0)
  {
    return 0;
  }
  // Cells marked for the same lights side by side, sixteen to a 4 x 4 square of the block
  // (the order refined_cells_scatter_vs.glsl reads them back in): a fragment block then runs the refined count of
  // points for the lights its cells share, not for every light some cell of it marks.
  std::stable_sort(marked.begin(), marked.end(),
    [](const Marked& a, const Marked& b) { return a.lights < b.lights; });
  const int width = std::max(4, list_width / 4 * 4);
  const int squares_per_row = width / 4;
  const std::size_t squares = (count + 15) / 16;
  const int height = static_cast<int>(4 * ((squares + squares_per_row - 1) / squares_per_row));
  std::vector<float> texels, cells(4 * std::size_t(width) * height, 0.0f);
  texels.reserve(2 * count);
  for (std::size_t i = 0; i < count; ++i)
  {
    const std::size_t square = i / 16, within = i % 16;
    const std::size_t x = 4 * (square % squares_per_row) + within % 4;
    const std::size_t y = 4 * (square / squares_per_row) + within / 4;
    texels.insert(texels.end(), { float(marked[i].x), float(marked[i].y) });
    float* cell = &cells[4 * (y * width + x)];
    cell[0] = float(marked[i].x);
    cell[1] = float(marked[i].y);
    cell[2] = float(marked[i].lights);
  }

  // Lit again in a block of their own.
  if (!refined_cell_)
  {
    refined_cell_ = float_texture_2d(window, width, height);
  }
  refined_cell_->Create2DFromRaw(width, height, 4, VTK_FLOAT, cells.data());  // same handle
  for (auto& t : refined_E_)
  {
    if (!t || t->GetWidth() != unsigned(width) || t->GetHeight() < unsigned(height))
    {
      t = float_texture_2d(window, width, height);
    }
  }
  vtkOpenGLState* state = window->GetState();
  vtkShaderProgram* program = refined_quad_->Program;
  window->GetShaderCache()->ReadyShaderProgram(program);
  SetCellUniforms(program, list, maps, fresnel_, disc_radius);
  refined_cell_->Activate();
  program->SetUniformi("refinedCell", refined_cell_->GetTextureUnit());
  program->SetUniformi("cellSamples", cell_samples);
  program->SetUniformi("cellRefinedSamples", refined_samples);
  fbo_->AddColorAttachment(0, refined_E_[0]);
  fbo_->AddColorAttachment(1, refined_E_[1]);
  fbo_->ActivateDrawBuffers(2);
  state->vtkglViewport(0, 0, width, height);
  refined_quad_->Render();
  fbo_->RemoveColorAttachments(2);
  refined_cell_->Deactivate();

  // Each back in its texel.
  window->GetShaderCache()->ReadyShaderProgram(scatter);
  refined_texels_->Upload(texels, vtkOpenGLBufferObject::ArrayBuffer);
  scatter_vao_.bind_vec2(scatter, refined_texels_, "cellTexel");
  refined_E_[0]->Activate();
  refined_E_[1]->Activate();
  scatter->SetUniformi("refinedFront", refined_E_[0]->GetTextureUnit());
  scatter->SetUniformi("refinedBack", refined_E_[1]->GetTextureUnit());
  scatter->SetUniformi("refinedWidth", width);
  const float size[2] = { float(list_width), float(list_height) };
  scatter->SetUniform2f("listSize", size);
  fbo_->AddColorAttachment(0, E_[0]);
  fbo_->AddColorAttachment(1, E_[1]);
  fbo_->ActivateDrawBuffers(2);
  state->vtkglViewport(0, 0, list_width, list_height);
  glDrawArrays(GL_POINTS, 0, static_cast<GLsizei>(count));
  scatter_vao_.vao->Release();
  fbo_->RemoveColorAttachments(2);
  refined_E_[1]->Deactivate();
  refined_E_[0]->Deactivate();
  return count;
}

bool LitCells::reduce(vtkOpenGLRenderWindow* window, const SurfelList& list, std::size_t& lit,
  std::string& error)
{
  static const std::string sources_fs =
    shader_with_pieces(sss_lit_cell_sources_fs, sss_surfel_list);
  vtkShaderProgram* sources = ready_quad(sources_quad_, window, sources_fs.c_str());
  vtkShaderProgram* reduce = ready_quad(reduce_quad_, window, sss_pyramid_reduce_fs);
  if (!sources || !reduce)
  {
    error = "the cell sources' or pyramid shader did not compile";
    return false;
  }
  allocate_pyramids(window, list.width(), list.height(), lights_ > 1 ? kMaxPyramids : 1);
  const int pyramids = this->pyramids();
  vtkOpenGLState* state = window->GetState();
  PointPassState pass_state(state);
  state->PushFramebufferBindings();
  fbo_->SetContext(window);
  fbo_->Bind();

  // The atlas cleared: the targets lit_cell_sources_fs.glsl leaves are 0 at level 0.
  state->vtkglClearColor(0, 0, 0, 0);
  state->vtkglViewport(0, 0, source_[0]->GetWidth(), source_[0]->GetHeight());
  for (int k = 0; k < kSources; ++k)
  {
    fbo_->AddColorAttachment(k, source_[k]);
  }
  fbo_->ActivateDrawBuffers(kSources);
  state->vtkglClear(GL_COLOR_BUFFER_BIT);
  fbo_->RemoveColorAttachments(kSources);

  // The finest level from both sides of each cell (lit_cell_sources_fs.glsl).
  for (int k = 0; k < kCellSources; ++k)
  {
    fbo_->AddColorAttachment(k, source_[k]);
  }
  fbo_->ActivateDrawBuffers(kCellSources);
  window->GetShaderCache()->ReadyShaderProgram(sources);
  list.activate();
  list.set(sources);
  activate_irradiance(sources);
  for (int p = 0; p < pyramids; ++p)
  {
    sources->SetUniformi("minorSide", p);
    const Rect& r = levels_[p][0];
    state->vtkglViewport(r.x, r.y, r.width, r.height);
    sources_quad_->Render();
  }
  E_[1]->Deactivate();
  E_[0]->Deactivate();
  list.deactivate();
  fbo_->RemoveColorAttachments(kCellSources);

  // The coarser levels.
  for (int k = 0; k < kSources; ++k)
  {
    fbo_->AddColorAttachment(k, source_[k]);
  }
  fbo_->ActivateDrawBuffers(kSources);
  window->GetShaderCache()->ReadyShaderProgram(reduce);
  for (auto& t : source_)
  {
    t->Activate();
  }
  const char* names[kSources] = { "mapPoint", "mapPower", "mapNormal", "mapCovariance0",
    "mapCovariance1", "mapCovariance2", "mapCovariance3", "mapCovariance4" };
  for (int k = 0; k < kSources; ++k)
  {
    reduce->SetUniformi(names[k], source_[k]->GetTextureUnit());
  }
  for (int p = 0; p < pyramids; ++p)
  {
    for (std::size_t L = 1; L < levels_[p].size(); ++L)
    {
      const Rect& src = levels_[p][L - 1];
      const Rect& dst = levels_[p][L];
      const int origin[2] = { src.x, src.y }, size[2] = { src.width, src.height },
                target[2] = { dst.width, dst.height };
      reduce->SetUniform2i("sourceOrigin", origin);
      reduce->SetUniform2i("sourceSize", size);
      reduce->SetUniform2i("targetSize", target);
      Barrier();
      state->vtkglViewport(dst.x, dst.y, dst.width, dst.height);
      reduce_quad_->Render();
    }
  }
  Barrier();
  for (auto& t : source_)
  {
    t->Deactivate();
  }
  // The pyramids' tops count the lit cells (a cell lit on both sides counts in both).
  lit = 0;
  fbo_->ActivateReadBuffer(1);
  for (int p = 0; p < pyramids; ++p)
  {
    const Rect& top = levels_[p].back();
    float value[4] = { 0, 0, 0, 0 };
    glReadPixels(top.x, top.y, 1, 1, GL_RGBA, GL_FLOAT, value);
    lit += static_cast<std::size_t>(value[3] + 0.5f);
  }
  fbo_->RemoveColorAttachments(kSources);
  state->PopFramebufferBindings();
  return true;
}

void LitCells::activate(vtkShaderProgram* program) const
{
  activate_irradiance(program);
  if (!source_[0])
  {
    return;  // no far field, so no pyramid (reduce)
  }
  const char* names[kSources] = { "sourcePoint", "sourcePower", "sourceNormal",
    "sourceCovariance0", "sourceCovariance1", "sourceCovariance2", "sourceCovariance3",
    "sourceCovariance4" };
  for (int k = 0; k < kSources; ++k)
  {
    source_[k]->Activate();
    program->SetUniformi(names[k], source_[k]->GetTextureUnit());
  }
  std::vector<float> rects(4 * kMaxPyramids * kMaxLevels, 0.0f);
  for (std::size_t p = 0; p < levels_.size(); ++p)
  {
    for (std::size_t L = 0; L < levels_[p].size() && L < std::size_t(kMaxLevels); ++L)
    {
      const Rect& r = levels_[p][L];
      float* out = &rects[4 * (p * kMaxLevels + L)];
      out[0] = float(r.x);
      out[1] = float(r.y);
      out[2] = float(r.width);
      out[3] = float(r.height);
    }
  }
  program->SetUniform4fv("sourceLevelRect", kMaxPyramids * kMaxLevels, rects.data());
}

void LitCells::deactivate() const
{
  for (auto& t : source_)
  {
    if (t)
    {
      t->Deactivate();
    }
  }
  E_[1]->Deactivate();
  E_[0]->Deactivate();
}

}
