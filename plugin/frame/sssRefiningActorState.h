// One translucent actor of a vtkSubsurfacePass with Refinement on: a change of its lights,
// material or geometry is shown first from a coarser method (the 2005 paper's: a light move of
// a few plain frames, tens of percent off), and the pass's own settings' B is computed over the
// frames drawn once the inputs have rested for a while, a part of its light move each, and
// shown when complete. Each method keeps its own state and bake (sssTranslucentActorState), so
// going back and forth re-bakes neither.
#ifndef sssRefiningActorState_h
#define sssRefiningActorState_h

#include "sssTranslucentActorState.h"

#include <chrono>
#include <string>

namespace sss
{

// When refinement runs: on, the settings' B follows a preview once the inputs have not changed
// for rest_seconds since the preview was ready, over frames of about frame_seconds each (a
// light move's map, cells and near field run in one frame, its far field in parts).
struct RefinementRule
{
  bool on = false;
  double rest_seconds = 0.3;
  double frame_seconds = 0.1;
};

class RefiningActorState
{
public:
  enum class Shown
  {
    Settled,  // B at the pass's settings
    Preview,  // B from the coarser method, just computed
    Refining,  // the preview again, while the settings' B is under way
    Unrefined  // the preview, the settings' B having failed for these inputs (`error` says why)
  };

  // Runs what the inputs call for (above); with the rule off, the settings' steps at once, and
  // so too when the preview fails. `report` is that of the method whose steps ran. False with
  // `error` set when it cannot run; a failed refinement leaves the preview (Shown::Unrefined).
  bool update(const StepContext& context, const ActorInputs& actor, const RefinementRule& rule,
    Shown& shown, StepReport& report, std::string& error);

  // The state whose B is on screen.
  TranslucentActorState& shown() { return preview_shown_ ? preview_ : settled_; }
  // The settled state, for B given from outside (TranslucentActorState::show_radiance).
  TranslucentActorState& settled_for_given_radiance();

  // While refining, the share of the settled light move done (0 to 1).
  double refined_share() const { return refined_share_; }
  // While refining, whether the settled bake's CPU part still runs on its thread.
  bool preparing() const { return preview_shown_ && settled_.preparing(); }
  // Whether an update now, with the inputs of the last, would take the refinement further: a
  // preview is shown, its inputs have rested for the rule's rest_seconds, and no bake's thread
  // is still at work. Read at any time, between frames.
  bool part_due(const RefinementRule& rule) const;

  // The mean relative error (error_metric.h) of the last preview against the settled B that
  // replaced it (0.01 = 1 %); negative before the first refinement.
  double preview_error() const { return preview_error_; }

  void release(vtkWindow* window);

private:
  // The coarser method's settings: the paper's, at its defaults.
  static QualitySettings preview_settings();
  // Whether the preview's inputs have not changed for the rule's rest_seconds.
  bool rested(const RefinementRule& rule) const;

  TranslucentActorState settled_;
  TranslucentActorState preview_;
  bool preview_shown_ = false;
  bool settled_failed_ = false;  // for the preview's inputs
  std::chrono::steady_clock::time_point preview_inputs_since_;  // its steps' end for new inputs
  double preview_error_ = -1.0;
  double refined_share_ = 0.0;
};

}

#endif
