// One translucent actor in a vtkSubsurfacePass: which steps its changed inputs call for, and
// their order. The steps live in their own rooms: the light maps (step 1, sssLightMaps), step 2
// (the strategy's, sssKernelStrategies: sssNearFarStrategy or the paper's
// sssPaperStrategy) and the hand-over of each surfel's B to the view (sssSurfelResolve).
#ifndef sssTranslucentActorState_h
#define sssTranslucentActorState_h

#include "dipole.h"
#include "material.h"
#include "quality_settings.h"
#include "sssBackgroundBake.h"
#include "sssLightMaps.h"
#include "sssKernelStrategies.h"
#include "sssSurfelBuffers.h"
#include "sssSurfelPreparation.h"

#include "vtkNew.h"
#include "vtkSmartPointer.h"
#include "vtkType.h"

#include <Eigen/Core>
#include <memory>
#include <optional>
#include <string>
#include <vector>

class vtkOpenGLBufferObject;
class vtkOpenGLFramebufferObject;
class vtkOpenGLRenderWindow;
class vtkSubsurfacePieces;
class vtkOpenGLVertexArrayObject;
class vtkShaderProgram;
class vtkTextureObject;
class vtkWindow;

namespace sss
{

// One actor's inputs to its steps: its prepared surfels and the vertex buffers its mapper
// uploaded (a new upload is a new geometry), its material in its own units, whether its colours
// are albedo, and the lights in its model frame.
struct ActorInputs
{
  const PreparedSurfels& surfels;
  const SurfelBuffers& buffers;
  Material material;
  bool albedo_from_colour = false;
  std::vector<GpuLight> lights;
};

class TranslucentActorState
{
public:
  TranslucentActorState();
  ~TranslucentActorState();
  TranslucentActorState(const TranslucentActorState&) = delete;  // owns GPU resources
  TranslucentActorState& operator=(const TranslucentActorState&) = delete;

  // Runs steps 1-2 where their inputs changed, or goes on with an unfinished light move (one
  // that stopped at the context's seconds: report.unfinished) when they did not. With finite
  // seconds a bake's CPU part (Strategy::bake_work) runs on a thread of its own: the calls until
  // it is done return at once, unfinished with nothing done, and the one that finds it done
  // makes the bake's uploads and returns so too; the light move starts in the next. Returns false
  // with `error` set when it cannot run. With the context's pieces (a cloud split over
  // processes), step 1 runs on every piece when it must on any, and its maps are combined over
  // them (sssLightMapPieces.h): collective.
  bool update(const StepContext& context, const ActorInputs& actor, StepReport& report,
    std::string& error);

  // What update does on the other pieces, for a piece whose actor has no surfels: takes part
  // in the decision and, when step 1 runs, in the combination of the maps of `lights` (model
  // frame). Collective.
  static void take_part_without_surfels(
    const StepContext& context, const std::vector<GpuLight>& lights);

  // Whether update would run nothing: B is that of these inputs. Not collective.
  bool is_current(const StepContext& context, const ActorInputs& actor) const;
  // Whether a bake's CPU part runs on its thread (update() returns unfinished meanwhile).
  bool preparing() const { return background_.running(); }
  // Whether that thread is still at work: while it is, an update has nothing to do (read at
  // any time; preparing() stays true until an update takes the result).
  bool preparation_under_way() const { return background_.running() && !background_.finished(); }
  // Cancels a bake's CPU part that runs for other surfels, material or settings than these, so
  // that a run the inputs have left behind stops at once, not at the next update.
  void drop_stale_preparation(const StepContext& context, const ActorInputs& actor);

  // The per-surfel B texture (RGBA32F, surfel i at texel (i % width, i / width)).
  vtkTextureObject* surfel_radiance() const;
  int list_width() const;
  const Material& material() const { return material_; }

  // Shows B given per surfel (e.g. the CPU reference's) instead of running steps 1-2.
  bool show_radiance(vtkOpenGLRenderWindow* window, const PreparedSurfels& surfels,
    const Material& material, const std::vector<Rgb>& B, std::string& error);

  // B of every surfel, read back from the GPU (for baking and tests).
  bool read_surfel_radiance(vtkOpenGLRenderWindow* window, std::vector<Rgb>& B);

  void release(vtkWindow* window);

private:
  struct Gpu;
  // What a bake is of: the surfels' upload, the material, the settings and the albedo.
  struct BakeInputs
  {
    vtkMTimeType geometry_time = 0;
    std::vector<double> material_key;
    QualitySettings settings;
    bool albedo = false;
    bool operator==(const BakeInputs& other) const
    {
      return geometry_time == other.geometry_time && material_key == other.material_key &&
        settings == other.settings && albedo == other.albedo;
    }
  };
  static BakeInputs bake_inputs(const StepContext& context, const ActorInputs& actor);
  // Whether the bake is that of these surfels, material and settings.
  bool geometry_current(const StepContext& context, const ActorInputs& actor) const;
  // How far bake() got: done in this call, its CPU part still on background_ (finite
  // seconds), or done now from that part (the frame that took it ends there).
  enum class BakeProgress
  {
    Done,
    Waiting,
    DoneFromBackground
  };
  // The bake: what changes with the geometry, the material or a setting.
  bool bake(const StepContext& context, const ActorInputs& actor, StepReport& report,
    BakeProgress& progress, std::string& error);
  // What bake() does before the strategy's own bake: the local surfels, the dipole, the
  // strategy for the settings.
  bool begin_bake(const StepContext& context, const ActorInputs& actor, std::string& error);

  std::unique_ptr<Gpu> gpu_;
  Material material_;
  BakeInputs baked_inputs_;  // geometry_time 0: every step runs at the next update
  BackgroundBake background_;
  BakeInputs background_inputs_;  // of background_'s run
  std::vector<GpuLight> lights_;
  bool baked_ = false;       // the bake is that of baked_inputs_
  bool valid_ = false;       // B is that of lights_
  bool unfinished_ = false;  // the light move to lights_ stopped at its time (StepContext)
  StepReport unfinished_move_;  // its report so far
  // A bake that ended its frame (BakeProgress::DoneFromBackground): the report the next light
  // move starts from.
  std::optional<StepReport> bake_report_;
};

}

#endif
