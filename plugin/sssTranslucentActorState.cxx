#include "sssTranslucentActorState.h"

#include "sssGpuHelpers.h"
#include "sssPaperTaps.h"
#include "sss_dipole.h"
#include "sss_gather_paper.h"
#include "sss_illumination_fs.h"
#include "sss_light_map_surfel_fs.h"
#include "sss_light_maps.h"
#include "sss_paper_taps_fs.h"
#include "sss_surfel_gs.h"
#include "sss_surfel_resolve_fs.h"
#include "sss_surfel_resolve_vs.h"
#include "sss_surfel_vs.h"
#include "sss_virtual_points_fs.h"
#include "sss_virtual_points_vs.h"

#include "disc_raster.h"
#include "local_surfels.h"
#include "stopwatch.h"
#include "virtual_grid.h"

#include "vtkOpenGLBufferObject.h"
#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLQuadHelper.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkOpenGLState.h"
#include "vtkOpenGLVertexArrayObject.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"
#include "vtkTextureUnitManager.h"
#include "vtk_glew.h"

#include <Eigen/Dense>

#include <algorithm>
#include <cstdint>
#include <memory>
#include <numeric>
#include <sstream>

namespace sss
{

namespace
{
// The paper's grid: 64 points per axis (13-19 k kept on its scans).
constexpr int kPaperGridLevel = 6;
constexpr int kListWidth = 256;  // a squarish list keeps the rasteriser's tiles (threads) busy

std::string WithPieces(std::string source, const std::string& gather)
{
  vtkShaderProgram::Substitute(source, "//SSS::Gather::Dec", gather, true);
  vtkShaderProgram::Substitute(source, "//SSS::Dipole::Dec", sss_dipole, true);
  vtkShaderProgram::Substitute(source, "SSS_MAX_LIGHTS", std::to_string(kMaxLights), true);
  vtkShaderProgram::Substitute(source, "SSS_MAX_LEVELS", std::to_string(kMaxLevels), true);
  return source;
}

void Finish(bool finish)
{
  if (finish)
  {
    glFinish();
  }
}

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
    vao->Bind();
    if (needs(p))
    {
      vao->ReleaseGraphicsResources();
      vao->Bind();
      vao->AddAttributeArray(p, buffer, name, 0, 12, VTK_FLOAT, 3, false);
      if (buffer2)
      {
        vao->AddAttributeArray(p, buffer2, name2, 0, 8, VTK_FLOAT, 2, false);
      }
      program = p;
    }
  }
};

// 30-bit Morton code of a point quantised to 1024 cells per axis over the cube `lo`, `edge`.
std::uint32_t MortonCode(const Eigen::Vector3d& p, const Eigen::Vector3d& lo, double edge)
{
  std::uint32_t code = 0;
  for (int a = 0; a < 3; ++a)
  {
    const double t = edge > 0.0 ? (p[a] - lo[a]) / edge : 0.0;
    const std::uint32_t q = static_cast<std::uint32_t>(std::clamp(t * 1024.0, 0.0, 1023.0));
    for (int b = 0; b < 10; ++b)
    {
      code |= ((q >> b) & 1u) << (3 * b + a);
    }
  }
  return code;
}
}

// The paper's virtual points as a list texture: in Morton order of position, 16 to a 4 x 4
// texel block (itself in Morton order), blocks row by row.
struct ReceiverList
{
  vtkSmartPointer<vtkTextureObject> points;  // xyz: local mm, w: 1 where a receiver
  vtkSmartPointer<vtkTextureObject> B;       // the taps' result, same layout
  vtkNew<vtkOpenGLBufferObject> texel;       // per receiver, in input order: its texel
  int width = 0, height = 0;

  void upload(vtkOpenGLRenderWindow* window, const std::vector<Eigen::Vector3d>& positions)
  {
    const std::size_t n = positions.size();
    Eigen::Vector3d lo = Eigen::Vector3d::Zero(), hi = Eigen::Vector3d::Zero();
    if (n > 0)
    {
      lo = hi = positions[0];
    }
    for (const Eigen::Vector3d& p : positions)
    {
      lo = lo.cwiseMin(p);
      hi = hi.cwiseMax(p);
    }
    const double edge = (hi - lo).maxCoeff();
    std::vector<std::uint32_t> code(n);
    for (std::size_t i = 0; i < n; ++i)
    {
      code[i] = MortonCode(positions[i], lo, edge);
    }
    std::vector<std::size_t> order(n);
    std::iota(order.begin(), order.end(), 0);
    std::stable_sort(
      order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return code[a] < code[b]; });
    const int blocks_per_row = kListWidth / 4;
    const std::size_t blocks = (n + 15) / 16;
    width = kListWidth;
    height = 4 * static_cast<int>(std::max<std::size_t>(1, (blocks + blocks_per_row - 1) / blocks_per_row));
    std::vector<float> texels(4 * static_cast<std::size_t>(width) * height, 0.0f);
    std::vector<float> at(2 * n);
    for (std::size_t rank = 0; rank < n; ++rank)
    {
      const std::size_t block = rank / 16;
      const int j = static_cast<int>(rank % 16);
      const int x = static_cast<int>(block % blocks_per_row) * 4 + ((j & 1) | ((j >> 1) & 2));
      const int y = static_cast<int>(block / blocks_per_row) * 4 + (((j >> 1) & 1) | ((j >> 2) & 2));
      const std::size_t i = order[rank];
      float* t = &texels[4 * (static_cast<std::size_t>(y) * width + x)];
      for (int c = 0; c < 3; ++c)
      {
        t[c] = static_cast<float>(positions[i][c]);
      }
      t[3] = 1.0f;
      at[2 * i] = static_cast<float>(x);
      at[2 * i + 1] = static_cast<float>(y);
    }
    points = float_texture_2d(window, width, height);
    points->Create2DFromRaw(width, height, 4, VTK_FLOAT, texels.data());
    B = float_texture_2d(window, width, height);
    texel->Upload(at, vtkOpenGLBufferObject::ArrayBuffer);
  }

  void release(vtkWindow* window)
  {
    texel->ReleaseGraphicsResources();
    for (auto* t : { &points, &B })
    {
      if (*t)
      {
        (*t)->ReleaseGraphicsResources(window);
        *t = nullptr;
      }
    }
  }
};

struct TranslucentActorState::Gpu
{
  LocalSurfels local;
  std::unique_ptr<Dipole> dipole;

  vtkNew<vtkOpenGLBufferObject> points, normals, colours, curvatures, disc_radii;
  vtkNew<vtkOpenGLBufferObject> no_texel;  // the resolve's texel attribute for the paper: unused
  ProgramVAO illumination_vao, resolve_vao, grid_vao;

  // Step 1: one light map per light, side by side in one atlas: the paper's point, power and
  // normal per texel, or the surfel pipeline's seen surfel.
  std::vector<OrthoView> maps;
  std::vector<Eigen::Vector3d> light_directions;
  std::vector<Rgb> light_irradiance;
  std::vector<int> map_x;  // where each light's map starts in the atlas
  int atlas_width = 0, atlas_height = 0;
  vtkSmartPointer<vtkTextureObject> atlas_point, atlas_power, atlas_normal, atlas_surfel, atlas_depth;
  vtkNew<vtkOpenGLFramebufferObject> map_fbo, grid_fbo, list_fbo, taps_fbo;

  // Step 2: the surfel pipeline, or the paper's virtual points.
  SurfelPipeline pipeline;
  std::unique_ptr<VirtualGrid> grid;
  vtkNew<vtkOpenGLBufferObject> grid_index;
  std::vector<std::pair<int, int>> slice_range;  // first, count per k
  vtkSmartPointer<vtkTextureObject> grid_radiance;
  ReceiverList grid_receivers;
  std::unique_ptr<vtkOpenGLQuadHelper> taps_quad;

  // Step 3's input: B per surfel in input order.
  vtkSmartPointer<vtkTextureObject> list;
  int list_height = 1;

  LightMapAtlas atlas() const
  {
    LightMapAtlas a;
    a.surfel = atlas_surfel;
    for (std::size_t l = 0; l < maps.size(); ++l)
    {
      LightMapAtlas::Map m;
      m.x = map_x[l];
      m.y = 0;
      m.width = maps[l].width;
      m.height = maps[l].height;
      m.texel = maps[l].pixel;
      m.u = maps[l].u;
      m.v = maps[l].v;
      m.corner = maps[l].corner;
      m.towards_light = light_directions[l];
      m.irradiance = light_irradiance[l];
      a.maps.push_back(m);
    }
    return a;
  }

  void release(vtkWindow* window)
  {
    points->ReleaseGraphicsResources();
    normals->ReleaseGraphicsResources();
    colours->ReleaseGraphicsResources();
    curvatures->ReleaseGraphicsResources();
    disc_radii->ReleaseGraphicsResources();
    no_texel->ReleaseGraphicsResources();
    grid_index->ReleaseGraphicsResources();
    for (ProgramVAO* v : { &illumination_vao, &resolve_vao, &grid_vao })
    {
      v->vao->ReleaseGraphicsResources();
      v->program = nullptr;
    }
    for (auto* t : { &atlas_point, &atlas_power, &atlas_normal, &atlas_surfel, &atlas_depth,
           &grid_radiance, &list })
    {
      if (*t)
      {
        (*t)->ReleaseGraphicsResources(window);
        *t = nullptr;
      }
    }
    pipeline.release(window);
    grid_receivers.release(window);
    if (taps_quad)
    {
      taps_quad->ReleaseGraphicsResources(window);
      taps_quad.reset();
    }
    for (vtkOpenGLFramebufferObject* f : { map_fbo.Get(), grid_fbo.Get(), list_fbo.Get(), taps_fbo.Get() })
    {
      f->ReleaseGraphicsResources(window);
    }
    atlas_width = atlas_height = 0;
  }
};

TranslucentActorState::TranslucentActorState()
  : gpu_(new Gpu)
{
}

TranslucentActorState::~TranslucentActorState()
{
  delete gpu_;
}

vtkTextureObject* TranslucentActorState::surfel_radiance() const
{
  return gpu_->list;
}

void TranslucentActorState::release(vtkWindow* window)
{
  gpu_->release(window);
  valid_ = false;
  geometry_time_ = 0;
}

bool TranslucentActorState::update(vtkOpenGLRenderWindow* window, const PreparedSurfels& surfels,
  vtkMTimeType surfels_time, const Material& material, bool albedo_from_colour,
  const std::vector<GpuLight>& lights, const GpuSettings& settings, bool finish,
  StepReport& report, std::string& error)
{
  std::vector<double> key;
  for (int c = 0; c < 3; ++c)
  {
    key.insert(key.end(), { material.sigma_a[c], material.sigma_s_prime[c], material.eta[c] });
  }
  key.push_back(material.mm_per_unit);
  const bool geometry_changed = !valid_ || surfels_time != geometry_time_ ||
    key != material_key_ || !(settings == geometry_settings_) ||
    albedo_from_colour != geometry_albedo_;
  const bool light_changed = geometry_changed || !(lights == lights_);
  report.surfel_count = surfels.cloud.size();
  if (!light_changed)
  {
    return true;
  }
  material_ = material;
  valid_ = false;
  Stopwatch clock;
  if (geometry_changed)
  {
    if (!upload_geometry(window, surfels, albedo_from_colour, settings, report, error))
    {
      return false;
    }
    material_key_ = key;
    geometry_time_ = surfels_time;
    geometry_settings_ = settings;
    geometry_albedo_ = albedo_from_colour;
    report.bake = true;
    report.seconds_bake = clock.lap();
  }
  if (!run_illumination(window, lights, settings, albedo_from_colour, report, error))
  {
    return false;
  }
  Finish(finish);
  report.illumination = true;
  report.seconds_illumination = clock.lap();
  if (settings.strategy == KernelStrategy::NearFar)
  {
    SurfelPipelineReport step;
    if (!gpu_->pipeline.light(window, gpu_->atlas(), finish, step, error))
    {
      return false;
    }
    report.lit_cells = step.lit_cells;
    report.seconds_cells = step.seconds_cells;
    report.seconds_B = step.seconds_B;
  }
  else if (!run_paper_taps(window, error))
  {
    return false;
  }
  if (!resolve(window, settings, error))
  {
    return false;
  }
  Finish(finish);
  report.surfels = true;
  report.seconds_surfels = clock.lap();
  lights_ = lights;
  settings_ = settings;
  valid_ = true;
  return true;
}

bool TranslucentActorState::upload_geometry(vtkOpenGLRenderWindow* window,
  const PreparedSurfels& surfels, bool albedo_from_colour, const GpuSettings& settings,
  StepReport& report, std::string& error)
{
  Gpu& g = *gpu_;
  g.local = LocalSurfels::from(surfels.cloud, material_.mm_per_unit);
  g.dipole = std::make_unique<Dipole>(material_);
  const std::size_t n = g.local.size();
  // Each disc's curvature lifts the light's texels onto its local surface (clamped at one
  // over the disc radius, as core/light_map.cpp does).
  // Each disc's radius in the light's view, the one that closes the surface (mm).
  std::vector<float> points(3 * n), normals(3 * n), curvatures(n), disc_radii(n);
  const double lift_limit = 1.0 / g.local.radius;
  for (std::size_t i = 0; i < n; ++i)
  {
    for (int c = 0; c < 3; ++c)
    {
      points[3 * i + c] = static_cast<float>(g.local.positions[i][c]);
      normals[3 * i + c] = static_cast<float>(g.local.normals[i][c]);
    }
    curvatures[i] = static_cast<float>(std::clamp(g.local.curvature[i], -lift_limit, lift_limit));
    disc_radii[i] = static_cast<float>(g.local.disc_radius(i));
  }
  g.points->Upload(points, vtkOpenGLBufferObject::ArrayBuffer);
  g.normals->Upload(normals, vtkOpenGLBufferObject::ArrayBuffer);
  g.colours->Upload(surfels.rgba, vtkOpenGLBufferObject::ArrayBuffer);
  g.curvatures->Upload(curvatures, vtkOpenGLBufferObject::ArrayBuffer);
  g.disc_radii->Upload(disc_radii, vtkOpenGLBufferObject::ArrayBuffer);
  g.illumination_vao.program = nullptr;
  g.resolve_vao.program = nullptr;

  list_width_ = kListWidth;
  g.list_height = static_cast<int>((n + kListWidth - 1) / kListWidth);
  g.list = float_texture_2d(window, list_width_, std::max(1, g.list_height));

  g.grid.reset();
  g.grid_radiance = nullptr;
  if (settings.strategy == KernelStrategy::NearFar)
  {
    // Colours as albedo, as the illumination map's fragments take them.
    g.local.albedo.clear();
    if (albedo_from_colour)
    {
      g.local.albedo.resize(n);
      for (std::size_t i = 0; i < n; ++i)
      {
        for (int c = 0; c < 3; ++c)
        {
          g.local.albedo[i][c] = surfels.rgba[4 * i + c] / 255.0;
        }
      }
    }
    SurfelPipelineReport step;
    if (!g.pipeline.bake(window, g.local, material_, settings.pipeline, step, error))
    {
      return false;
    }
    report.near_reach_mm = step.near_reach_mm;
    report.far_from_mm = step.far_from_mm;
    report.near_entries = step.near_entries;
    return true;
  }

  g.no_texel->Upload(std::vector<float>(2 * n, 0.0f), vtkOpenGLBufferObject::ArrayBuffer);
  VirtualGridSettings grid_settings;
  grid_settings.level = settings.grid_level == 0 ? kPaperGridLevel : settings.grid_level;
  try
  {
    g.grid = std::make_unique<VirtualGrid>(VirtualGrid::build(g.local, *g.dipole, grid_settings));
  }
  catch (const std::exception& e)
  {
    error = e.what();
    return false;
  }
  const VirtualGrid& grid = *g.grid;
  std::vector<std::size_t> order(grid.points().size());
  std::iota(order.begin(), order.end(), 0);
  std::vector<Eigen::Array3d> ijk(order.size());
  for (std::size_t i = 0; i < order.size(); ++i)
  {
    ijk[i] = ((grid.points()[i] - grid.origin()) / grid.spacing()).array().round();
  }
  std::stable_sort(order.begin(), order.end(),
    [&](std::size_t a, std::size_t b) { return ijk[a].z() < ijk[b].z(); });
  std::vector<float> indices;
  indices.reserve(3 * order.size());
  std::vector<Eigen::Vector3d> receivers;
  receivers.reserve(order.size());
  g.slice_range.assign(grid.dims()[2], { 0, 0 });
  for (std::size_t r = 0; r < order.size(); ++r)
  {
    const Eigen::Array3d& c = ijk[order[r]];
    const int k = static_cast<int>(c.z());
    if (g.slice_range[k].second == 0)
    {
      g.slice_range[k].first = static_cast<int>(r);
    }
    ++g.slice_range[k].second;
    indices.insert(indices.end(),
      { static_cast<float>(c.x()), static_cast<float>(c.y()), static_cast<float>(c.z()) });
    receivers.push_back(grid.points()[order[r]]);  // the paper evaluates at the grid points
  }
  g.grid_receivers.upload(window, receivers);
  g.grid_index->Upload(indices, vtkOpenGLBufferObject::ArrayBuffer);
  g.grid_vao.program = nullptr;
  auto tex = vtkSmartPointer<vtkTextureObject>::New();
  tex->SetContext(window);
  tex->SetInternalFormat(GL_RGBA32F);
  tex->SetFormat(GL_RGBA);
  tex->SetDataType(GL_FLOAT);
  tex->SetMinificationFilter(vtkTextureObject::Linear);
  tex->SetMagnificationFilter(vtkTextureObject::Linear);
  tex->SetWrapS(vtkTextureObject::ClampToEdge);
  tex->SetWrapT(vtkTextureObject::ClampToEdge);
  tex->SetWrapR(vtkTextureObject::ClampToEdge);
  if (!tex->Allocate3D(grid.dims()[0], grid.dims()[1], grid.dims()[2], 4, VTK_FLOAT))
  {
    error = "cannot allocate the virtual points' 3-D texture";
    return false;
  }
  g.grid_radiance = tex;
  report.virtual_point_count = grid.points().size();
  report.grid_level = grid.level();
  report.grid_spacing_mm = grid.spacing();
  return true;
}

bool TranslucentActorState::run_illumination(vtkOpenGLRenderWindow* window,
  const std::vector<GpuLight>& lights, const GpuSettings& settings, bool albedo_from_colour,
  StepReport& report, std::string& error)
{
  Gpu& g = *gpu_;
  if (lights.size() > static_cast<std::size_t>(kMaxLights))
  {
    error = "at most " + std::to_string(kMaxLights) + " directional lights are supported";
    return false;
  }
  const bool paper = settings.strategy == KernelStrategy::Paper;
  // The paper's map is 512 texels a side; the surfel pipeline's texels are TexelPerRadius of
  // a disc radius, at most MaxMapSize a side.
  const double texel = paper ? 1e-9 : settings.texel_per_radius * g.local.radius;
  const int max_size = paper ? kPaperMapSize : settings.max_map_size;
  g.maps.clear();
  g.map_x.clear();
  g.light_directions.clear();
  g.light_irradiance.clear();
  int atlas_w = 0, atlas_h = 1;
  for (const GpuLight& light : lights)
  {
    const OrthoView map = OrthoView::fit_pixel(g.local.positions, g.local.max_disc_radius(),
      light.towards_light, Eigen::Vector3d::UnitZ(), texel, max_size);
    g.map_x.push_back(atlas_w);
    atlas_w += map.width;
    atlas_h = std::max(atlas_h, map.height);
    g.maps.push_back(map);
    g.light_directions.push_back(light.towards_light);
    g.light_irradiance.push_back(light.irradiance);
  }
  atlas_w = std::max(atlas_w, 1);
  int max_texture = 0;
  glGetIntegerv(GL_MAX_TEXTURE_SIZE, &max_texture);
  if (atlas_w > max_texture || atlas_h > max_texture)
  {
    std::ostringstream msg;
    msg << "the light maps need a " << atlas_w << " x " << atlas_h
        << " texture, over this GL's limit of " << max_texture << "; lower MaxMapSize";
    error = msg.str();
    return false;
  }
  // A moving light changes the maps' shapes every frame, and reallocating the textures each
  // time costs more than unused texels: the atlas is kept while it is large enough and no
  // more than four times the area needed.
  const bool fits = atlas_w <= g.atlas_width && atlas_h <= g.atlas_height;
  const bool oversized = 4.0 * atlas_w * atlas_h < double(g.atlas_width) * g.atlas_height;
  const bool other_kind = paper ? !g.atlas_point : !g.atlas_surfel;
  if (!fits || oversized || other_kind)
  {
    if (!oversized)
    {
      atlas_w = std::max(atlas_w, g.atlas_width);
      atlas_h = std::max(atlas_h, g.atlas_height);
    }
    for (auto* t : { &g.atlas_point, &g.atlas_power, &g.atlas_normal, &g.atlas_surfel })
    {
      if (*t)
      {
        (*t)->ReleaseGraphicsResources(window);
        *t = nullptr;
      }
    }
    if (paper)
    {
      g.atlas_point = float_texture_2d(window, atlas_w, atlas_h);
      g.atlas_power = float_texture_2d(window, atlas_w, atlas_h);
      g.atlas_normal = float_texture_2d(window, atlas_w, atlas_h);
    }
    else
    {
      g.atlas_surfel = float_texture_2d(window, atlas_w, atlas_h, 2);
    }
    g.atlas_depth = vtkSmartPointer<vtkTextureObject>::New();
    g.atlas_depth->SetContext(window);
    g.atlas_depth->AllocateDepth(atlas_w, atlas_h, vtkTextureObject::Float32);
    g.atlas_width = atlas_w;
    g.atlas_height = atlas_h;
  }
  report.map_width = g.maps.empty() ? 0 : g.maps[0].width;
  report.map_height = g.maps.empty() ? 0 : g.maps[0].height;
  report.texel_mm = g.maps.empty() ? 0.0 : g.maps[0].pixel;

  vtkOpenGLState* state = window->GetState();
  vtkOpenGLState::ScopedglViewport viewport(state);
  vtkOpenGLState::ScopedglEnableDisable depth_test(state, GL_DEPTH_TEST);
  vtkOpenGLState::ScopedglEnableDisable blending(state, GL_BLEND);
  vtkOpenGLState::ScopedglEnableDisable scissor(state, GL_SCISSOR_TEST);
  state->PushFramebufferBindings();
  g.map_fbo->SetContext(window);
  g.map_fbo->Bind();
  const int targets = paper ? 3 : 1;
  if (paper)
  {
    g.map_fbo->AddColorAttachment(0, g.atlas_point);
    g.map_fbo->AddColorAttachment(1, g.atlas_power);
    g.map_fbo->AddColorAttachment(2, g.atlas_normal);
  }
  else
  {
    g.map_fbo->AddColorAttachment(0, g.atlas_surfel);
  }
  g.map_fbo->AddDepthAttachment(g.atlas_depth);
  g.map_fbo->ActivateDrawBuffers(targets);
  state->vtkglDisable(GL_SCISSOR_TEST);
  state->vtkglDisable(GL_BLEND);
  state->vtkglViewport(0, 0, g.atlas_width, g.atlas_height);
  const float none = paper ? 0.0f : -1.0f;  // the paper's normal 0, or no surfel
  state->vtkglClearColor(none, none, none, none);
  state->vtkglClearDepth(1.0);
  state->vtkglDepthMask(GL_TRUE);
  state->vtkglColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  state->vtkglClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);

  // The paper's texels lifted by each disc's curvature; the pipeline's carry the surfel's list
  // texel in the colour.
  std::string vs = sss_surfel_vs;
  vtkShaderProgram::Substitute(vs, "//SSS::Radiance::Dec", "", true);
  vtkShaderProgram::Substitute(vs, "//SSS::Radiance::Impl", "", true);
  vtkShaderProgram::Substitute(
    vs, "//SSS::Shape::Dec", paper ? "in float curvatureMC;" : "in vec2 listTexelMC;", true);
  vtkShaderProgram::Substitute(vs, "//SSS::Shape::Impl",
    paper ? "curvature_gs = curvatureMC;" : "colour_gs = vec4(listTexelMC, 0.0, 0.0);", true);
  const std::string fs = paper ? WithPieces(sss_illumination_fs, "") : sss_light_map_surfel_fs;
  vtkShaderProgram* program =
    window->GetShaderCache()->ReadyShaderProgram(vs.c_str(), fs.c_str(), sss_surfel_gs);
  if (!program)
  {
    error = "the illumination-map shaders did not compile";
    state->PopFramebufferBindings();
    return false;
  }
  ProgramVAO& pv = g.illumination_vao;
  pv.vao->Bind();
  if (pv.needs(program))
  {
    pv.vao->ReleaseGraphicsResources();
    pv.vao->Bind();
    pv.vao->AddAttributeArray(program, g.points, "positionMC", 0, 12, VTK_FLOAT, 3, false);
    pv.vao->AddAttributeArray(program, g.normals, "normalMC", 0, 12, VTK_FLOAT, 3, false);
    pv.vao->AddAttributeArray(program, g.disc_radii, "radiusMC", 0, 4, VTK_FLOAT, 1, false);
    if (paper)
    {
      pv.vao->AddAttributeArray(program, g.colours, "colourMC", 0, 4, VTK_UNSIGNED_CHAR, 4, true);
      pv.vao->AddAttributeArray(program, g.curvatures, "curvatureMC", 0, 4, VTK_FLOAT, 1, false);
    }
    else
    {
      pv.vao->AddAttributeArray(
        program, g.pipeline.list_texel(), "listTexelMC", 0, 8, VTK_FLOAT, 2, false);
    }
    pv.program = program;
  }
  float eta[3];
  for (int c = 0; c < 3; ++c)
  {
    eta[c] = static_cast<float>(material_.eta[c]);
  }
  program->SetUniform3f("eta", eta);
  state->vtkglEnable(GL_DEPTH_TEST);
  state->vtkglDepthFunc(GL_LESS);
  const double reach = 0.5 * g.local.bounds.extent().norm() + g.local.max_disc_radius() + 1.0;
  for (std::size_t l = 0; l < lights.size(); ++l)
  {
    const OrthoView& map = g.maps[l];
    Eigen::Matrix3d rows;
    rows.row(0) = map.u.transpose();
    rows.row(1) = map.v.transpose();
    rows.row(2) = map.w.transpose();
    Eigen::Matrix4f model_to_view = Eigen::Matrix4f::Identity();
    model_to_view.block<3, 3>(0, 0) = rows.cast<float>();
    const Eigen::Matrix3f normal_to_view = rows.cast<float>();
    const Eigen::Matrix3f view_to_local = rows.transpose().cast<float>();
    Eigen::Matrix4d ortho = Eigen::Matrix4d::Zero();
    ortho(0, 0) = 2.0 / (map.width * map.pixel);
    ortho(0, 3) = -2.0 * map.corner.x() / (map.width * map.pixel) - 1.0;
    ortho(1, 1) = 2.0 / (map.height * map.pixel);
    ortho(1, 3) = -2.0 * map.corner.y() / (map.height * map.pixel) - 1.0;
    ortho(2, 2) = -1.0 / reach;
    ortho(3, 3) = 1.0;
    const Eigen::Matrix4f view_to_clip = ortho.cast<float>();
    program->SetUniformMatrix4x4("modelToView", model_to_view.data());
    program->SetUniformMatrix3x3("normalToView", const_cast<float*>(normal_to_view.data()));
    program->SetUniformMatrix4x4("viewToClip", const_cast<float*>(view_to_clip.data()));
    program->SetUniformMatrix3x3("viewToLocal", const_cast<float*>(view_to_local.data()));
    program->SetUniformi("perPointRadius", 1);
    program->SetUniformf("modelToViewScale", 1.0f);
    program->SetUniformi("orthographic", 1);
    const float towards[3] = { static_cast<float>(lights[l].towards_light.x()),
      static_cast<float>(lights[l].towards_light.y()),
      static_cast<float>(lights[l].towards_light.z()) };
    program->SetUniform3f("towardsLight", towards);
    float power[3];
    for (int c = 0; c < 3; ++c)
    {
      power[c] = static_cast<float>(lights[l].irradiance[c] * map.pixel * map.pixel);
    }
    program->SetUniform3f("irradianceArea", power);
    program->SetUniformi("albedoFromColour", albedo_from_colour ? 1 : 0);
    const float albedo_as_is[3] = { 1.0f, 0.0f, 1.0f };  // ambient only: colour = colourMC
    program->SetUniform3f("ambientDiffuse", albedo_as_is);
    state->vtkglViewport(g.map_x[l], 0, map.width, map.height);
    glDrawArrays(GL_POINTS, 0, static_cast<GLsizei>(g.local.size()));
  }
  pv.vao->Release();
  g.map_fbo->RemoveColorAttachments(targets);
  g.map_fbo->RemoveDepthAttachment();
  state->PopFramebufferBindings();
  return true;
}

bool TranslucentActorState::run_paper_taps(vtkOpenGLRenderWindow* window, std::string& error)
{
  Gpu& g = *gpu_;
  const VirtualGrid& grid = *g.grid;
  const std::string gather =
    std::string(sss_light_maps) + "\n" + sss_dipole + "\n" + sss_gather_paper;
  const std::string fs = WithPieces(sss_paper_taps_fs, gather);
  vtkShaderProgram* taps = ready_quad(g.taps_quad, window, fs.c_str());
  if (!taps)
  {
    error = "the paper's tap shader did not compile";
    return false;
  }
  vtkOpenGLState* state = window->GetState();
  PointPassState point_pass(state);
  {
    const LightMapAtlas atlas = g.atlas();
    g.atlas_point->Activate();
    g.atlas_power->Activate();
    g.atlas_normal->Activate();
    g.grid_receivers.points->Activate();
    float zr[3], zv[3], str[3], factor[3];
    for (int c = 0; c < 3; ++c)
    {
      const DipoleChannel& ch = g.dipole->channel[c];
      zr[c] = static_cast<float>(ch.z_r);
      zv[c] = static_cast<float>(ch.z_v);
      str[c] = static_cast<float>(ch.s_tr);
      factor[c] = static_cast<float>(ch.alpha_prime / (4.0 * M_PI));
    }
    taps->SetUniform3f("zR", zr);
    taps->SetUniform3f("zV", zv);
    taps->SetUniform3f("sTr", str);
    taps->SetUniform3f("rdFactor", factor);
    std::vector<float> rects(4 * kMaxLights * kMaxLevels, 0.0f), texel(kMaxLights, 0.0f),
      axis_u(3 * kMaxLights, 0.0f), axis_v(3 * kMaxLights, 0.0f), corner(2 * kMaxLights, 0.0f);
    for (std::size_t l = 0; l < atlas.maps.size(); ++l)
    {
      const LightMapAtlas::Map& m = atlas.maps[l];
      float* r = &rects[4 * l * kMaxLevels];
      r[0] = float(m.x);
      r[1] = float(m.y);
      r[2] = float(m.width);
      r[3] = float(m.height);
      texel[l] = static_cast<float>(m.texel);
      for (int c = 0; c < 3; ++c)
      {
        axis_u[3 * l + c] = static_cast<float>(m.u[c]);
        axis_v[3 * l + c] = static_cast<float>(m.v[c]);
      }
      corner[2 * l] = static_cast<float>(m.corner.x());
      corner[2 * l + 1] = static_cast<float>(m.corner.y());
    }
    taps->SetUniformi("lightCount", static_cast<int>(atlas.maps.size()));
    taps->SetUniform4fv("levelRect", kMaxLights * kMaxLevels, rects.data());
    taps->SetUniform1fv("texelSize", kMaxLights, texel.data());
    taps->SetUniform3fv("mapAxisU", kMaxLights, axis_u.data());
    taps->SetUniform3fv("mapAxisV", kMaxLights, axis_v.data());
    taps->SetUniform2fv("mapCorner", kMaxLights, corner.data());
    const auto tap_table = paper_taps();
    taps->SetUniform3fv("paperTaps", kPaperTapCount, &tap_table[0][0]);
    taps->SetUniformi("mapPoint", g.atlas_point->GetTextureUnit());
    taps->SetUniformi("mapPower", g.atlas_power->GetTextureUnit());
    taps->SetUniformi("mapNormal", g.atlas_normal->GetTextureUnit());
    taps->SetUniformi("receivers", g.grid_receivers.points->GetTextureUnit());
    state->PushFramebufferBindings();
    g.taps_fbo->SetContext(window);
    g.taps_fbo->Bind();
    g.taps_fbo->AddColorAttachment(0, g.grid_receivers.B);
    g.taps_fbo->ActivateDrawBuffers(1);
    state->vtkglViewport(0, 0, g.grid_receivers.width, g.grid_receivers.height);
    g.taps_quad->Render();
    g.taps_fbo->RemoveColorAttachments(1);
    state->PopFramebufferBindings();
    g.grid_receivers.points->Deactivate();
    g.atlas_point->Deactivate();
    g.atlas_power->Deactivate();
    g.atlas_normal->Deactivate();
  }

  // Into the 3-D texture, one layer at a time.
  vtkShaderProgram* program = window->GetShaderCache()->ReadyShaderProgram(
    sss_virtual_points_vs, sss_virtual_points_fs, "");
  if (!program)
  {
    error = "the virtual-point shaders did not compile";
    return false;
  }
  ProgramVAO& pv = g.grid_vao;
  pv.bind(program, g.grid_index, "gridIndex", g.grid_receivers.texel, "gatheredTexel");
  g.grid_receivers.B->Activate();
  program->SetUniformi("gathered", g.grid_receivers.B->GetTextureUnit());
  const float slice[2] = { float(grid.dims()[0]), float(grid.dims()[1]) };
  program->SetUniform2f("sliceSize", slice);
  state->PushFramebufferBindings();
  g.grid_fbo->SetContext(window);
  g.grid_fbo->Bind();
  state->vtkglViewport(0, 0, grid.dims()[0], grid.dims()[1]);
  state->vtkglClearColor(0, 0, 0, 0);
  GLenum draw_buffer = GL_COLOR_ATTACHMENT0;
  state->vtkglDrawBuffers(1, &draw_buffer);
  for (int k = 0; k < grid.dims()[2]; ++k)
  {
    glFramebufferTextureLayer(
      GL_DRAW_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, g.grid_radiance->GetHandle(), 0, k);
    state->vtkglClear(GL_COLOR_BUFFER_BIT);
    if (g.slice_range[k].second > 0)
    {
      glDrawArrays(GL_POINTS, g.slice_range[k].first, g.slice_range[k].second);
    }
  }
  glFramebufferTextureLayer(GL_DRAW_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, 0, 0, 0);
  state->PopFramebufferBindings();
  pv.vao->Release();
  g.grid_receivers.B->Deactivate();
  return true;
}

bool TranslucentActorState::resolve(
  vtkOpenGLRenderWindow* window, const GpuSettings& settings, std::string& error)
{
  Gpu& g = *gpu_;
  const bool use_grid = settings.strategy == KernelStrategy::Paper;
  vtkShaderProgram* program = window->GetShaderCache()->ReadyShaderProgram(
    sss_surfel_resolve_vs, sss_surfel_resolve_fs, "");
  if (!program)
  {
    error = "the per-surfel shaders did not compile";
    return false;
  }
  vtkOpenGLState* state = window->GetState();
  PointPassState point_pass(state);
  ProgramVAO& pv = g.resolve_vao;
  // The list texel each surfel's B lies at (unused with the grid).
  vtkOpenGLBufferObject* texel = use_grid ? g.no_texel.Get() : g.pipeline.list_texel();
  pv.bind(program, g.points, "pointLocal", texel, "gatheredTexel");
  vtkTextureObject* gathered = use_grid ? g.grid_receivers.B.Get() : g.pipeline.radiance();
  gathered->Activate();
  program->SetUniformi("gathered", gathered->GetTextureUnit());
  program->SetUniformi("useGrid", use_grid ? 1 : 0);
  // A sampler3D must not share a texture unit with the sampler2D, even unused.
  vtkTextureUnitManager* units = window->GetTextureUnitManager();
  const int spare_unit = use_grid ? -1 : units->Allocate();
  program->SetUniformi("gridRadiance", spare_unit);
  if (use_grid)
  {
    const VirtualGrid& grid = *g.grid;
    g.grid_radiance->Activate();
    program->SetUniformi("gridRadiance", g.grid_radiance->GetTextureUnit());
    const float origin[3] = { static_cast<float>(grid.origin().x()),
      static_cast<float>(grid.origin().y()), static_cast<float>(grid.origin().z()) };
    program->SetUniform3f("gridOrigin", origin);
    program->SetUniformf("gridSpacing", static_cast<float>(grid.spacing()));
    const float dims[3] = { float(grid.dims()[0]), float(grid.dims()[1]), float(grid.dims()[2]) };
    program->SetUniform3f("gridDims", dims);
  }
  program->SetUniformi("listWidth", list_width_);
  const float list_size[2] = { float(list_width_), float(g.list_height) };
  program->SetUniform2f("listSize", list_size);

  state->PushFramebufferBindings();
  g.list_fbo->SetContext(window);
  g.list_fbo->Bind();
  g.list_fbo->AddColorAttachment(0, g.list);
  g.list_fbo->ActivateDrawBuffers(1);
  state->vtkglViewport(0, 0, list_width_, g.list_height);
  state->vtkglClearColor(0, 0, 0, 0);
  state->vtkglClear(GL_COLOR_BUFFER_BIT);
  glDrawArrays(GL_POINTS, 0, static_cast<GLsizei>(g.local.size()));
  g.list_fbo->RemoveColorAttachments(1);
  state->PopFramebufferBindings();
  pv.vao->Release();
  if (use_grid)
  {
    g.grid_radiance->Deactivate();
  }
  else
  {
    units->Free(spare_unit);
  }
  gathered->Deactivate();
  return true;
}

bool TranslucentActorState::show_radiance(vtkOpenGLRenderWindow* window,
  const PreparedSurfels& surfels, const Material& material, const std::vector<Rgb>& B,
  std::string& error)
{
  if (B.size() != surfels.cloud.size())
  {
    error = "the given radiance has " + std::to_string(B.size()) + " values for " +
      std::to_string(surfels.cloud.size()) + " surfels";
    return false;
  }
  Gpu& g = *gpu_;
  material_ = material;
  g.local = LocalSurfels::from(surfels.cloud, material.mm_per_unit, false);
  list_width_ = kListWidth;
  g.list_height = static_cast<int>((B.size() + kListWidth - 1) / kListWidth);
  std::vector<float> texels(4 * static_cast<std::size_t>(list_width_) * std::max(1, g.list_height), 0.0f);
  for (std::size_t i = 0; i < B.size(); ++i)
  {
    for (int c = 0; c < 3; ++c)
    {
      texels[4 * i + c] = static_cast<float>(B[i][c]);
    }
  }
  g.list = float_texture_2d(window, list_width_, std::max(1, g.list_height));
  g.list->Create2DFromRaw(list_width_, std::max(1, g.list_height), 4, VTK_FLOAT, texels.data());
  valid_ = true;
  geometry_time_ = 0;  // the next update() runs every step
  material_key_.clear();
  return true;
}

bool TranslucentActorState::read_surfel_radiance(vtkOpenGLRenderWindow* window, std::vector<Rgb>& B)
{
  Gpu& g = *gpu_;
  if (!valid_ || !g.list)
  {
    return false;
  }
  std::vector<float> texels(4 * static_cast<std::size_t>(list_width_) * g.list_height);
  vtkOpenGLState* state = window->GetState();
  state->PushFramebufferBindings();
  g.list_fbo->SetContext(window);
  g.list_fbo->Bind();
  g.list_fbo->AddColorAttachment(0, g.list);
  g.list_fbo->ActivateReadBuffer(0);
  glReadPixels(0, 0, list_width_, g.list_height, GL_RGBA, GL_FLOAT, texels.data());
  g.list_fbo->RemoveColorAttachments(1);
  state->PopFramebufferBindings();
  B.resize(g.local.size());
  for (std::size_t i = 0; i < B.size(); ++i)
  {
    B[i] = { texels[4 * i], texels[4 * i + 1], texels[4 * i + 2] };
  }
  return true;
}

}
