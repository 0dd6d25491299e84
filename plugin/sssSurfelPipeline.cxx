#include "sssSurfelPipeline.h"

#include "sssGpuHelpers.h"
#include "sss_dipole.h"
#include "sss_far_field.h"
#include "sss_fresnel_table.h"
#include "sss_light_maps.h"
#include "sss_light_visibility.h"
#include "sss_near_field.h"
#include "sss_near_field_fs.h"
#include "sss_pyramid_reduce_fs.h"
#include "sss_surfel_irradiance_fs.h"
#include "sss_surfel_list.h"

#include "fresnel.h"
#include "local_surface.h"
#include "morton_order.h"
#include "near_field.h"
#include "stopwatch.h"
#include "surfel_cells.h"
#include "surfel_index.h"

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
#include <cmath>

namespace sss
{

namespace
{
// Sources beyond this distance carry less than this fraction of the kernel's integral.
constexpr double kSupportFraction = 1e-7;
constexpr int kFresnelTableSize = 256;
constexpr int kEntriesWidth = 4096;
constexpr int kWalkRoot = 7;  // pyramid level whose nodes the far field's quads start from

struct Rect
{
  int x, y, width, height;
};

int CeilLog2(std::size_t n)
{
  int k = 0;
  while ((std::size_t(1) << k) < n)
  {
    ++k;
  }
  return k;
}

// The texel of list position `rank` in a 2^xbits x 2^ybits layout: its bits dealt to x and y
// in turn (x first), an axis that is full skipped, so that every 2^k x 2^k square holds
// consecutive ranks.
std::pair<int, int> MortonTexel(std::size_t rank, int xbits, int ybits)
{
  int x = 0, y = 0, xi = 0, yi = 0;
  for (int bit = 0; bit < xbits + ybits; ++bit)
  {
    const int value = static_cast<int>((rank >> bit) & 1u);
    const bool to_x = xi < xbits && (yi >= ybits || xi <= yi);
    if (to_x)
    {
      x |= value << xi++;
    }
    else
    {
      y |= value << yi++;
    }
  }
  return { x, y };
}

vtkSmartPointer<vtkTextureObject> Upload(
  vtkOpenGLRenderWindow* window, int w, int h, std::vector<float>& texels)
{
  vtkSmartPointer<vtkTextureObject> t = float_texture_2d(window, w, h);
  t->Create2DFromRaw(w, h, 4, VTK_FLOAT, texels.data());
  return t;
}

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

struct SurfelPipeline::Gpu
{
  std::size_t count = 0;
  int width = 1, height = 1, xbits = 0, ybits = 0;
  std::unique_ptr<Dipole> dipole;
  Material material;
  NearFarSplit split;
  double support = 0;
  double radius = 0;
  SurfelPipelineSettings settings;

  vtkSmartPointer<vtkTextureObject> point, shape, cell, albedo, rows, entries, fresnel, B;
  // Per light atlases: E, and the source pyramid (pyramid_reduce_fs.glsl): point, power,
  // normal, then the moments of points, normals and their cross term. The irradiance pass
  // writes the first kCellSources at level 0; a cell's normal is constant, so the others are
  // 0 there.
  static constexpr int kSources = 8, kCellSources = 5;
  vtkSmartPointer<vtkTextureObject> E, source[kSources];
  int atlas_lights = 0;
  std::vector<std::vector<Rect>> levels;  // per light: the source pyramid's levels
  vtkNew<vtkOpenGLBufferObject> texel;    // per input surfel: its list texel
  vtkNew<vtkOpenGLFramebufferObject> fbo;
  std::unique_ptr<vtkOpenGLQuadHelper> irradiance_quad, reduce_quad, gather_quad;

  void release(vtkWindow* window)
  {
    for (auto* t : { &point, &shape, &cell, &albedo, &rows, &entries, &fresnel, &B, &E })
    {
      if (*t)
      {
        (*t)->ReleaseGraphicsResources(window);
        *t = nullptr;
      }
    }
    for (auto& t : source)
    {
      if (t)
      {
        t->ReleaseGraphicsResources(window);
        t = nullptr;
      }
    }
    for (auto* q : { &irradiance_quad, &reduce_quad, &gather_quad })
    {
      if (*q)
      {
        (*q)->ReleaseGraphicsResources(window);
        q->reset();
      }
    }
    texel->ReleaseGraphicsResources();
    fbo->ReleaseGraphicsResources(window);
    atlas_lights = 0;
  }

  // The dipole's uniforms (dipole.glsl) and where the far field starts (far_field.glsl).
  void set_dipole(vtkShaderProgram* program) const
  {
    float zr[3], zv[3], str[3], factor[3], eta[3];
    for (int c = 0; c < 3; ++c)
    {
      const DipoleChannel& ch = dipole->channel[c];
      zr[c] = static_cast<float>(ch.z_r);
      zv[c] = static_cast<float>(ch.z_v);
      str[c] = static_cast<float>(ch.s_tr);
      factor[c] = static_cast<float>(ch.alpha_prime / (4.0 * M_PI));
      eta[c] = static_cast<float>(material.eta[c]);
    }
    program->SetUniform3f("zR", zr);
    program->SetUniform3f("zV", zv);
    program->SetUniform3f("sTr", str);
    program->SetUniform3f("rdFactor", factor);
    program->SetUniform3f("eta", eta);
    program->SetUniformf("farFrom", static_cast<float>(split.reach));
  }

  // The light maps' uniforms and samplers (light_maps.glsl); the maps must be active.
  void set_maps(vtkShaderProgram* program, const LightMapAtlas& maps) const
  {
    std::vector<float> rects(4 * kMaxLights * kMaxLevels, 0.0f), texel(kMaxLights, 0.0f),
      corner(2 * kMaxLights, 0.0f);
    std::vector<Eigen::Vector3d> u, v, towards, irradiance;
    for (std::size_t l = 0; l < maps.maps.size(); ++l)
    {
      const LightMapAtlas::Map& m = maps.maps[l];
      float* r = &rects[4 * l * kMaxLevels];
      r[0] = float(m.x);
      r[1] = float(m.y);
      r[2] = float(m.width);
      r[3] = float(m.height);
      texel[l] = static_cast<float>(m.texel);
      corner[2 * l] = static_cast<float>(m.corner.x());
      corner[2 * l + 1] = static_cast<float>(m.corner.y());
      u.push_back(m.u);
      v.push_back(m.v);
      towards.push_back(m.towards_light);
      irradiance.push_back(Eigen::Vector3d(m.irradiance[0], m.irradiance[1], m.irradiance[2]));
    }
    program->SetUniformi("lightCount", static_cast<int>(maps.maps.size()));
    program->SetUniform4fv("levelRect", kMaxLights * kMaxLevels, rects.data());
    program->SetUniform1fv("texelSize", kMaxLights, texel.data());
    program->SetUniform2fv("mapCorner", kMaxLights, corner.data());
    SetFloat3Array(program, "mapAxisU", u);
    SetFloat3Array(program, "mapAxisV", v);
    SetFloat3Array(program, "lightDirection", towards);
    SetFloat3Array(program, "lightIrradiance", irradiance);
    program->SetUniformi("mapSurfel", maps.surfel->GetTextureUnit());
    program->SetUniformf("kappaLimitCell", static_cast<float>(1.0 / radius));
  }

  void activate_list()
  {
    for (vtkTextureObject* t : { point.Get(), shape.Get(), cell.Get(), albedo.Get() })
    {
      t->Activate();
    }
  }
  void deactivate_list()
  {
    for (vtkTextureObject* t : { point.Get(), shape.Get(), cell.Get(), albedo.Get() })
    {
      t->Deactivate();
    }
  }
  void set_list(vtkShaderProgram* program) const
  {
    program->SetUniformi("surfelPoint", point->GetTextureUnit());
    program->SetUniformi("surfelShape", shape->GetTextureUnit());
    program->SetUniformi("surfelCell", cell->GetTextureUnit());
    program->SetUniformi("surfelAlbedo", albedo->GetTextureUnit());
  }

  // The source atlases for `lights` lights: each light's pyramid, level 0 the list's size at
  // (0, l * height), the coarser levels to its right.
  void allocate_sources(vtkOpenGLRenderWindow* window, int lights)
  {
    levels.assign(lights, {});
    for (int l = 0; l < lights; ++l)
    {
      std::vector<Rect>& r = levels[l];
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
    if (atlas_lights == lights && E)
    {
      return;
    }
    const int atlas_w = width + std::max(1, width / 2);
    const int atlas_h = height * lights;
    E = float_texture_2d(window, width, atlas_h);
    for (auto& t : source)
    {
      t = float_texture_2d(window, atlas_w, atlas_h);
    }
    atlas_lights = lights;
  }
};

SurfelPipeline::SurfelPipeline()
  : gpu_(new Gpu)
{
}

SurfelPipeline::~SurfelPipeline() = default;

vtkTextureObject* SurfelPipeline::radiance() const
{
  return gpu_->B;
}

vtkOpenGLBufferObject* SurfelPipeline::list_texel() const
{
  return gpu_->texel;
}

void SurfelPipeline::release(vtkWindow* window)
{
  gpu_->release(window);
}

bool SurfelPipeline::bake(vtkOpenGLRenderWindow* window, const LocalSurfels& local,
  const Material& material, const SurfelPipelineSettings& settings, SurfelPipelineReport& report,
  std::string& error)
{
  Gpu& g = *gpu_;
  const std::size_t n = local.size();
  g.count = n;
  g.material = material;
  g.settings = settings;
  g.radius = local.radius;
  g.dipole = std::make_unique<Dipole>(material);
  g.support = g.dipole->max_support_radius(kSupportFraction);
  g.split = NearFarSplit::choose(*g.dipole, local.radius > 0.0 ? local.radius : 1.0, kSupportFraction);
  SurfelCells cells;
  NearFieldWeights weights;
  try
  {
    const SurfelIndex index(local.positions);
    cells = surfel_cells(local, index);
    weights = near_field_weights(local, cells, index, *g.dipole, g.split.reach);
  }
  catch (const std::exception& e)
  {
    error = e.what();
    return false;
  }
  report.near_reach_mm = g.split.reach;
  report.far_from_mm = g.split.has_far ? g.split.reach : 0.0;
  report.near_entries = weights.source.size();
  const std::vector<double>& area = cells.area;

  // The surfel list: Morton order of position, laid out in 2-D Morton order.
  const std::vector<std::size_t> order = morton_order(local.positions);
  const int bits = CeilLog2(std::max<std::size_t>(n, 1));
  g.xbits = (bits + 1) / 2;
  g.ybits = bits - g.xbits;
  g.width = 1 << g.xbits;
  g.height = 1 << g.ybits;
  const std::size_t texels = static_cast<std::size_t>(g.width) * g.height;
  if (g.width > 16384 || g.height > 16384)
  {
    error = "too many surfels for one list texture";
    return false;
  }
  std::vector<std::size_t> texel_of(n);  // input order -> linear texel (y * width + x)
  for (std::size_t rank = 0; rank < n; ++rank)
  {
    const auto [x, y] = MortonTexel(rank, g.xbits, g.ybits);
    texel_of[order[rank]] = static_cast<std::size_t>(y) * g.width + x;
  }

  std::vector<float> point(4 * texels, 0.0f), shape(4 * texels, 0.0f), cell(4 * texels, 0.0f),
    albedo(4 * texels, 0.0f), rows(4 * texels, 0.0f);
  std::vector<float> at(2 * n);
  for (std::size_t i = 0; i < n; ++i)
  {
    const std::size_t t = texel_of[i];
    for (int c = 0; c < 3; ++c)
    {
      point[4 * t + c] = static_cast<float>(local.positions[i][c]);
      shape[4 * t + c] = static_cast<float>(local.normals[i][c]);
      albedo[4 * t + c] = static_cast<float>(local.albedo.empty() ? 1.0 : local.albedo[i][c]);
    }
    point[4 * t + 3] = static_cast<float>(
      surface_thickness(local.roughness[i], local.curvature[i], local.radius));
    shape[4 * t + 3] = static_cast<float>(local.curvature[i]);
    cell[4 * t] = static_cast<float>(std::sqrt(area[i] / M_PI));
    cell[4 * t + 1] = static_cast<float>(area[i]);
    cell[4 * t + 2] = static_cast<float>(local.disc_radius(i));
    rows[4 * t] = static_cast<float>(weights.first[i]);
    rows[4 * t + 1] = static_cast<float>(weights.first[i + 1] - weights.first[i]);
    at[2 * i] = static_cast<float>(t % g.width);
    at[2 * i + 1] = static_cast<float>(t / g.width);
  }
  const std::size_t entry_count = std::max<std::size_t>(weights.source.size(), 1);
  const int entries_w = static_cast<int>(std::min<std::size_t>(entry_count, kEntriesWidth));
  const int entries_h = static_cast<int>((entry_count + entries_w - 1) / entries_w);
  if (entries_h > 16384)
  {
    error = "the near-field table has too many entries for one texture";
    return false;
  }
  std::vector<float> entries(4 * static_cast<std::size_t>(entries_w) * entries_h, 0.0f);
  for (std::size_t e = 0; e < weights.source.size(); ++e)
  {
    entries[4 * e] = static_cast<float>(texel_of[weights.source[e]]);
    for (int c = 0; c < 3; ++c)
    {
      entries[4 * e + 1 + c] = static_cast<float>(weights.weight[e][c]);
    }
  }
  g.point = Upload(window, g.width, g.height, point);
  g.shape = Upload(window, g.width, g.height, shape);
  g.cell = Upload(window, g.width, g.height, cell);
  g.albedo = Upload(window, g.width, g.height, albedo);
  g.rows = Upload(window, g.width, g.height, rows);
  g.entries = Upload(window, entries_w, entries_h, entries);
  g.B = float_texture_2d(window, g.width, g.height);
  g.texel->Upload(at, vtkOpenGLBufferObject::ArrayBuffer);

  std::vector<float> table(4 * kFresnelTableSize, 1.0f);
  for (int k = 0; k < kFresnelTableSize; ++k)
  {
    for (int c = 0; c < 3; ++c)
    {
      table[4 * k + c] = static_cast<float>(
        fresnel_transmittance(material.eta[c], double(k) / (kFresnelTableSize - 1)));
    }
  }
  g.fresnel = float_texture_2d(window, kFresnelTableSize, 1);
  g.fresnel->SetMinificationFilter(vtkTextureObject::Linear);
  g.fresnel->SetMagnificationFilter(vtkTextureObject::Linear);
  g.fresnel->Create2DFromRaw(kFresnelTableSize, 1, 4, VTK_FLOAT, table.data());
  g.atlas_lights = 0;
  return true;
}

bool SurfelPipeline::light(vtkOpenGLRenderWindow* window, const LightMapAtlas& maps, bool finish,
  SurfelPipelineReport& report, std::string& error)
{
  Gpu& g = *gpu_;
  Stopwatch clock;
  const int lights = static_cast<int>(maps.maps.size());
  g.allocate_sources(window, std::max(lights, 1));
  vtkOpenGLState* state = window->GetState();
  PointPassState pass_state(state);
  state->PushFramebufferBindings();
  g.fbo->SetContext(window);
  g.fbo->Bind();

  // Each light: the cells' irradiance and the finest level of its source pyramid, then the
  // coarser levels.
  const std::string irradiance_fs = shader_with_pieces(sss_surfel_irradiance_fs,
    std::string(sss_light_maps) + sss_surfel_list + sss_light_visibility + sss_fresnel_table);
  vtkShaderProgram* irradiance = ready_quad(g.irradiance_quad, window, irradiance_fs.c_str());
  vtkShaderProgram* reduce = irradiance ? ready_quad(g.reduce_quad, window, sss_pyramid_reduce_fs) : nullptr;
  if (!irradiance || !reduce)
  {
    error = "the irradiance or pyramid shader did not compile";
    state->PopFramebufferBindings();
    return false;
  }
  state->vtkglClearColor(0, 0, 0, 0);
  state->vtkglViewport(0, 0, g.source[0]->GetWidth(), g.source[0]->GetHeight());
  for (int k = 0; k < Gpu::kSources; ++k)  // kSources <= 8 draw buffers
  {
    g.fbo->AddColorAttachment(k, g.source[k]);
  }
  g.fbo->ActivateDrawBuffers(Gpu::kSources);
  state->vtkglClear(GL_COLOR_BUFFER_BIT);
  g.fbo->RemoveColorAttachments(Gpu::kSources);
  g.fbo->AddColorAttachment(0, g.E);
  for (int k = 0; k < Gpu::kCellSources; ++k)
  {
    g.fbo->AddColorAttachment(k + 1, g.source[k]);
  }
  g.fbo->ActivateDrawBuffers(Gpu::kCellSources + 1);
  state->vtkglClear(GL_COLOR_BUFFER_BIT);
  window->GetShaderCache()->ReadyShaderProgram(irradiance);
  maps.surfel->Activate();
  g.activate_list();
  g.fresnel->Activate();
  g.set_maps(irradiance, maps);
  g.set_list(irradiance);
  irradiance->SetUniformi("fresnelTable", g.fresnel->GetTextureUnit());
  irradiance->SetUniformi("fresnelTableSize", kFresnelTableSize);
  irradiance->SetUniformi("cellSamples", g.settings.cell_samples);
  irradiance->SetUniformi("cellRefinedSamples", g.settings.cell_refined_samples);
  for (int l = 0; l < lights; ++l)
  {
    irradiance->SetUniformi("light", l);
    const Rect& r = g.levels[l][0];
    state->vtkglViewport(r.x, r.y, r.width, r.height);
    g.irradiance_quad->Render();
  }
  g.fresnel->Deactivate();
  g.deactivate_list();
  maps.surfel->Deactivate();
  g.fbo->RemoveColorAttachments(Gpu::kCellSources + 1);

  for (int k = 0; k < Gpu::kSources; ++k)
  {
    g.fbo->AddColorAttachment(k, g.source[k]);
  }
  g.fbo->ActivateDrawBuffers(Gpu::kSources);
  window->GetShaderCache()->ReadyShaderProgram(reduce);
  for (auto& t : g.source)
  {
    t->Activate();
  }
  const char* names[Gpu::kSources] = { "mapPoint", "mapPower", "mapNormal", "mapCovariance0",
    "mapCovariance1", "mapCovariance2", "mapCovariance3", "mapCovariance4" };
  for (int k = 0; k < Gpu::kSources; ++k)
  {
    reduce->SetUniformi(names[k], g.source[k]->GetTextureUnit());
  }
  for (int l = 0; l < lights; ++l)
  {
    for (std::size_t L = 1; L < g.levels[l].size(); ++L)
    {
      const Rect& src = g.levels[l][L - 1];
      const Rect& dst = g.levels[l][L];
      const int origin[2] = { src.x, src.y }, size[2] = { src.width, src.height },
                target[2] = { dst.width, dst.height };
      reduce->SetUniform2i("sourceOrigin", origin);
      reduce->SetUniform2i("sourceSize", size);
      reduce->SetUniform2i("targetSize", target);
      Barrier();
      state->vtkglViewport(dst.x, dst.y, dst.width, dst.height);
      g.reduce_quad->Render();
    }
  }
  Barrier();
  report.lit_cells = 0;
  g.fbo->ActivateReadBuffer(1);
  for (int l = 0; l < lights; ++l)
  {
    const Rect& top = g.levels[l].back();
    float value[4] = { 0, 0, 0, 0 };
    glReadPixels(top.x, top.y, 1, 1, GL_RGBA, GL_FLOAT, value);
    report.lit_cells += static_cast<std::size_t>(value[3] + 0.5f);
  }
  g.fbo->RemoveColorAttachments(Gpu::kSources);
  if (finish)
  {
    glFinish();
  }
  report.seconds_cells = clock.lap();

  // B at every surfel: the near field's table, and the far field's walk.
  const std::string gather_fs = shader_with_pieces(sss_near_field_fs,
    std::string(sss_surfel_list) + "uniform int lightCount;\n" + sss_dipole + sss_near_field +
      sss_far_field);
  vtkShaderProgram* gather = ready_quad(g.gather_quad, window, gather_fs.c_str());
  if (!gather)
  {
    error = "the near- and far-field shader did not compile";
    for (auto& t : g.source)
    {
      t->Deactivate();
    }
    state->PopFramebufferBindings();
    return false;
  }
  g.fbo->AddColorAttachment(0, g.B);
  g.fbo->ActivateDrawBuffers(1);
  g.activate_list();
  g.rows->Activate();
  g.entries->Activate();
  g.E->Activate();
  g.set_list(gather);
  g.set_dipole(gather);
  gather->SetUniformi("lightCount", lights);
  gather->SetUniformi("nearRows", g.rows->GetTextureUnit());
  gather->SetUniformi("nearEntries", g.entries->GetTextureUnit());
  gather->SetUniformi("irradiance", g.E->GetTextureUnit());
  const char* source_names[Gpu::kSources] = { "sourcePoint", "sourcePower", "sourceNormal",
    "sourceCovariance0", "sourceCovariance1", "sourceCovariance2", "sourceCovariance3",
    "sourceCovariance4" };
  for (int k = 0; k < Gpu::kSources; ++k)
  {
    gather->SetUniformi(source_names[k], g.source[k]->GetTextureUnit());
  }
  std::vector<float> rects(4 * kMaxLights * kMaxLevels, 0.0f);
  for (int l = 0; l < lights; ++l)
  {
    for (std::size_t L = 0; L < g.levels[l].size() && L < std::size_t(kMaxLevels); ++L)
    {
      const Rect& r = g.levels[l][L];
      float* out = &rects[4 * (l * kMaxLevels + L)];
      out[0] = float(r.x);
      out[1] = float(r.y);
      out[2] = float(r.width);
      out[3] = float(r.height);
    }
  }
  gather->SetUniform4fv("sourceLevelRect", kMaxLights * kMaxLevels, rects.data());
  gather->SetUniformf("openingAngle", static_cast<float>(g.settings.opening_angle));
  gather->SetUniformf(
    "maxGroupDiffusionLengths", static_cast<float>(g.settings.max_group_diffusion_lengths));
  gather->SetUniformf("supportRadius", static_cast<float>(g.support));
  state->vtkglViewport(0, 0, g.width, g.height);
  vtkOpenGLState::ScopedglEnableDisable blend_saved(state, GL_BLEND);
  vtkOpenGLState::ScopedglBlendFuncSeparate blend_function_saved(state);
  state->vtkglDisable(GL_BLEND);
  gather->SetUniformi("addNearField", 1);
  gather->SetUniformi("addFarField", 0);
  g.gather_quad->Render();
  if (g.split.has_far && lights > 0)
  {
    // The far field in pieces: one quad per light and node of its pyramid's level kWalkRoot
    // (or its top), so that no fragment walks more than (4^(kWalkRoot + 1) - 1) / 3 nodes;
    // llvmpipe stops a shader invocation's loops after 65,535 iterations in all.
    gather->SetUniformi("addNearField", 0);
    gather->SetUniformi("addFarField", 1);
    state->vtkglEnable(GL_BLEND);
    state->vtkglBlendFunc(GL_ONE, GL_ONE);
    for (int l = 0; l < lights; ++l)
    {
      const int level = std::min(static_cast<int>(g.levels[l].size()) - 1, kWalkRoot);
      const Rect& roots = g.levels[l][level];
      gather->SetUniformi("walkLight", l);
      for (int y = 0; y < roots.height; ++y)
      {
        for (int x = 0; x < roots.width; ++x)
        {
          const int root[2] = { x, y };
          gather->SetUniform2i("walkRoot", root);
          gather->SetUniformi("walkRootLevel", level);
          g.gather_quad->Render();
        }
      }
    }
  }
  for (auto& t : g.source)
  {
    t->Deactivate();
  }
  g.E->Deactivate();
  g.entries->Deactivate();
  g.rows->Deactivate();
  g.deactivate_list();
  g.fbo->RemoveColorAttachments(1);
  state->PopFramebufferBindings();
  if (finish)
  {
    glFinish();
  }
  report.seconds_B = clock.lap();
  return true;
}

}
