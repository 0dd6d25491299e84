#include "sssPaperStrategy.h"

#include "sssLightMaps.h"
#include "sssMaterialUniforms.h"
#include "sssPaperTaps.h"
#include "sssSurfelResolve.h"
#include "sss_dipole.h"
#include "sss_gather_paper.h"
#include "sss_light_maps.h"
#include "sss_paper_taps_fs.h"
#include "sss_virtual_points_fs.h"
#include "sss_virtual_points_vs.h"

#include "dipole.h"
#include "local_surfels.h"
#include "hilbert_order.h"
#include "virtual_grid.h"

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
#include <numeric>

namespace sss
{

namespace
{
// The paper's grid: 64 points per axis (13-19 k kept on its scans).
constexpr int kPaperGridLevel = 6;
}

// The virtual points as a list texture: in Hilbert order of position, 16 to a 4 x 4 texel
// block (itself in Morton order), blocks row by row.
struct ReceiverList
{
  vtkSmartPointer<vtkTextureObject> points;  // xyz: local mm, w: 1 where a receiver
  vtkSmartPointer<vtkTextureObject> B;       // the taps' result, same layout
  vtkNew<vtkOpenGLBufferObject> texel;       // per receiver, in input order: its texel
  int width = 0, height = 0;

  void upload(vtkOpenGLRenderWindow* window, const std::vector<Eigen::Vector3d>& positions)
  {
    const std::size_t n = positions.size();
    const std::vector<std::size_t> order = hilbert_order(positions);
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
    release_held(window, points, B);
  }
};

PaperStrategy::PaperStrategy()
  : receivers_(new ReceiverList)
{
}

PaperStrategy::~PaperStrategy() = default;

void PaperStrategy::release(vtkWindow* window)
{
  grid_.reset();
  receivers_->release(window);
  grid_index_->ReleaseGraphicsResources();
  grid_vao_.release();
  release_held(window, radiance_, taps_quad_);
  taps_fbo_->ReleaseGraphicsResources(window);
  grid_fbo_->ReleaseGraphicsResources(window);
}

LightMapRequest PaperStrategy::light_map_request(const QualitySettings&) const
{
  LightMapRequest request;
  request.paper = true;
  request.max_map_size = kPaperMapSize;
  return request;
}

bool PaperStrategy::bake(const StepContext& context, const LocalSurfels& local,
  const Material&, const Dipole& dipole, StepReport& report, std::string& error)
{
  vtkOpenGLRenderWindow* const window = context.window;
  const QualitySettings& settings = context.settings;
  const int level = settings.grid_level;
  grid_.reset();
  radiance_ = nullptr;
  VirtualGridSettings grid_settings;
  grid_settings.level = level == 0 ? kPaperGridLevel : level;
  try
  {
    grid_ = std::make_unique<VirtualGrid>(VirtualGrid::build(local, dipole, grid_settings));
  }
  catch (const std::exception& e)
  {
    error = e.what();
    return false;
  }
  const VirtualGrid& grid = *grid_;
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
  slice_range_.assign(grid.dims()[2], { 0, 0 });
  for (std::size_t r = 0; r < order.size(); ++r)
  {
    const Eigen::Array3d& c = ijk[order[r]];
    const int k = static_cast<int>(c.z());
    if (slice_range_[k].second == 0)
    {
      slice_range_[k].first = static_cast<int>(r);
    }
    ++slice_range_[k].second;
    indices.insert(indices.end(),
      { static_cast<float>(c.x()), static_cast<float>(c.y()), static_cast<float>(c.z()) });
    receivers.push_back(grid.points()[order[r]]);  // the paper evaluates at the grid points
  }
  receivers_->upload(window, receivers);
  grid_index_->Upload(indices, vtkOpenGLBufferObject::ArrayBuffer);
  grid_vao_.program = nullptr;
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
  radiance_ = tex;
  report.virtual_point_count = grid.points().size();
  report.grid_level = grid.level();
  report.grid_spacing_mm = grid.spacing();
  return true;
}

bool PaperStrategy::light(const StepContext& context, const GpuLightMaps& maps,
  const Dipole& dipole, SurfelResolve& resolve, vtkOpenGLBufferObject* positions, StepReport&,
  std::string& error)
{
  vtkOpenGLRenderWindow* const window = context.window;
  const VirtualGrid& grid = *grid_;
  ReceiverList& receivers = *receivers_;
  static const std::string fs = shader_with_pieces(sss_paper_taps_fs,
    std::string(sss_light_maps) + "\n" + sss_dipole + "\n" + sss_gather_paper);
  vtkShaderProgram* taps = ready_quad(taps_quad_, window, fs.c_str());
  if (!taps)
  {
    error = "the paper's tap shader did not compile";
    return false;
  }
  vtkOpenGLState* state = window->GetState();
  PointPassState point_pass(state);
  {
    const LightMapAtlas atlas = maps.atlas();
    maps.point()->Activate();
    maps.power()->Activate();
    maps.normal()->Activate();
    receivers.points->Activate();
    set_dipole_uniforms(taps, dipole);
    std::vector<float> rects(4 * kMaxLights * kMaxLevels, 0.0f), texel(kMaxLights, 0.0f),
      axis_u(3 * kMaxLights, 0.0f), axis_v(3 * kMaxLights, 0.0f), corner(2 * kMaxLights, 0.0f);
    for (std::size_t l = 0; l < atlas.maps.size(); ++l)
    {
      const LightMapAtlas::Map& m = atlas.maps[l];
      const OrthoView& o = m.view.ortho;  // the paper's maps are all orthographic
      float* r = &rects[4 * l * kMaxLevels];
      r[0] = float(m.x);
      r[1] = float(m.y);
      r[2] = float(o.width);
      r[3] = float(o.height);
      texel[l] = static_cast<float>(o.pixel);
      for (int c = 0; c < 3; ++c)
      {
        axis_u[3 * l + c] = static_cast<float>(o.u[c]);
        axis_v[3 * l + c] = static_cast<float>(o.v[c]);
      }
      corner[2 * l] = static_cast<float>(o.corner.x());
      corner[2 * l + 1] = static_cast<float>(o.corner.y());
    }
    taps->SetUniformi("lightCount", static_cast<int>(atlas.maps.size()));
    taps->SetUniform4fv("levelRect", kMaxLights * kMaxLevels, rects.data());
    taps->SetUniform1fv("texelSize", kMaxLights, texel.data());
    taps->SetUniform3fv("mapAxisU", kMaxLights, axis_u.data());
    taps->SetUniform3fv("mapAxisV", kMaxLights, axis_v.data());
    taps->SetUniform2fv("mapCorner", kMaxLights, corner.data());
    const auto tap_table = paper_taps();
    taps->SetUniform3fv("paperTaps", kPaperTapCount, &tap_table[0][0]);
    taps->SetUniformi("mapPoint", maps.point()->GetTextureUnit());
    taps->SetUniformi("mapPower", maps.power()->GetTextureUnit());
    taps->SetUniformi("mapNormal", maps.normal()->GetTextureUnit());
    taps->SetUniformi("receivers", receivers.points->GetTextureUnit());
    state->PushFramebufferBindings();
    taps_fbo_->SetContext(window);
    taps_fbo_->Bind();
    taps_fbo_->AddColorAttachment(0, receivers.B);
    taps_fbo_->ActivateDrawBuffers(1);
    state->vtkglViewport(0, 0, receivers.width, receivers.height);
    taps_quad_->Render();
    taps_fbo_->RemoveColorAttachments(1);
    state->PopFramebufferBindings();
    receivers.points->Deactivate();
    maps.point()->Deactivate();
    maps.power()->Deactivate();
    maps.normal()->Deactivate();
  }

  // Into the 3-D texture, one layer at a time.
  vtkShaderProgram* program = window->GetShaderCache()->ReadyShaderProgram(
    sss_virtual_points_vs, sss_virtual_points_fs, "");
  if (!program)
  {
    error = "the virtual-point shaders did not compile";
    return false;
  }
  grid_vao_.bind(program, grid_index_, "gridIndex", receivers.texel, "gatheredTexel");
  receivers.B->Activate();
  program->SetUniformi("gathered", receivers.B->GetTextureUnit());
  const float slice[2] = { float(grid.dims()[0]), float(grid.dims()[1]) };
  program->SetUniform2f("sliceSize", slice);
  state->PushFramebufferBindings();
  grid_fbo_->SetContext(window);
  grid_fbo_->Bind();
  state->vtkglViewport(0, 0, grid.dims()[0], grid.dims()[1]);
  state->vtkglClearColor(0, 0, 0, 0);
  GLenum draw_buffer = GL_COLOR_ATTACHMENT0;
  state->vtkglDrawBuffers(1, &draw_buffer);
  for (int k = 0; k < grid.dims()[2]; ++k)
  {
    glFramebufferTextureLayer(
      GL_DRAW_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, radiance_->GetHandle(), 0, k);
    state->vtkglClear(GL_COLOR_BUFFER_BIT);
    if (slice_range_[k].second > 0)
    {
      glDrawArrays(GL_POINTS, slice_range_[k].first, slice_range_[k].second);
    }
  }
  glFramebufferTextureLayer(GL_DRAW_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, 0, 0, 0);
  state->PopFramebufferBindings();
  grid_vao_.vao->Release();
  receivers.B->Deactivate();
  GridRadiance on_grid;
  on_grid.grid = grid_.get();
  on_grid.radiance = radiance_;
  on_grid.gathered = receivers.B;  // B per virtual point, in their list's layout
  return resolve.from_grid(window, positions, on_grid, error);
}

}
