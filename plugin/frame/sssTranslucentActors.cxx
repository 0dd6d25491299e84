#include "sssTranslucentActors.h"

#include "sssCoreMaterial.h"
#include "sssSceneLights.h"
#include "vtkSurfelMapper.h"
#include "vtkTranslucentMaterial.h"

#include "vtkActor.h"
#include "vtkFloatArray.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkRenderState.h"

#include <algorithm>

namespace sss
{

TranslucentActors::TranslucentActors(Say say, Record record)
  : say_(std::move(say))
  , record_(std::move(record))
{
}

void TranslucentActors::update(const vtkRenderState* s, const StepContext& context,
  const std::vector<GpuLight>& lights, const RefinementRule& rule)
{
  RefinementRule here = rule;
  here.on = rule.on && !context.pieces;
  ready_.clear();
  previewing_ = false;
  unrefined_ = false;
  refined_share_ = 1.0;
  preparing_ = false;
  std::set<vtkActor*> seen;
  for (int i = 0; i < s->GetPropArrayCount(); ++i)
  {
    auto* actor = vtkActor::SafeDownCast(s->GetPropArray()[i]);
    if (!actor || !actor->GetVisibility() || !vtkTranslucentMaterial::GetFrom(actor))
    {
      continue;
    }
    if (this->update_actor(actor, context, lights, here, seen))
    {
      ready_.insert(actor);
    }
  }
  for (auto it = states_.begin(); it != states_.end();)
  {
    if (seen.count(it->first) == 0)
    {
      it->second->release(context.window);
      it = states_.erase(it);
    }
    else
    {
      ++it;
    }
  }
}

bool TranslucentActors::update_actor(vtkActor* actor, const StepContext& context,
  const std::vector<GpuLight>& lights, const RefinementRule& rule, std::set<vtkActor*>& seen)
{
  vtkTranslucentMaterial* material = vtkTranslucentMaterial::GetFrom(actor);
  auto* mapper = vtkSurfelMapper::SafeDownCast(actor->GetMapper());
  if (!mapper)
  {
    say_("an actor carries a translucent material but its mapper is not a vtkSurfelMapper; it "
         "draws as before",
      false);
    return false;
  }
  const std::string invalid = material->Validate();
  if (!invalid.empty())
  {
    say_("translucent material: " + invalid, true);
    return false;
  }
  const PreparedSurfels& surfels = mapper->UpdateSurfels(actor);
  const SurfelBuffers& buffers = mapper->UpdateBuffers(actor);
  const std::vector<GpuLight> local = lights_in_model_frame(lights, actor->GetMatrix());
  if (!surfels.error.empty())
  {
    // The mapper reports it and draws nothing; the other pieces' step 1 still needs this one.
    TranslucentActorState::take_part_without_surfels(context, local);
    return false;
  }
  if (lights.empty())
  {
    say_("the renderer has no switched-on light: translucent actors receive no light and are "
         "black",
      false);
  }
  seen.insert(actor);
  Material core = core_material(*material);
  core.mm_per_unit *= model_scale(actor->GetMatrix());
  auto& state = states_[actor];
  if (!state)
  {
    state = std::make_unique<RefiningActorState>();
  }
  std::string error;
  auto precomputed = precomputed_.find(actor);
  if (precomputed != precomputed_.end())
  {
    std::vector<Rgb> B;
    if (!radiance_in_surfel_order(surfels, precomputed->second, B))
    {
      say_("precomputed radiance needs 3 components per input point", true);
      return false;
    }
    TranslucentActorState& given = state->settled_for_given_radiance();
    if (!given.show_radiance(context.window, surfels, core, B, error))
    {
      say_("precomputed radiance: " + error, true);
      return false;
    }
    return true;
  }
  StepReport report;
  const ActorInputs inputs{ surfels, buffers, core, material->GetColoursAsAlbedo(), local };
  RefiningActorState::Shown shown = RefiningActorState::Shown::Settled;
  if (!state->update(context, inputs, rule, shown, report, error))
  {
    say_("subsurface scattering is off for an actor: " + error, true);
    return false;
  }
  for (const std::string& note : report.notes)
  {
    say_(note, false);
  }
  if (shown == RefiningActorState::Shown::Settled)
  {
    record_(report);
    return true;
  }
  if (shown == RefiningActorState::Shown::Unrefined)
  {
    if (!error.empty())
    {
      say_("the refinement failed; the preview stays until the inputs change: " + error, true);
    }
    unrefined_ = true;
    return true;
  }
  previewing_ = true;
  refined_share_ = std::min(refined_share_, state->refined_share());
  preparing_ = preparing_ || state->preparing();
  if (shown == RefiningActorState::Shown::Preview)
  {
    last_preview_seconds_ = report.seconds_illumination + report.seconds_surfels;
  }
  return true;
}

TranslucentActorState* TranslucentActors::state(vtkActor* actor) const
{
  auto found = states_.find(actor);
  return found == states_.end() ? nullptr : &found->second->shown();
}

double TranslucentActors::preview_error() const
{
  double largest = -1.0;
  for (const auto& entry : states_)
  {
    largest = std::max(largest, entry.second->preview_error());
  }
  return largest;
}

bool TranslucentActors::part_due(const RefinementRule& rule) const
{
  for (const auto& entry : states_)
  {
    if (entry.second->part_due(rule))
    {
      return true;
    }
  }
  return false;
}

void TranslucentActors::set_precomputed(vtkActor* actor, vtkFloatArray* B)
{
  if (B)
  {
    precomputed_[actor] = B;
  }
  else
  {
    precomputed_.erase(actor);
  }
}

void TranslucentActors::release(vtkWindow* window)
{
  for (auto& entry : states_)
  {
    entry.second->release(window);
  }
  states_.clear();
  ready_.clear();
}

}
