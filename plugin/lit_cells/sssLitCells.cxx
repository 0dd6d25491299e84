#include "sssLitCells.h"

#include "sssGpuHelpers.h"
#include "sssLightMaps.h"
#include "sssSurfelList.h"
#include "sss_fresnel_table.h"
#include "sss_light_maps.h"
#include "sss_light_visibility.h"
#include "sss_cell_samples.h"
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
  release_held(window, E_, fresnel_, irradiance_quad_, refined_quad_, reduce_quad_, refined_cell_,
    refined_E_);
  refined_texels_->ReleaseGraphicsResources();
  scatter_vao_.release();
  for (auto& t : source_)
  {
    release_held(window, t);
  }
  fbo_->ReleaseGraphicsResources(window);
  atlas_lights_ = 0;
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
  atlas_lights_ = 0;
}

// Each light's pyramid: level 0 the list's size at (0, l * height), the coarser levels to its
// right.
void LitCells::allocate(vtkOpenGLRenderWindow* window, int width, int height, int lights)
{
  levels_.assign(lights, {});
  for (int l = 0; l < lights; ++l)
  {
    std::vector<Rect>& r = levels_[l];
    r.push_back({ 0, l * height, width, height });
    int w = width, h = height, y = l * height;
    while (w > 1 || h > 1)
    {
      w = (w + 1) / 2;
      h = (h + 1) / 2;
      r.push_back({ width, y, w, h });
      y += h;
    }
  }
  if (atlas_lights_ == lights && atlas_width_ == width && atlas_height_ == height && E_)
  {
    return;
  }
  const int atlas_w = width + std::max(1, width / 2);
  const int atlas_h = height * lights;
  E_ = float_texture_2d(window, width, atlas_h);
  for (auto& t : source_)
  {
    t = float_texture_2d(window, atlas_w, atlas_h);
  }
  atlas_lights_ = lights;
  atlas_width_ = width;
  atlas_height_ = height;
}

int LitCells::levels(int light) const
{
  return static_cast<int>(levels_[light].size());
}

int LitCells::level_width(int light, int level) const
{
  return levels_[light][level].width;
}

int LitCells::level_height(int light, int level) const
{
  return levels_[light][level].height;
}

bool LitCells::light(vtkOpenGLRenderWindow* window, const SurfelList& list,
  const LightMapAtlas& maps, double disc_radius, int cell_samples, std::size_t& refined,
  std::string& error)
{
  const int lights = static_cast<int>(maps.maps.size());
  allocate(window, list.width(), list.height(), std::max(lights, 1));
  static const std::string pieces =
    std::string(sss_light_maps) + sss_surfel_list + sss_light_visibility + sss_fresnel_table +
    sss_cell_samples;
  static const std::string irradiance_fs = shader_with_pieces(sss_surfel_irradiance_fs, pieces);
  static const std::string refined_fs = shader_with_pieces(sss_refined_cells_fs, pieces);
  static const std::string scatter_fs =
    shader_with_pieces(sss_refined_cells_scatter_fs, sss_surfel_list);
  vtkShaderProgram* scatter = window->GetShaderCache()->ReadyShaderProgram(
    sss_refined_cells_scatter_vs, scatter_fs.c_str(), "");
  vtkShaderProgram* irradiance = ready_quad(irradiance_quad_, window, irradiance_fs.c_str());
  if (!scatter || !irradiance || !ready_quad(refined_quad_, window, refined_fs.c_str()) ||
    !ready_quad(reduce_quad_, window, sss_pyramid_reduce_fs))
  {
    error = "the irradiance, refined cells' or pyramid shader did not compile";
    return false;
  }
  lights_ = lights;
  vtkOpenGLState* state = window->GetState();
  PointPassState pass_state(state);
  state->PushFramebufferBindings();
  fbo_->SetContext(window);
  fbo_->Bind();

  // Each light: the cells' irradiance and the finest level of its source pyramid.
  state->vtkglClearColor(0, 0, 0, 0);
  state->vtkglViewport(0, 0, source_[0]->GetWidth(), source_[0]->GetHeight());
  for (int k = 0; k < kSources; ++k)
  {
    fbo_->AddColorAttachment(k, source_[k]);
  }
  fbo_->ActivateDrawBuffers(kSources);
  state->vtkglClear(GL_COLOR_BUFFER_BIT);
  fbo_->RemoveColorAttachments(kSources);
  fbo_->AddColorAttachment(0, E_);
  for (int k = 0; k < kCellSources; ++k)
  {
    fbo_->AddColorAttachment(k + 1, source_[k]);
  }
  fbo_->ActivateDrawBuffers(kCellSources + 1);
  state->vtkglClear(GL_COLOR_BUFFER_BIT);
  window->GetShaderCache()->ReadyShaderProgram(irradiance);
  maps.surfel->Activate();
  list.activate();
  fresnel_->Activate();
  SetCellUniforms(irradiance, list, maps, fresnel_, disc_radius);
  const int refined_samples = kRefinedSamplesPerSample * cell_samples;
  irradiance->SetUniformi("cellSamples", cell_samples);
  irradiance->SetUniformi("cellRefinedSamples", refined_samples);
  for (int l = 0; l < lights; ++l)
  {
    irradiance->SetUniformi("light", l);
    const Rect& r = levels_[l][0];
    state->vtkglViewport(r.x, r.y, r.width, r.height);
    irradiance_quad_->Render();
  }
  fbo_->RemoveColorAttachments(kCellSources + 1);
  refined = 0;
  for (int l = 0; l < lights; ++l)
  {
    refined += refine(window, list, maps, disc_radius, refined_samples, scatter, l);
  }
  fresnel_->Deactivate();
  list.deactivate();
  maps.surfel->Deactivate();
  state->PopFramebufferBindings();
  return true;
}

std::size_t LitCells::refine(vtkOpenGLRenderWindow* window, const SurfelList& list,
  const LightMapAtlas& maps, double disc_radius, int refined_samples, vtkShaderProgram* scatter,
  int l)
{
  // The marked cells, from E's alpha.
  const Rect& r = levels_[l][0];
  std::vector<float> E(4 * std::size_t(r.width) * std::size_t(r.height));
  fbo_->AddColorAttachment(0, E_);
  fbo_->ActivateDrawBuffers(1);
  fbo_->ActivateReadBuffer(0);
  glReadPixels(r.x, r.y, r.width, r.height, GL_RGBA, GL_FLOAT, E.data());
  fbo_->RemoveColorAttachments(1);
  std::vector<float> texels;
  for (int y = 0; y < r.height; ++y)
  {
    for (int x = 0; x < r.width; ++x)
    {
      if (E[4 * (std::size_t(y) * r.width + x) + 3] > 0.5f)
      {
        texels.push_back(float(x));
        texels.push_back(float(y));
      }
    }
  }
  const std::size_t count = texels.size() / 2;
  if (count == 0)
  {
    return 0;
  }

  // Lit again in a block of their own, row by row.
  const int width = r.width;
  const int height = static_cast<int>((count + width - 1) / width);
  texels.resize(2 * std::size_t(width) * height, 0.0f);
  if (!refined_cell_)
  {
    refined_cell_ = float_texture_2d(window, width, height, 2);
  }
  refined_cell_->Create2DFromRaw(width, height, 2, VTK_FLOAT, texels.data());  // same handle
  if (!refined_E_ || refined_E_->GetWidth() != unsigned(width) ||
    refined_E_->GetHeight() < unsigned(height))
  {
    refined_E_ = float_texture_2d(window, width, height);
  }
  vtkOpenGLState* state = window->GetState();
  vtkShaderProgram* program = refined_quad_->Program;
  window->GetShaderCache()->ReadyShaderProgram(program);
  SetCellUniforms(program, list, maps, fresnel_, disc_radius);
  refined_cell_->Activate();
  program->SetUniformi("refinedCell", refined_cell_->GetTextureUnit());
  program->SetUniformi("refinedCount", static_cast<int>(count));
  program->SetUniformi("cellRefinedSamples", refined_samples);
  program->SetUniformi("light", l);
  fbo_->AddColorAttachment(0, refined_E_);
  fbo_->ActivateDrawBuffers(1);
  state->vtkglViewport(0, 0, width, height);
  refined_quad_->Render();
  fbo_->RemoveColorAttachments(1);
  refined_cell_->Deactivate();

  // Each back in its texel: E, and the power and weight of the pyramid's finest level.
  window->GetShaderCache()->ReadyShaderProgram(scatter);
  texels.resize(2 * count);
  refined_texels_->Upload(texels, vtkOpenGLBufferObject::ArrayBuffer);
  scatter_vao_.bind_vec2(scatter, refined_texels_, "cellTexel");
  list.set(scatter);
  refined_E_->Activate();
  scatter->SetUniformi("refinedE", refined_E_->GetTextureUnit());
  scatter->SetUniformi("refinedWidth", width);
  const float size[2] = { float(r.width), float(r.height) };
  scatter->SetUniform2f("listSize", size);
  fbo_->AddColorAttachment(0, E_);
  fbo_->AddColorAttachment(1, source_[0]);
  fbo_->AddColorAttachment(2, source_[1]);
  fbo_->ActivateDrawBuffers(3);
  state->vtkglViewport(r.x, r.y, r.width, r.height);
  glDrawArrays(GL_POINTS, 0, static_cast<GLsizei>(count));
  scatter_vao_.vao->Release();
  fbo_->RemoveColorAttachments(3);
  refined_E_->Deactivate();
  return count;
}

void LitCells::reduce(vtkOpenGLRenderWindow* window, std::size_t& lit)
{
  const int lights = lights_;
  vtkShaderProgram* reduce = reduce_quad_->Program;
  vtkOpenGLState* state = window->GetState();
  PointPassState pass_state(state);
  state->PushFramebufferBindings();
  fbo_->SetContext(window);
  fbo_->Bind();
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
  for (int l = 0; l < lights; ++l)
  {
    for (std::size_t L = 1; L < levels_[l].size(); ++L)
    {
      const Rect& src = levels_[l][L - 1];
      const Rect& dst = levels_[l][L];
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
  // The pyramids' tops count the lit cells.
  lit = 0;
  fbo_->ActivateReadBuffer(1);
  for (int l = 0; l < lights; ++l)
  {
    const Rect& top = levels_[l].back();
    float value[4] = { 0, 0, 0, 0 };
    glReadPixels(top.x, top.y, 1, 1, GL_RGBA, GL_FLOAT, value);
    lit += static_cast<std::size_t>(value[3] + 0.5f);
  }
  fbo_->RemoveColorAttachments(kSources);
  state->PopFramebufferBindings();
}

void LitCells::activate(vtkShaderProgram* program) const
{
  E_->Activate();
  program->SetUniformi("irradiance", E_->GetTextureUnit());
  const char* names[kSources] = { "sourcePoint", "sourcePower", "sourceNormal",
    "sourceCovariance0", "sourceCovariance1", "sourceCovariance2", "sourceCovariance3",
    "sourceCovariance4" };
  for (int k = 0; k < kSources; ++k)
  {
    source_[k]->Activate();
    program->SetUniformi(names[k], source_[k]->GetTextureUnit());
  }
  std::vector<float> rects(4 * kMaxLights * kMaxLevels, 0.0f);
  for (std::size_t l = 0; l < levels_.size(); ++l)
  {
    for (std::size_t L = 0; L < levels_[l].size() && L < std::size_t(kMaxLevels); ++L)
    {
      const Rect& r = levels_[l][L];
      float* out = &rects[4 * (l * kMaxLevels + L)];
      out[0] = float(r.x);
      out[1] = float(r.y);
      out[2] = float(r.width);
      out[3] = float(r.height);
    }
  }
  program->SetUniform4fv("sourceLevelRect", kMaxLights * kMaxLevels, rects.data());
}

void LitCells::deactivate() const
{
  for (auto& t : source_)
  {
    t->Deactivate();
  }
  E_->Deactivate();
}

}
