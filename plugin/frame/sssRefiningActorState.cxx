#include "sssRefiningActorState.h"

#include "error_metric.h"

#include "vtkOpenGLRenderWindow.h"

#include <vector>

namespace sss
{

QualitySettings RefiningActorState::preview_settings()
{
  QualitySettings paper;
  paper.strategy = KernelStrategy::Paper;
  return paper;
}

bool RefiningActorState::update(const StepContext& context, const ActorInputs& actor,
  const RefinementRule& rule, Shown& shown, StepReport& report, std::string& error)
{
  using Clock = std::chrono::steady_clock;
  shown = Shown::Settled;
  if (!rule.on || context.settings.strategy == preview_settings().strategy ||
    settled_.is_current(context, actor))
  {
    preview_shown_ = false;
    return settled_.update(context, actor, report, error);
  }
  StepContext coarse = context;
  coarse.settings = preview_settings();
  if (!preview_shown_ || !preview_.is_current(coarse, actor))
  {
    // The inputs changed since the last frame: the preview follows them, and the rest counts
    // from when it is ready. A bake under way for the settled B of other inputs stops now.
    settled_.drop_stale_preparation(context, actor);
    if (!preview_.update(coarse, actor, report, error))
    {
      // No preview (its grid did not fit, say): the settings' B at once.
      preview_shown_ = false;
      report = StepReport{};
      error.clear();
      return settled_.update(context, actor, report, error);
    }
    preview_inputs_since_ = Clock::now();
    preview_shown_ = true;
    settled_failed_ = false;
    refined_share_ = 0.0;
    shown = Shown::Preview;
    return true;
  }
  if (settled_failed_)
  {
    shown = Shown::Unrefined;  // until the inputs change
    return true;
  }
  shown = Shown::Refining;
  if (!rested(rule))
  {
    return true;  // still moving, as far as we know: the preview stays
  }
  // The preview on screen is of these inputs, which have rested: refine, a part a frame.
  StepContext part = context;
  part.seconds = rule.frame_seconds;
  if (!settled_.update(part, actor, report, error))
  {
    settled_failed_ = true;  // not tried again for these inputs; the preview stays
    shown = Shown::Unrefined;
    return true;
  }
  if (report.unfinished)
  {
    refined_share_ = report.done_share;
    return true;
  }
  shown = Shown::Settled;
  preview_shown_ = false;
  std::vector<Rgb> coarse_B, settled_B;
  if (preview_.read_surfel_radiance(context.window, coarse_B) &&
    settled_.read_surfel_radiance(context.window, settled_B) &&
    coarse_B.size() == settled_B.size())
  {
    preview_error_ = compare_radiance(coarse_B, settled_B).mean;
  }
  return true;
}

bool RefiningActorState::rested(const RefinementRule& rule) const
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - preview_inputs_since_)
           .count() >= rule.rest_seconds;
}

bool RefiningActorState::part_due(const RefinementRule& rule) const
{
  return rule.on && preview_shown_ && !settled_failed_ && rested(rule) &&
    !settled_.preparation_under_way();
}

TranslucentActorState& RefiningActorState::settled_for_given_radiance()
{
  preview_shown_ = false;
  return settled_;
}

void RefiningActorState::release(vtkWindow* window)
{
  settled_.release(window);
  preview_.release(window);
  preview_shown_ = false;
}

}
