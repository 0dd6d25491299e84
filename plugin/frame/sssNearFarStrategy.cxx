#include "sssNearFarStrategy.h"

#include "sssFarField.h"
#include "sssGpuHelpers.h"
#include "sssLitCells.h"
#include "sssMaterialUniforms.h"
#include "sssNearFieldTable.h"
#include "sssSurfelList.h"
#include "sssSurfelResolve.h"
#include "sss_dipole.h"
#include "sss_far_field.h"
#include "sss_near_field.h"
#include "sss_near_field_fs.h"
#include "sss_surfel_list.h"

#include "near_field.h"
#include "stopwatch.h"
#include "surfel_cells.h"
#include "surfel_index.h"

#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLQuadHelper.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLState.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"
#include "vtk_glew.h"

#include <algorithm>
#include <cmath>

namespace sss
{

// What the bake computes on the CPU (NearFarStrategy::prepare).
struct NearFarStrategy::Preparation : BakePreparation
{
  NearFarSplit split;
  SurfelCells cells;
  NearFieldWeights weights;
};

struct NearFarStrategy::Gpu
{
  Material material;
  NearFarSplit split;
  double support = 0;
  double cell_radius = 0;  // mm
  QualitySettings settings;

  SurfelList list;
  LitCells cells;
  NearFieldTable near;
  FarFieldProgress far_progress;  // of the light move under way
  std::unique_ptr<Preparation> prepared;  // adopted for the next bake
  vtkSmartPointer<vtkTextureObject> B;  // surfel list layout
  vtkNew<vtkOpenGLFramebufferObject> fbo;
  std::unique_ptr<vtkOpenGLQuadHelper> gather_quad;

  void release(vtkWindow* window)
  {
    list.release(window);
    cells.release(window);
    near.release(window);
    release_held(window, B, gather_quad);
    fbo->ReleaseGraphicsResources(window);
  }

  // The dipole's uniforms (dipole.glsl) and where the far field starts (far_field.glsl).
  void set_dipole(vtkShaderProgram* program, const Dipole& dipole) const
  {
    set_dipole_uniforms(program, dipole);
    set_eta_uniform(program, material);
    program->SetUniformf("farFrom", static_cast<float>(split.reach));
  }
};

NearFarStrategy::NearFarStrategy()
  : gpu_(new Gpu)
{
}

NearFarStrategy::~NearFarStrategy() = default;

LightMapRequest NearFarStrategy::light_map_request(const QualitySettings& settings) const
{
  LightMapRequest request;
  request.texel_per_radius = settings.texel_per_radius;
  request.max_map_size = settings.max_map_size;
  request.list_texel = gpu_->list.texel_buffer();
  return request;
}

void NearFarStrategy::release(vtkWindow* window)
{
  gpu_->release(window);
}

std::unique_ptr<NearFarStrategy::Preparation> NearFarStrategy::prepare(
  const LocalSurfels& local, const Dipole& dipole, const CancelFlag* cancel)
{
  auto prepared = std::make_unique<Preparation>();
  prepared->split = NearFarSplit::choose(
    dipole, local.cell_radius > 0.0 ? local.cell_radius : 1.0, kKernelSupportFraction);
  const SurfelIndex index(local.positions);
  prepared->cells = surfel_cells(local, index, cancel);
  prepared->weights =
    near_field_weights(local, prepared->cells, index, dipole, prepared->split.reach, {}, cancel);
  return prepared;
}

BakeWork NearFarStrategy::bake_work(const LocalSurfels& local, const Dipole& dipole) const
{
  return [local, dipole](const CancelFlag& cancel) -> std::unique_ptr<BakePreparation> {
    return prepare(local, dipole, &cancel);
  };
}

void NearFarStrategy::adopt(std::unique_ptr<BakePreparation> prepared)
{
  gpu_->prepared.reset(dynamic_cast<Preparation*>(prepared.get()));
  if (gpu_->prepared)
  {
    prepared.release();
  }
}

bool NearFarStrategy::bake(const StepContext& context, const LocalSurfels& local,
  const Material& material, const Dipole& dipole, StepReport& report, std::string& error)
{
  vtkOpenGLRenderWindow* const window = context.window;
  Gpu& g = *gpu_;
  g.material = material;
  g.settings = context.settings;
  g.cell_radius = local.cell_radius;
  g.support = dipole.max_support_radius(kKernelSupportFraction);
  std::unique_ptr<Preparation> prepared = std::move(g.prepared);
  if (!prepared)
  {
    try
    {
      prepared = prepare(local, dipole);
    }
    catch (const std::exception& e)
    {
      error = e.what();
      return false;
    }
  }
  g.split = prepared->split;
  report.near_reach_mm = g.split.reach;
  report.far_from_mm = g.split.has_far ? g.split.reach : 0.0;
  report.near_entries = prepared->weights.source.size();
  if (!g.list.upload(window, local, prepared->cells, error) ||
    !g.near.upload(window, g.list, prepared->weights, error))
  {
    return false;
  }
  g.B = float_texture_2d(window, g.list.width(), g.list.height());
  g.cells.bake(window, material);
  return true;
}

bool NearFarStrategy::light(const StepContext& context, const GpuLightMaps& light_maps,
  const Dipole& dipole, SurfelResolve& resolve, vtkOpenGLBufferObject* positions,
  StepReport& report, std::string& error)
{
  vtkOpenGLRenderWindow* const window = context.window;
  const bool finish = context.finish;
  const LightMapAtlas maps = light_maps.atlas();
  Gpu& g = *gpu_;
  const Stopwatch call;
  Stopwatch clock;
  if (!context.resume)
  {
    g.far_progress.restart();
    if (!g.cells.light(window, g.list, maps, g.cell_radius, g.settings.cell_samples,
          report.refined_cells, error))
    {
      return false;
    }
    finish_if(finish);
    report.seconds_cells = clock.lap();
    report.lit_cells = 0;
    if (g.split.has_far && !maps.maps.empty() &&
      !g.cells.reduce(window, g.list, report.lit_cells, error))
    {
      return false;
    }
    finish_if(finish);
    report.seconds_pyramid = clock.lap();
  }

  // B at every surfel: the near field's table, then the far field's walk.
  static const std::string gather_fs = shader_with_pieces(sss_near_field_fs,
    std::string(sss_surfel_list) + sss_dipole + sss_near_field +
      sss_far_field);
  vtkShaderProgram* gather = ready_quad(g.gather_quad, window, gather_fs.c_str());
  if (!gather)
  {
    error = "the near- and far-field shader did not compile";
    return false;
  }
  const int lights = static_cast<int>(maps.maps.size());
  vtkOpenGLState* state = window->GetState();
  PointPassState pass_state(state);
  vtkOpenGLState::ScopedglBlendFuncSeparate blend_function_saved(state);
  state->PushFramebufferBindings();
  g.fbo->SetContext(window);
  g.fbo->Bind();
  g.fbo->AddColorAttachment(0, g.B);
  g.fbo->ActivateDrawBuffers(1);
  g.list.activate();
  g.near.activate(gather);
  g.cells.activate(gather);
  g.list.set(gather);
  g.set_dipole(gather, dipole);
  state->vtkglViewport(0, 0, g.list.width(), g.list.height());
  if (!context.resume)
  {
    gather->SetUniformi("addNearField", 1);
    gather->SetUniformi("addFarField", 0);
    g.gather_quad->Render();
    finish_if(finish);
    report.seconds_near = clock.lap();
  }
  if (g.split.has_far && lights > 0)
  {
    FarFieldSettings far;
    far.opening_angle = g.settings.opening_angle;
    far.max_group_diffusion_lengths = g.settings.max_group_diffusion_lengths;
    far.support_radius = g.support;
    for (int c = 0; c < 3; ++c)
    {
      far.size_bound_reach[c] = dipole.channel[c].support_radius(kGroupSizeBoundFraction);
    }
    // A first part that has used its time leaves the whole far field to the next.
    if (context.resume || call.seconds() < context.seconds)
    {
      g.far_progress.band_seconds = context.seconds;
      add_far_field(state, *g.gather_quad, gather, g.cells, g.list.height(), far,
        g.far_progress, context.seconds - call.seconds());
    }
    else
    {
      g.far_progress.total = far_field_parts(g.cells);
    }
  }
  g.cells.deactivate();
  g.near.deactivate();
  g.list.deactivate();
  g.fbo->RemoveColorAttachments(1);
  state->PopFramebufferBindings();
  finish_if(finish);
  report.seconds_far = clock.lap();
  if (!g.far_progress.done())
  {
    report.unfinished = true;
    report.done_share = g.far_progress.share(g.list.height());
    return true;
  }
  const bool handed = resolve.from_list(window, positions, g.list.texel_buffer(), g.B, error);
  finish_if(finish);
  report.seconds_hand_over = clock.lap();
  return handed;
}

}
