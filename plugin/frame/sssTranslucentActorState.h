// One translucent actor in a vtkSubsurfacePass: which steps its changed inputs call for, and
// their order. The steps live in their own rooms: the light maps (step 1, sssLightMaps), step 2
// (the strategy's, sssKernelStrategies: sssNearFarStrategy or the paper's
// sssPaperStrategy) and the hand-over of each surfel's B to the view (sssSurfelResolve).
#ifndef sssTranslucentActorState_h
#define sssTranslucentActorState_h

#include "dipole.h"
#include "material.h"
#include "quality_settings.h"
#include "sssLightMaps.h"
#include "sssKernelStrategies.h"
#include "sssSurfelBuffers.h"
#include "sssSurfelPreparation.h"

#include "vtkNew.h"
#include "vtkSmartPointer.h"
#include "vtkType.h"

#include <Eigen/Core>
#include <memory>
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
  // that stopped at the context's seconds: report.unfinished) when they did not. Returns false
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
  // Whether the bake is that of these surfels, material and settings.
  bool geometry_current(const StepContext& context, const ActorInputs& actor) const;
  // The bake: what changes with the geometry, the material or a setting.
  bool bake(const StepContext& context, const ActorInputs& actor, StepReport& report,
    std::string& error);

  std::unique_ptr<Gpu> gpu_;
  Material material_;
  std::vector<double> material_key_;
  vtkMTimeType geometry_time_ = 0;  // the buffers' upload
  QualitySettings geometry_settings_;
  bool geometry_albedo_ = false;
  std::vector<GpuLight> lights_;
  bool baked_ = false;       // the bake is that of geometry_time_, material_key_, ...
  bool valid_ = false;       // B is that of lights_
  bool unfinished_ = false;  // the light move to lights_ stopped at its time (StepContext)
  StepReport unfinished_move_;  // its report so far
};

}

#endif
