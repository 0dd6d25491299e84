// The translucent actors of a frame in a vtkSubsurfacePass: each visible actor that carries a
// vtkTranslucentMaterial and draws with a vtkSurfelMapper gets its steps 1-2 brought up to
// date (sssTranslucentActorState; with refinement first from a coarser method,
// sssRefiningActorState) or the radiance given for it shown; the actors ready for the view are
// kept, and the states of actors no longer drawn are released.
#ifndef sssTranslucentActors_h
#define sssTranslucentActors_h

#include "quality_settings.h"
#include "sssLightMaps.h"
#include "sssRefiningActorState.h"
#include "sssTranslucentActorState.h"

#include "vtkSmartPointer.h"

#include <functional>
#include <map>
#include <memory>
#include <set>
#include <string>
#include <vector>

class vtkActor;
class vtkFloatArray;
class vtkOpenGLRenderWindow;
class vtkRenderState;
class vtkSubsurfacePieces;
class vtkWindow;

namespace sss
{

class TranslucentActors
{
public:
  // A warning (error false) or an error for the pass to report.
  using Say = std::function<void(const std::string& message, bool error)>;
  // The report of an actor whose steps ran.
  using Record = std::function<void(const StepReport& report)>;

  // Warnings and errors go to `say`, the reports of the actors whose steps ran to `record`.
  TranslucentActors(Say say, Record record);

  // Steps 1-2 of every translucent actor among the state's props, where their inputs changed,
  // with the world-frame `lights`, refined by the rule as RefiningActorState::update does (not
  // with pieces). Collective with the context's pieces (TranslucentActorState::update).
  void update(const vtkRenderState* s, const StepContext& context,
    const std::vector<GpuLight>& lights, const RefinementRule& rule);

  // Whether a ready actor shows a preview that a frame with unchanged inputs will refine.
  bool previewing() const { return previewing_; }
  // Whether a ready actor shows a preview whose refinement failed (until its inputs change).
  bool unrefined() const { return unrefined_; }
  // The last preview's steps 1-2 in seconds (0 before the first).
  double last_preview_seconds() const { return last_preview_seconds_; }
  // The largest RefiningActorState::preview_error over the actors (negative: none yet).
  double preview_error() const;
  // While previewing, the least share of a settled light move done over the actors (0 to 1).
  double refined_share() const { return refined_share_; }
  // Whether a refining actor's bake still runs its CPU part on a thread.
  bool preparing() const { return preparing_; }
  // Whether a frame now, with unchanged inputs, would take an actor's refinement further
  // (RefiningActorState::part_due); read at any time, between frames.
  bool part_due(const RefinementRule& rule) const;

  // The actors whose B is valid this frame; none after clear_ready.
  const std::set<vtkActor*>& ready() const { return ready_; }
  bool is_ready(vtkActor* actor) const { return ready_.count(actor) != 0; }
  void clear_ready() { ready_.clear(); }

  // The state whose B the actor shows, or null when it has none.
  TranslucentActorState* state(vtkActor* actor) const;

  // B per input point to show for `actor` instead of its steps 1-2; null goes back to them.
  void set_precomputed(vtkActor* actor, vtkFloatArray* B);

  void release(vtkWindow* window);

private:
  // Brings one actor up to date; false when it is not ready. Adds it to `seen` once it has
  // surfels and a valid material (the states of the others are released).
  bool update_actor(vtkActor* actor, const StepContext& context,
    const std::vector<GpuLight>& lights, const RefinementRule& rule, std::set<vtkActor*>& seen);

  Say say_;
  Record record_;
  std::map<vtkActor*, std::unique_ptr<RefiningActorState>> states_;
  bool previewing_ = false;
  bool unrefined_ = false;
  double last_preview_seconds_ = 0.0;
  double refined_share_ = 1.0;
  bool preparing_ = false;
  std::set<vtkActor*> ready_;
  std::map<vtkActor*, vtkSmartPointer<vtkFloatArray>> precomputed_;
};

}

#endif
