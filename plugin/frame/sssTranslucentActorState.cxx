#include "sssTranslucentActorState.h"

#include "sssSurfelResolve.h"

#include "local_surfels.h"
#include "stopwatch.h"

#include "vtkOpenGLBufferObject.h"
#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkSubsurfacePieces.h"
#include "vtkTextureObject.h"

#include <cmath>
#include <memory>

namespace sss
{
namespace
{

// Whether step 1 must run on any piece (every piece then runs it); `here` alone without pieces.
bool agree_over_pieces(vtkSubsurfacePieces* pieces, bool here)
{
  if (!pieces || pieces->GetNumberOfPieces() < 2)
  {
    return here;
  }
  double not_here = here ? 0.0 : 1.0;
  pieces->MinimumOverPieces(&not_here, 1);
  return not_here == 0.0;
}

// What a material change is: its coefficients and its scale.
std::vector<double> material_key(const Material& material)
{
  std::vector<double> key;
  for (int c = 0; c < 3; ++c)
  {
    key.insert(key.end(), { material.sigma_a[c], material.sigma_s_prime[c], material.eta[c] });
  }
  key.push_back(material.mm_per_unit);
  return key;
}

}


struct TranslucentActorState::Gpu
{
  LocalSurfels local;
  std::unique_ptr<Dipole> dipole;
  GpuLightMaps maps;                  // step 1
  std::unique_ptr<Strategy> strategy;  // step 2, as the settings' kernel strategy runs it
  KernelStrategy strategy_kind = KernelStrategy::NearFar;
  SurfelResolve resolve;              // B per surfel for the camera view

  void release(vtkWindow* window)
  {
    maps.release(window);
    if (strategy)
    {
      strategy->release(window);
    }
    resolve.release(window);
  }
};

TranslucentActorState::TranslucentActorState()
  : gpu_(new Gpu)
{
}

TranslucentActorState::~TranslucentActorState() = default;

vtkTextureObject* TranslucentActorState::surfel_radiance() const
{
  return gpu_->resolve.texture();
}

int TranslucentActorState::list_width() const
{
  return gpu_->resolve.width();
}

void TranslucentActorState::take_part_without_surfels(
  const StepContext& context, const std::vector<GpuLight>& lights)
{
  if (agree_over_pieces(context.pieces, false) &&
    context.settings.strategy != KernelStrategy::Paper)
  {
    GpuLightMaps::take_part_without_surfels(
      context.pieces, lights, context.settings.max_map_size);
  }
}

void TranslucentActorState::release(vtkWindow* window)
{
  gpu_->release(window);
  valid_ = false;
  baked_ = false;
  unfinished_ = false;
  baked_inputs_ = BakeInputs{};
  background_.drop();
}

TranslucentActorState::BakeInputs TranslucentActorState::bake_inputs(
  const StepContext& context, const ActorInputs& actor)
{
  return { actor.buffers.upload_time.GetMTime(), material_key(actor.material), context.settings,
    actor.albedo_from_colour };
}

bool TranslucentActorState::geometry_current(
  const StepContext& context, const ActorInputs& actor) const
{
  return baked_ && baked_inputs_.geometry_time != 0 &&
    bake_inputs(context, actor) == baked_inputs_;
}

void TranslucentActorState::drop_stale_preparation(
  const StepContext& context, const ActorInputs& actor)
{
  if (background_.running() && !(background_inputs_ == bake_inputs(context, actor)))
  {
    background_.drop();
  }
}

bool TranslucentActorState::is_current(const StepContext& context, const ActorInputs& actor) const
{
  return valid_ && geometry_current(context, actor) && actor.lights == lights_;
}

bool TranslucentActorState::update(
  const StepContext& context, const ActorInputs& actor, StepReport& report, std::string& error)
{
  const Material& material = actor.material;
  const bool geometry_changed = !geometry_current(context, actor);
  const bool light_changed = agree_over_pieces(context.pieces,
    geometry_changed || !(actor.lights == lights_) || (!valid_ && !unfinished_));
  if (light_changed && !geometry_changed && bake_report_)
  {
    report = *bake_report_;  // the bake that ended the last frame is this light move's
  }
  bake_report_.reset();
  report.surfel_count = actor.surfels.cloud.size();
  if (!light_changed && !unfinished_)
  {
    return true;
  }
  Gpu& g = *gpu_;
  Stopwatch clock;
  StepContext step = context;
  step.resume = !light_changed;  // the same inputs as the unfinished light move: go on with it
  if (light_changed)
  {
    material_ = material;
    valid_ = false;
    unfinished_ = false;
    if (geometry_changed)
    {
      baked_ = false;
      BakeProgress progress = BakeProgress::Done;
      if (!bake(context, actor, report, progress, error))
      {
        return false;
      }
      if (progress != BakeProgress::Waiting)
      {
        baked_ = true;
        baked_inputs_ = bake_inputs(context, actor);
        report.bake = true;
        report.seconds_bake += clock.lap();
      }
      if (progress != BakeProgress::Done)
      {
        // Waiting, or the uploads took this frame: the light move starts in the next.
        if (progress == BakeProgress::DoneFromBackground)
        {
          bake_report_ = report;
        }
        report.unfinished = true;
        report.done_share = 0.0;
        return true;
      }
    }

    LightMapReport maps;
    LightMapRequest request = g.strategy->light_map_request(context.settings);
    request.pieces = context.pieces;
    if (!g.maps.render(context.window, actor.buffers, g.local, actor.lights, request, maps, error))
    {
      return false;
    }
    finish_if(context.finish);
    report.illumination = true;
    report.seconds_illumination = clock.lap();
    report.map_width = maps.map_width;
    report.map_height = maps.map_height;
    report.texel_mm = maps.texel_mm;
    report.notes = maps.notes;
    lights_ = actor.lights;
  }
  if (!g.strategy->light(step, g.maps, *g.dipole, g.resolve, actor.buffers.positions, report,
        error))
  {
    unfinished_ = false;  // the next update starts again
    return false;
  }
  finish_if(context.finish);
  report.seconds_surfels = clock.lap();
  if (step.resume)
  {
    unfinished_move_.add_resumed(report);
    report = unfinished_move_;
  }
  report.surfels = !report.unfinished;
  unfinished_ = report.unfinished;
  if (unfinished_)
  {
    unfinished_move_ = report;
    return true;
  }
  valid_ = true;
  return true;
}

bool TranslucentActorState::bake(const StepContext& context, const ActorInputs& actor,
  StepReport& report, BakeProgress& progress, std::string& error)
{
  Gpu& g = *gpu_;
  progress = BakeProgress::Done;
  const BakeInputs inputs = bake_inputs(context, actor);
  if (background_.running() && background_inputs_ == inputs)
  {
    if (!std::isfinite(context.seconds))
    {
      background_.wait();  // a frame that must show the settled B
    }
    else if (!background_.finished())
    {
      progress = BakeProgress::Waiting;
      return true;
    }
    std::unique_ptr<BakePreparation> prepared = background_.take(error);
    if (!prepared)
    {
      return false;
    }
    report.seconds_bake = prepared->seconds;  // update() adds this frame's part
    g.strategy->adopt(std::move(prepared));
    if (std::isfinite(context.seconds))
    {
      progress = BakeProgress::DoneFromBackground;
    }
    return g.strategy->bake(context, g.local, material_, *g.dipole, report, error);
  }
  background_.drop();  // of other inputs
  if (!begin_bake(context, actor, error))
  {
    return false;
  }
  if (std::isfinite(context.seconds))
  {
    if (BakeWork work = g.strategy->bake_work(g.local, *g.dipole))
    {
      background_.start(std::move(work));
      background_inputs_ = inputs;
      progress = BakeProgress::Waiting;
      return true;
    }
  }
  return g.strategy->bake(context, g.local, material_, *g.dipole, report, error);
}

bool TranslucentActorState::begin_bake(
  const StepContext& context, const ActorInputs& actor, std::string& error)
{
  Gpu& g = *gpu_;
  g.local = LocalSurfels::from(actor.surfels.cloud, material_.mm_per_unit);
  g.dipole = std::make_unique<Dipole>(material_);
  const std::size_t n = g.local.size();
  if (actor.buffers.count != n)
  {
    error = "the surfels' vertex buffers hold " + std::to_string(actor.buffers.count) + " of " +
      std::to_string(n) + " surfels";
    return false;
  }
  g.resolve.allocate(context.window, n, material_.mm_per_unit);
  g.maps.set_surfels(g.local, material_, actor.albedo_from_colour);
  const QualitySettings& settings = context.settings;
  if (!g.strategy || g.strategy_kind != settings.strategy)
  {
    if (g.strategy)
    {
      g.strategy->release(context.window);
    }
    g.strategy = make_strategy(settings.strategy);
    g.strategy_kind = settings.strategy;
  }
  // Colours as albedo, as the light maps' fragments take them.
  g.local.albedo.clear();
  if (actor.albedo_from_colour)
  {
    g.local.albedo.resize(n);
    for (std::size_t i = 0; i < n; ++i)
    {
      for (int c = 0; c < 3; ++c)
      {
        g.local.albedo[i][c] = actor.surfels.rgba[4 * i + c] / 255.0;
      }
    }
  }
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
  material_ = material;
  gpu_->resolve.set(window, B);
  valid_ = true;
  baked_inputs_ = BakeInputs{};  // the next update() runs every step
  return true;
}

bool TranslucentActorState::read_surfel_radiance(vtkOpenGLRenderWindow* window, std::vector<Rgb>& B)
{
  return valid_ && gpu_->resolve.read(window, B);
}

}
