#include "sssTranslucentActorState.h"

#include "sssGpuHelpers.h"
#include "sssPaperTaps.h"
#include "sss_dipole.h"
#include "sss_gather_paper.h"
#include "sss_gather_receivers_fs.h"
#include "sss_gather_tree.h"
#include "sss_illumination_fs.h"
#include "sss_kernel_window.h"
#include "sss_light_maps.h"
#include "sss_near_field.h"
#include "sss_near_field_fs.h"
#include "sss_pyramid_reduce_fs.h"
#include "sss_surfel_gs.h"
#include "sss_surfel_resolve_fs.h"
#include "sss_surfel_resolve_vs.h"
#include "sss_surfel_vs.h"
#include "sss_virtual_points_fs.h"
#include "sss_virtual_points_vs.h"

#include "disc_raster.h"
#include "fresnel.h"
#include "local_surface.h"
#include "local_surfels.h"
#include "near_far_split.h"
#include "near_field_quadrature.h"
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
// Sources beyond this distance carry less than this fraction of the kernel's integral.
constexpr double kSupportFraction = 1e-7;
// An automatic grid level keeps at most this many virtual points (the paper kept 13-19 k):
// the virtual points' walk is then about as costly as the paper's taps.
constexpr std::size_t kVirtualPointBudget = 16384;
// The paper's grid: 64 points per axis (13-19 k kept on its scans), its automatic level.
constexpr int kPaperGridLevel = 6;
constexpr int kListWidth = 256;  // a squarish list keeps the rasteriser's tiles (threads) busy
constexpr int kFresnelTableSize = 256;

struct LevelRect
{
  int x, y, width, height;
};

std::string WithPieces(std::string source, const std::string& gather)
{
  vtkShaderProgram::Substitute(source, "//SSS::Gather::Dec", gather, true);
  vtkShaderProgram::Substitute(source, "//SSS::Dipole::Dec", sss_dipole, true);
  vtkShaderProgram::Substitute(source, "SSS_MAX_LIGHTS", std::to_string(kMaxLights), true);
  vtkShaderProgram::Substitute(source, "SSS_MAX_LEVELS", std::to_string(kMaxLevels), true);
  vtkShaderProgram::Substitute(source, "SSS_MAX_RINGS", std::to_string(kMaxRings), true);
  return source;
}

std::string WithoutRadianceHooks(std::string source)
{
  vtkShaderProgram::Substitute(source, "//SSS::Radiance::Dec", "", true);
  vtkShaderProgram::Substitute(source, "//SSS::Radiance::Impl", "", true);
  return source;
}

void Finish(bool finish)
{
  if (finish)
  {
    glFinish();
  }
}

void TextureBarrier()
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

// The receivers of one walk (surfels or kept virtual points) as a list texture: in Morton
// order of position, 16 to a 4 x 4 texel block (itself in Morton order), blocks row by row.
// llvmpipe shades a 4 x 4 block in SIMD lanes and a divergent loop costs its slowest lane,
// so neighbouring receivers side by side walk nearly the same tree in the same time.
struct ReceiverList
{
  vtkSmartPointer<vtkTextureObject> points;  // xyz: local mm, w: > 0 where a receiver
  vtkSmartPointer<vtkTextureObject> shape;   // optional: per receiver, same layout
  vtkSmartPointer<vtkTextureObject> B;       // the walk's result, same layout
  vtkNew<vtkOpenGLBufferObject> texel;       // per receiver, in input order: its texel
  int width = 0, height = 0;

  // `w` (one per receiver, > 0; empty: 1) goes into the points' w, `shapes` (empty: none) into
  // a second texture of the same layout.
  void upload(vtkOpenGLRenderWindow* window, const std::vector<Eigen::Vector3d>& positions,
    const std::vector<float>& w = {}, const std::vector<Eigen::Vector4f>& shapes = {})
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
    std::vector<float> shape_texels(shapes.empty() ? 0 : texels.size(), 0.0f);
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
      t[3] = w.empty() ? 1.0f : w[i];
      if (!shapes.empty())
      {
        std::copy(shapes[i].data(), shapes[i].data() + 4,
          &shape_texels[4 * (static_cast<std::size_t>(y) * width + x)]);
      }
      at[2 * i] = static_cast<float>(x);
      at[2 * i + 1] = static_cast<float>(y);
    }
    points = float_texture_2d(window, width, height);
    points->Create2DFromRaw(width, height, 4, VTK_FLOAT, texels.data());
    shape = nullptr;
    if (!shapes.empty())
    {
      shape = float_texture_2d(window, width, height);
      shape->Create2DFromRaw(width, height, 4, VTK_FLOAT, shape_texels.data());
    }
    B = float_texture_2d(window, width, height);
    texel->Upload(at, vtkOpenGLBufferObject::ArrayBuffer);
  }

  void release(vtkWindow* window)
  {
    texel->ReleaseGraphicsResources();
    for (auto* t : { &points, &shape, &B })
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
  double support_radius = 0;

  vtkNew<vtkOpenGLBufferObject> points, normals, colours, curvatures;
  ProgramVAO illumination_vao, resolve_vao, grid_vao;

  // The near field (NearFar): where it hands over to the far field, its quadrature, the
  // exact Fresnel transmittance as a table, and the far field at each surfel.
  NearFarSplit split;
  std::unique_ptr<NearFieldQuadrature> quadrature;
  vtkSmartPointer<vtkTextureObject> fresnel_table, surfel_far;
  std::unique_ptr<vtkOpenGLQuadHelper> near_quad;
  std::vector<Eigen::Vector3d> light_directions;

  std::vector<OrthoView> maps;
  std::vector<std::vector<LevelRect>> levels;
  int atlas_width = 0, atlas_height = 0;
  vtkSmartPointer<vtkTextureObject> atlas_point, atlas_power, atlas_normal, atlas_cov0,
    atlas_cov1, atlas_depth;
  vtkNew<vtkOpenGLFramebufferObject> map_fbo, grid_fbo, list_fbo;
  std::unique_ptr<vtkOpenGLQuadHelper> reduce;

  std::unique_ptr<VirtualGrid> grid;
  vtkNew<vtkOpenGLBufferObject> grid_index;
  std::vector<std::pair<int, int>> slice_range;  // first, count per k
  vtkSmartPointer<vtkTextureObject> grid_radiance;

  vtkSmartPointer<vtkTextureObject> list;
  int list_height = 1;

  ReceiverList surfel_receivers, grid_receivers;
  std::unique_ptr<vtkOpenGLQuadHelper> gather_quad;
  std::string gather_quad_source;
  vtkNew<vtkOpenGLFramebufferObject> gather_fbo;

  void activate_maps()
  {
    for (vtkTextureObject* t : { atlas_point.Get(), atlas_power.Get(), atlas_normal.Get(),
           atlas_cov0.Get(), atlas_cov1.Get() })
    {
      t->Activate();
    }
  }
  void deactivate_maps()
  {
    for (vtkTextureObject* t : { atlas_point.Get(), atlas_power.Get(), atlas_normal.Get(),
           atlas_cov0.Get(), atlas_cov1.Get() })
    {
      t->Deactivate();
    }
  }
  // The maps' samplers, named as in the shaders.
  void set_map_samplers(vtkShaderProgram* program)
  {
    program->SetUniformi("mapPoint", atlas_point->GetTextureUnit());
    program->SetUniformi("mapPower", atlas_power->GetTextureUnit());
    program->SetUniformi("mapNormal", atlas_normal->GetTextureUnit());
    program->SetUniformi("mapCovariance0", atlas_cov0->GetTextureUnit());
    program->SetUniformi("mapCovariance1", atlas_cov1->GetTextureUnit());
  }

  void release(vtkWindow* window)
  {
    points->ReleaseGraphicsResources();
    normals->ReleaseGraphicsResources();
    colours->ReleaseGraphicsResources();
    curvatures->ReleaseGraphicsResources();
    grid_index->ReleaseGraphicsResources();
    for (ProgramVAO* v : { &illumination_vao, &resolve_vao, &grid_vao })
    {
      v->vao->ReleaseGraphicsResources();
      v->program = nullptr;
    }
    for (auto* t : { &atlas_point, &atlas_power, &atlas_normal, &atlas_cov0, &atlas_cov1,
           &atlas_depth, &grid_radiance,
           &list, &fresnel_table, &surfel_far })
    {
      if (*t)
      {
        (*t)->ReleaseGraphicsResources(window);
        *t = nullptr;
      }
    }
    surfel_receivers.release(window);
    grid_receivers.release(window);
    for (auto* quad : { &gather_quad, &near_quad })
    {
      if (*quad)
      {
        (*quad)->ReleaseGraphicsResources(window);
        quad->reset();
      }
    }
    gather_fbo->ReleaseGraphicsResources(window);
    map_fbo->ReleaseGraphicsResources(window);
    grid_fbo->ReleaseGraphicsResources(window);
    list_fbo->ReleaseGraphicsResources(window);
    if (reduce)
    {
      reduce->ReleaseGraphicsResources(window);
      reduce.reset();
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
  const bool material_changed = key != material_key_;
  const bool geometry_changed = !valid_ || surfels_time != geometry_time_ || material_changed ||
    !(settings == geometry_settings_);
  const bool light_changed = geometry_changed || !(lights == lights_) ||
    !(settings == settings_) || albedo_from_colour != albedo_from_colour_;
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
    if (!upload_geometry(window, surfels, settings, error))
    {
      return false;
    }
    material_key_ = key;
    geometry_time_ = surfels_time;
    geometry_settings_ = settings;
  }
  if (!run_illumination(window, lights, settings, albedo_from_colour, report, error))
  {
    return false;
  }
  Finish(finish);
  report.illumination = true;
  report.seconds_illumination = clock.lap();
  if (gpu_->grid)
  {
    if (!run_virtual_points(window, settings, error))
    {
      return false;
    }
    Finish(finish);
    report.virtual_points = true;
    report.seconds_virtual_points = clock.lap();
    report.virtual_point_count = gpu_->grid->points().size();
    report.grid_level = gpu_->grid->level();
    report.grid_spacing_mm = gpu_->grid->spacing();
  }
  if (!run_surfels(window, settings, error))
  {
    return false;
  }
  Finish(finish);
  report.surfels = true;
  report.seconds_surfels = clock.lap();
  if (gpu_->quadrature)
  {
    report.near_reach_mm = gpu_->split.reach;
    report.far_from_mm = gpu_->split.has_far ? gpu_->split.far.r0 : 0.0;
    report.near_nodes = gpu_->quadrature->node_count();
  }
  lights_ = lights;
  settings_ = settings;
  albedo_from_colour_ = albedo_from_colour;
  valid_ = true;
  return true;
}

bool TranslucentActorState::upload_geometry(vtkOpenGLRenderWindow* window,
  const PreparedSurfels& surfels, const GpuSettings& settings, std::string& error)
{
  Gpu& g = *gpu_;
  g.local = LocalSurfels::from(surfels.cloud, material_.mm_per_unit);
  g.dipole = std::make_unique<Dipole>(material_);
  g.support_radius = g.dipole->max_support_radius(kSupportFraction);
  const std::size_t n = g.local.size();
  std::vector<float> points(3 * n), normals(3 * n);
  for (std::size_t i = 0; i < n; ++i)
  {
    for (int c = 0; c < 3; ++c)
    {
      points[3 * i + c] = static_cast<float>(g.local.positions[i][c]);
      normals[3 * i + c] = static_cast<float>(g.local.normals[i][c]);
    }
  }
  // Each disc's curvature lifts the light's texels onto its local surface (clamped at one
  // over the disc radius, as core/illumination.cpp does).
  std::vector<float> curvatures(n);
  const double lift_limit = 1.0 / g.local.radius;
  for (std::size_t i = 0; i < n; ++i)
  {
    curvatures[i] = static_cast<float>(std::clamp(g.local.curvature[i], -lift_limit, lift_limit));
  }
  g.points->Upload(points, vtkOpenGLBufferObject::ArrayBuffer);
  g.normals->Upload(normals, vtkOpenGLBufferObject::ArrayBuffer);
  g.colours->Upload(surfels.rgba, vtkOpenGLBufferObject::ArrayBuffer);
  g.curvatures->Upload(curvatures, vtkOpenGLBufferObject::ArrayBuffer);
  g.illumination_vao.program = nullptr;
  g.resolve_vao.program = nullptr;

  list_width_ = kListWidth;
  g.list_height = static_cast<int>((n + kListWidth - 1) / kListWidth);
  g.list = float_texture_2d(window, list_width_, std::max(1, g.list_height));
  g.quadrature.reset();
  g.surfel_far = nullptr;
  g.fresnel_table = nullptr;
  if (settings.strategy == KernelStrategy::NearFar)
  {
    // The largest texel any light's map can have (its diagonal over the map size) sets how
    // close the far field's point sources may come.
    const double extent = g.local.bounds.extent().norm() + 2.0 * g.local.radius;
    const double texel =
      std::max(settings.texel_per_z_r * g.dipole->min_z_r(), extent / settings.max_map_size);
    g.split = NearFarSplit::choose(
      *g.dipole, std::max(NearFarSplit::minimum_r0(g.local.radius), 2.0 * texel), kSupportFraction);
    QuadratureSettings quadrature;
    quadrature.rings = settings.near_rings;
    quadrature.min_nodes = std::min(4, settings.near_nodes);
    quadrature.max_nodes = settings.near_nodes;
    try
    {
      g.quadrature =
        std::make_unique<NearFieldQuadrature>(*g.dipole, g.split.near, g.split.reach, quadrature);
    }
    catch (const std::exception& e)
    {
      error = e.what();
      return false;
    }
    if (static_cast<int>(g.quadrature->rings().size()) > kMaxRings)
    {
      error = "at most " + std::to_string(kMaxRings) + " near-field rings are supported";
      return false;
    }
    std::vector<float> thickness(n);
    std::vector<Eigen::Vector4f> shapes(n);
    for (std::size_t i = 0; i < n; ++i)
    {
      thickness[i] = static_cast<float>(
        surface_thickness(g.local.roughness[i], g.local.curvature[i], g.local.radius));
      shapes[i] << g.local.normals[i].cast<float>(), static_cast<float>(g.local.curvature[i]);
    }
    g.surfel_receivers.upload(window, g.local.positions, thickness, shapes);
    if (g.split.has_far)
    {
      g.surfel_far = float_texture_2d(window, g.surfel_receivers.width, g.surfel_receivers.height);
    }
    std::vector<float> table(4 * kFresnelTableSize, 1.0f);
    for (int k = 0; k < kFresnelTableSize; ++k)
    {
      for (int c = 0; c < 3; ++c)
      {
        table[4 * k + c] = static_cast<float>(
          fresnel_transmittance(material_.eta[c], double(k) / (kFresnelTableSize - 1)));
      }
    }
    g.fresnel_table = float_texture_2d(window, kFresnelTableSize, 1);
    g.fresnel_table->SetMinificationFilter(vtkTextureObject::Linear);
    g.fresnel_table->SetMagnificationFilter(vtkTextureObject::Linear);
    g.fresnel_table->Create2DFromRaw(kFresnelTableSize, 1, 4, VTK_FLOAT, table.data());
  }
  else
  {
    g.surfel_receivers.upload(window, g.local.positions);
  }

  g.grid.reset();
  g.grid_radiance = nullptr;
  if (settings.strategy != KernelStrategy::Surfel && settings.strategy != KernelStrategy::NearFar)
  {
    VirtualGridSettings grid_settings;
    grid_settings.level = settings.grid_level == 0 && settings.strategy == KernelStrategy::Paper
      ? kPaperGridLevel
      : settings.grid_level;
    grid_settings.point_budget = kVirtualPointBudget;
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
    auto index_of = [&](std::size_t i) {
      return ((grid.points()[i] - grid.origin()) / grid.spacing()).array().round().eval();
    };
    std::vector<Eigen::Array3d> ijk(order.size());
    for (std::size_t i = 0; i < order.size(); ++i)
    {
      ijk[i] = index_of(i);
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
      // The paper evaluates B at the grid points themselves; the other strategies at the
      // points' anchors on the surface.
      receivers.push_back(settings.strategy == KernelStrategy::Paper
          ? grid.points()[order[r]]
          : grid.anchors()[order[r]]);
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
  }
  return true;
}

std::string TranslucentActorState::gather_source(const GpuSettings& settings) const
{
  return std::string(sss_light_maps) + "\n" + sss_kernel_window + "\n" + sss_dipole + "\n" +
    (settings.strategy == KernelStrategy::Paper ? sss_gather_paper : sss_gather_tree);
}

void TranslucentActorState::set_gather_uniforms(vtkShaderProgram* program,
  const GpuSettings& settings, int part, double r0, double r1)
{
  Gpu& g = *gpu_;
  float zr[3], zv[3], str[3], factor[3], eta[3];
  for (int c = 0; c < 3; ++c)
  {
    const DipoleChannel& ch = g.dipole->channel[c];
    zr[c] = static_cast<float>(ch.z_r);
    zv[c] = static_cast<float>(ch.z_v);
    str[c] = static_cast<float>(ch.s_tr);
    factor[c] = static_cast<float>(ch.alpha_prime / (4.0 * M_PI));
    eta[c] = static_cast<float>(material_.eta[c]);
  }
  program->SetUniform3f("zR", zr);
  program->SetUniform3f("zV", zv);
  program->SetUniform3f("sTr", str);
  program->SetUniform3f("rdFactor", factor);
  program->SetUniform3f("eta", eta);
  program->SetUniformi("windowPart", part);
  program->SetUniformf("windowR0", static_cast<float>(r0));
  program->SetUniformf("windowR1", static_cast<float>(r1));

  const int lights = static_cast<int>(g.maps.size());
  std::vector<float> rects(4 * kMaxLights * kMaxLevels, 0.0f), texel(kMaxLights, 0.0f),
    axis_u(3 * kMaxLights, 0.0f), axis_v(3 * kMaxLights, 0.0f), corner(2 * kMaxLights, 0.0f);
  std::vector<int> level_count(kMaxLights, 0);
  for (int l = 0; l < lights; ++l)
  {
    level_count[l] = static_cast<int>(g.levels[l].size());
    for (std::size_t L = 0; L < g.levels[l].size(); ++L)
    {
      const LevelRect& r = g.levels[l][L];
      float* out = &rects[4 * (l * kMaxLevels + L)];
      out[0] = float(r.x);
      out[1] = float(r.y);
      out[2] = float(r.width);
      out[3] = float(r.height);
    }
    const OrthoView& map = g.maps[l];
    texel[l] = static_cast<float>(map.pixel);
    for (int c = 0; c < 3; ++c)
    {
      axis_u[3 * l + c] = static_cast<float>(map.u[c]);
      axis_v[3 * l + c] = static_cast<float>(map.v[c]);
    }
    corner[2 * l] = static_cast<float>(map.corner.x());
    corner[2 * l + 1] = static_cast<float>(map.corner.y());
  }
  std::vector<float> directions(3 * kMaxLights, 0.0f);
  for (std::size_t l = 0; l < g.light_directions.size() && l < std::size_t(kMaxLights); ++l)
  {
    for (int c = 0; c < 3; ++c)
    {
      directions[3 * l + c] = static_cast<float>(g.light_directions[l][c]);
    }
  }
  program->SetUniform3fv("lightDirection", kMaxLights, directions.data());
  program->SetUniformi("lightCount", lights);
  program->SetUniform1iv("levelCount", kMaxLights, level_count.data());
  program->SetUniform4fv("levelRect", kMaxLights * kMaxLevels, rects.data());
  program->SetUniform1fv("texelSize", kMaxLights, texel.data());
  program->SetUniform3fv("mapAxisU", kMaxLights, axis_u.data());
  program->SetUniform3fv("mapAxisV", kMaxLights, axis_v.data());
  program->SetUniform2fv("mapCorner", kMaxLights, corner.data());
  program->SetUniformf("openingAngle", static_cast<float>(settings.opening_angle));
  program->SetUniformf(
    "maxGroupDiffusionLengths", static_cast<float>(settings.max_group_diffusion_lengths));
  program->SetUniformf("supportRadius", static_cast<float>(g.support_radius));
  if (settings.strategy == KernelStrategy::Paper)
  {
    const auto taps = paper_taps();
    program->SetUniform3fv("paperTaps", kPaperTapCount, &taps[0][0]);
  }
  if (g.atlas_point->GetTextureUnit() >= 0)
  {
    g.set_map_samplers(program);
  }
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
  const double texel = paper ? 1e-9 : settings.texel_per_z_r * g.dipole->min_z_r();
  const int max_size = paper ? kPaperMapSize : settings.max_map_size;
  g.maps.clear();
  g.levels.clear();
  g.light_directions.clear();
  for (const GpuLight& light : lights)
  {
    g.light_directions.push_back(light.towards_light);
  }
  int atlas_w = 1, atlas_h = 0;
  for (const GpuLight& light : lights)
  {
    const OrthoView map = OrthoView::fit_pixel(g.local.positions, g.local.radius,
      light.towards_light, Eigen::Vector3d::UnitZ(), texel, max_size);
    std::vector<LevelRect> rects{ { 0, atlas_h, map.width, map.height } };
    int w = map.width, h = map.height, y = atlas_h;
    while (w > 1 || h > 1)
    {
      w = (w + 1) / 2;
      h = (h + 1) / 2;
      rects.push_back({ map.width, y, w, h });
      y += h;
    }
    if (rects.size() > static_cast<std::size_t>(kMaxLevels))
    {
      error = "illumination map too large for the pyramid";
      return false;
    }
    atlas_w = std::max(atlas_w, map.width + (map.width > 1 ? rects[1].width : 0));
    atlas_h = std::max(atlas_h + map.height, y);  // the coarser levels may stack higher
    g.maps.push_back(map);
    g.levels.push_back(rects);
  }
  atlas_h = std::max(atlas_h, 1);
  int max_texture = 0;
  glGetIntegerv(GL_MAX_TEXTURE_SIZE, &max_texture);
  if (atlas_w > max_texture || atlas_h > max_texture)
  {
    std::ostringstream msg;
    msg << "the illumination maps need a " << atlas_w << " x " << atlas_h
        << " texture, over this GL's limit of " << max_texture << "; lower MaxMapSize";
    error = msg.str();
    return false;
  }
  // A moving light changes the maps' shapes every frame, and reallocating six textures each
  // time costs more than unused texels: the atlas is kept while it is large enough and no
  // more than four times the area needed (a smaller map size setting frees it).
  const bool fits = atlas_w <= g.atlas_width && atlas_h <= g.atlas_height;
  const bool oversized = 4.0 * atlas_w * atlas_h < double(g.atlas_width) * g.atlas_height;
  if (!fits || oversized || !g.atlas_point)
  {
    if (!oversized)
    {
      atlas_w = std::max(atlas_w, g.atlas_width);
      atlas_h = std::max(atlas_h, g.atlas_height);
    }
    g.atlas_point = float_texture_2d(window, atlas_w, atlas_h);
    g.atlas_power = float_texture_2d(window, atlas_w, atlas_h);
    g.atlas_normal = float_texture_2d(window, atlas_w, atlas_h);
    g.atlas_cov0 = float_texture_2d(window, atlas_w, atlas_h);
    g.atlas_cov1 = float_texture_2d(window, atlas_w, atlas_h);
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
  g.map_fbo->AddColorAttachment(0, g.atlas_point);
  g.map_fbo->AddColorAttachment(1, g.atlas_power);
  g.map_fbo->AddColorAttachment(2, g.atlas_normal);
  g.map_fbo->AddColorAttachment(3, g.atlas_cov0);
  g.map_fbo->AddColorAttachment(4, g.atlas_cov1);
  g.map_fbo->AddDepthAttachment(g.atlas_depth);
  g.map_fbo->ActivateDrawBuffers(5);
  state->vtkglDisable(GL_SCISSOR_TEST);
  state->vtkglDisable(GL_BLEND);
  state->vtkglViewport(0, 0, atlas_w, atlas_h);
  state->vtkglClearColor(0, 0, 0, 0);
  state->vtkglClearDepth(1.0);
  state->vtkglDepthMask(GL_TRUE);
  state->vtkglColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  state->vtkglClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);

  std::string vs = WithoutRadianceHooks(sss_surfel_vs);
  vtkShaderProgram::Substitute(vs, "//SSS::Shape::Dec", "in float curvatureMC;", true);
  vtkShaderProgram::Substitute(vs, "//SSS::Shape::Impl", "curvature_gs = curvatureMC;", true);
  const std::string fs = WithPieces(sss_illumination_fs, "");
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
    pv.vao->AddAttributeArray(program, g.colours, "colourMC", 0, 4, VTK_UNSIGNED_CHAR, 4, true);
    pv.vao->AddAttributeArray(program, g.curvatures, "curvatureMC", 0, 4, VTK_FLOAT, 1, false);
    pv.program = program;
  }
  set_gather_uniforms(program, settings, 0, 0, 0);
  state->vtkglEnable(GL_DEPTH_TEST);
  state->vtkglDepthFunc(GL_LESS);
  const double reach = 0.5 * g.local.bounds.extent().norm() + g.local.radius + 1.0;
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
    program->SetUniformf("radiusVC", static_cast<float>(g.local.radius));
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
    const float axis_u[3] = { float(map.u.x()), float(map.u.y()), float(map.u.z()) };
    const float axis_v[3] = { float(map.v.x()), float(map.v.y()), float(map.v.z()) };
    program->SetUniform3f("mapAxisU", axis_u);
    program->SetUniform3f("mapAxisV", axis_v);
    program->SetUniformf("texelEdge", static_cast<float>(map.pixel));
    const LevelRect& r = g.levels[l][0];
    state->vtkglViewport(r.x, r.y, r.width, r.height);
    glDrawArrays(GL_POINTS, 0, static_cast<GLsizei>(g.local.size()));
  }
  pv.vao->Release();

  // The pyramid: each level from the one below, in the same atlas (disjoint texels, with a
  // texture barrier between levels).
  state->vtkglDisable(GL_DEPTH_TEST);
  vtkShaderProgram* reduce = ready_quad(g.reduce, window, sss_pyramid_reduce_fs);
  if (!reduce)
  {
    error = "the pyramid shader did not compile";
    state->PopFramebufferBindings();
    return false;
  }
  g.activate_maps();
  g.set_map_samplers(reduce);
  for (std::size_t l = 0; l < lights.size(); ++l)
  {
    const float towards[3] = { static_cast<float>(lights[l].towards_light.x()),
      static_cast<float>(lights[l].towards_light.y()),
      static_cast<float>(lights[l].towards_light.z()) };
    reduce->SetUniform3f("towardsLight", towards);
    for (std::size_t L = 1; L < g.levels[l].size(); ++L)
    {
      const LevelRect& src = g.levels[l][L - 1];
      const LevelRect& dst = g.levels[l][L];
      const int source_origin[2] = { src.x, src.y }, source_size[2] = { src.width, src.height },
                target_size[2] = { dst.width, dst.height };
      reduce->SetUniform2i("sourceOrigin", source_origin);
      reduce->SetUniform2i("sourceSize", source_size);
      reduce->SetUniform2i("targetSize", target_size);
      TextureBarrier();
      state->vtkglViewport(dst.x, dst.y, dst.width, dst.height);
      g.reduce->Render();
    }
  }
  TextureBarrier();
  g.deactivate_maps();

  // Lit texels: the count the top of each pyramid holds.
  report.lit_samples = 0;
  g.map_fbo->ActivateReadBuffer(1);
  for (std::size_t l = 0; l < lights.size(); ++l)
  {
    const LevelRect& top = g.levels[l].back();
    float texel_value[4] = { 0, 0, 0, 0 };
    glReadPixels(top.x, top.y, 1, 1, GL_RGBA, GL_FLOAT, texel_value);
    report.lit_samples += static_cast<std::size_t>(texel_value[3] + 0.5f);
  }
  g.map_fbo->RemoveColorAttachments(5);
  g.map_fbo->RemoveDepthAttachment();
  state->PopFramebufferBindings();
  return true;
}

bool TranslucentActorState::run_virtual_points(
  vtkOpenGLRenderWindow* window, const GpuSettings& settings, std::string& error)
{
  Gpu& g = *gpu_;
  const VirtualGrid& grid = *g.grid;
  const bool split = settings.strategy == KernelStrategy::GridNear;
  const double r0 = settings.near_field_cells * grid.spacing();
  if (!gather_at_receivers(window, settings, g.grid_receivers, split ? 2 : 0, r0, 2.0 * r0, error))
  {
    return false;
  }
  vtkShaderProgram* program = window->GetShaderCache()->ReadyShaderProgram(
    sss_virtual_points_vs, sss_virtual_points_fs, "");
  if (!program)
  {
    error = "the virtual-point shaders did not compile";
    return false;
  }
  vtkOpenGLState* state = window->GetState();
  PointPassState point_pass(state);

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
    // One layer of the 3-D texture at a time.
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

bool TranslucentActorState::run_surfels(
  vtkOpenGLRenderWindow* window, const GpuSettings& settings, std::string& error)
{
  Gpu& g = *gpu_;
  const bool use_grid = static_cast<bool>(g.grid);
  const bool near_far = settings.strategy == KernelStrategy::NearFar;
  const bool near_only = settings.strategy == KernelStrategy::GridNear;
  const bool gather_here = !use_grid || near_only;
  const bool add_far = near_far && g.split.has_far;
  const double r0 = use_grid ? settings.near_field_cells * g.grid->spacing() : 0.0;
  if (near_far)
  {
    if (!run_near_field(window, settings, error) ||
      (add_far &&
        !gather_at_receivers(window, settings, g.surfel_receivers, 2, g.split.far.r0,
          g.split.far.r1, error, g.surfel_far)))
    {
      return false;
    }
  }
  else if (gather_here &&
    !gather_at_receivers(window, settings, g.surfel_receivers, near_only ? 1 : 0, r0, 2.0 * r0, error))
  {
    return false;
  }
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
  pv.bind(program, g.points, "pointLocal", g.surfel_receivers.texel, "gatheredTexel");
  g.surfel_receivers.B->Activate();
  program->SetUniformi("gathered", g.surfel_receivers.B->GetTextureUnit());
  program->SetUniformi("gatherAtSurfel", gather_here ? 1 : 0);
  // The far field at each surfel (NearFar), or a unit the sampler may use unread.
  vtkTextureObject* far = add_far ? g.surfel_far.Get() : g.surfel_receivers.B.Get();
  if (add_far)
  {
    far->Activate();
  }
  program->SetUniformi("gatheredFar", far->GetTextureUnit());
  program->SetUniformi("addFar", add_far ? 1 : 0);
  program->SetUniformi("useGrid", use_grid ? 1 : 0);
  // A sampler3D must not share a texture unit with the maps' sampler2Ds, even unused.
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
  if (add_far)
  {
    far->Deactivate();
  }
  g.surfel_receivers.B->Deactivate();
  return true;
}

bool TranslucentActorState::gather_at_receivers(vtkOpenGLRenderWindow* window,
  const GpuSettings& settings, ReceiverList& receivers, int part, double r0, double r1,
  std::string& error, vtkTextureObject* output)
{
  Gpu& g = *gpu_;
  const std::string fs = WithPieces(sss_gather_receivers_fs, gather_source(settings));
  if (g.gather_quad && g.gather_quad_source != fs)
  {
    g.gather_quad->ReleaseGraphicsResources(window);
    g.gather_quad.reset();
  }
  g.gather_quad_source = fs;
  vtkShaderProgram* program = ready_quad(g.gather_quad, window, fs.c_str());
  if (!program)
  {
    error = "the receivers' gather shader did not compile";
    return false;
  }
  vtkOpenGLState* state = window->GetState();
  PointPassState point_pass(state);
  g.activate_maps();
  receivers.points->Activate();
  set_gather_uniforms(program, settings, part, r0, r1);
  program->SetUniformi("receivers", receivers.points->GetTextureUnit());
  state->PushFramebufferBindings();
  g.gather_fbo->SetContext(window);
  g.gather_fbo->Bind();
  g.gather_fbo->AddColorAttachment(0, output ? output : receivers.B.Get());
  g.gather_fbo->ActivateDrawBuffers(1);
  state->vtkglViewport(0, 0, receivers.width, receivers.height);
  g.gather_quad->Render();
  g.gather_fbo->RemoveColorAttachments(1);
  state->PopFramebufferBindings();
  receivers.points->Deactivate();
  g.deactivate_maps();
  return true;
}

void TranslucentActorState::set_near_field_uniforms(vtkShaderProgram* program)
{
  Gpu& g = *gpu_;
  const auto& rings = g.quadrature->rings();
  const double kappa_limit = 1.0 / g.quadrature->reach();
  std::vector<float> radius(kMaxRings, 0.0f), weight(3 * kMaxRings, 0.0f),
    bend1(3 * kMaxRings, 0.0f), bend2(3 * kMaxRings, 0.0f);
  std::vector<int> nodes(kMaxRings, 0);
  for (std::size_t k = 0; k < rings.size(); ++k)
  {
    radius[k] = static_cast<float>(rings[k].radius);
    nodes[k] = rings[k].nodes;
    // The bend of the ring's weight with the surface as 1 + b1 kappa + b2 kappa^2 through its
    // exact values at kappa = +-kappa_limit.
    const Rgb up = NearFieldQuadrature::bend(*g.dipole, rings[k].radius, kappa_limit);
    const Rgb down = NearFieldQuadrature::bend(*g.dipole, rings[k].radius, -kappa_limit);
    for (int c = 0; c < 3; ++c)
    {
      weight[3 * k + c] = static_cast<float>(rings[k].node_weight[c]);
      bend1[3 * k + c] = static_cast<float>((up[c] - down[c]) / (2.0 * kappa_limit));
      bend2[3 * k + c] =
        static_cast<float>((up[c] + down[c] - 2.0) / (2.0 * kappa_limit * kappa_limit));
    }
  }
  program->SetUniformi("ringCount", static_cast<int>(rings.size()));
  program->SetUniform1fv("ringRadius", kMaxRings, radius.data());
  program->SetUniform1iv("ringNodes", kMaxRings, nodes.data());
  program->SetUniform3fv("ringWeight", kMaxRings, weight.data());
  program->SetUniform3fv("ringBend1", kMaxRings, bend1.data());
  program->SetUniform3fv("ringBend2", kMaxRings, bend2.data());
  program->SetUniformf("kappaLimit", static_cast<float>(kappa_limit));
  program->SetUniformi("fresnelTable", g.fresnel_table->GetTextureUnit());
  program->SetUniformi("fresnelTableSize", kFresnelTableSize);
}

bool TranslucentActorState::run_near_field(
  vtkOpenGLRenderWindow* window, const GpuSettings& settings, std::string& error)
{
  Gpu& g = *gpu_;
  const std::string pieces = std::string(sss_light_maps) + "\n" + sss_kernel_window + "\n" +
    sss_dipole + "\n" + sss_near_field;
  const std::string fs = WithPieces(sss_near_field_fs, pieces);
  vtkShaderProgram* program = ready_quad(g.near_quad, window, fs.c_str());
  if (!program)
  {
    error = "the near-field shader did not compile";
    return false;
  }
  vtkOpenGLState* state = window->GetState();
  PointPassState point_pass(state);
  ReceiverList& receivers = g.surfel_receivers;
  g.activate_maps();
  receivers.points->Activate();
  receivers.shape->Activate();
  g.fresnel_table->Activate();
  set_gather_uniforms(program, settings, 0, 0.0, 0.0);
  set_near_field_uniforms(program);
  program->SetUniformi("receivers", receivers.points->GetTextureUnit());
  program->SetUniformi("receiverShape", receivers.shape->GetTextureUnit());
  state->PushFramebufferBindings();
  g.gather_fbo->SetContext(window);
  g.gather_fbo->Bind();
  g.gather_fbo->AddColorAttachment(0, receivers.B);
  g.gather_fbo->ActivateDrawBuffers(1);
  state->vtkglViewport(0, 0, receivers.width, receivers.height);
  g.near_quad->Render();
  g.gather_fbo->RemoveColorAttachments(1);
  state->PopFramebufferBindings();
  g.fresnel_table->Deactivate();
  receivers.shape->Deactivate();
  receivers.points->Deactivate();
  g.deactivate_maps();
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
