// Step 2 as a kernel strategy: what it bakes when the geometry, the material or a setting
// changes, what it asks of the light maps, what a light move runs, and how it hands each
// surfel's B to the view. The strategies are rows of one table (sssKernelStrategies.h).
#ifndef sssStrategy_h
#define sssStrategy_h

#include "cancel.h"
#include "quality_settings.h"
#include "sssLightMaps.h"

#include <functional>
#include <limits>
#include <memory>
#include <string>
#include <vector>

class vtkOpenGLBufferObject;
class vtkOpenGLRenderWindow;
class vtkSubsurfacePieces;
class vtkWindow;

namespace sss
{

class Dipole;
class SurfelResolve;
struct LocalSurfels;

// How a frame runs the steps of its translucent actors: the window (its context current), the
// pass's settings, whether to wait for the GPU after each step (so that the reported times are
// real) and the cloud's other pieces, or none.
struct StepContext
{
  vtkOpenGLRenderWindow* window = nullptr;
  QualitySettings settings;
  bool finish = false;
  vtkSubsurfacePieces* pieces = nullptr;
  // How long one call of Strategy::light may take before it leaves the rest to the next call
  // (infinite: all of it in one call), and whether this call goes on from the last one's
  // unfinished work (StepReport::unfinished) for the same light maps.
  double seconds = std::numeric_limits<double>::infinity();
  bool resume = false;
};

// What the steps of one update did and measured.
struct StepReport
{
  bool bake = false, illumination = false, surfels = false;
  double seconds_bake = 0, seconds_illumination = 0, seconds_surfels = 0;
  // Within seconds_surfels (NEAR_FAR), a light move by step: the cells' light, the upward
  // pass (the source pyramids), the near field's table, the far field, and the hand-over of B
  // to the view.
  double seconds_cells = 0, seconds_pyramid = 0, seconds_near = 0, seconds_far = 0,
         seconds_hand_over = 0;
  // refined_cells: those whose first points disagreed, lit again with more (sssLitCells).
  std::size_t lit_cells = 0, refined_cells = 0, virtual_point_count = 0, surfel_count = 0,
              near_entries = 0;
  int map_width = 0, map_height = 0, grid_level = 0;
  double texel_mm = 0, grid_spacing_mm = 0;
  double near_reach_mm = 0, far_from_mm = 0;  // near field out to, far field from (0: none)
  std::vector<std::string> notes;             // lights drawn otherwise than asked, and why
  // Strategy::light stopped at StepContext::seconds with this share of its work done; B is not
  // handed over yet.
  bool unfinished = false;
  double done_share = 1.0;

  // Adds a resumed call's times and its end (unfinished, done_share) to this report.
  void add_resumed(const StepReport& later)
  {
    seconds_surfels += later.seconds_surfels;
    seconds_near += later.seconds_near;
    seconds_far += later.seconds_far;
    seconds_hand_over += later.seconds_hand_over;
    unfinished = later.unfinished;
    done_share = later.done_share;
  }
};

// What a strategy's bake computes on the CPU alone (Strategy::bake_work).
class BakePreparation
{
public:
  virtual ~BakePreparation() = default;
  double seconds = 0.0;  // the work's, on its thread (sssBackgroundBake)
};
// Work that owns copies of its inputs and touches no GL: it may run on another thread. It
// throws std::exception when it cannot be done, Cancelled once `cancel` is set.
using BakeWork = std::function<std::unique_ptr<BakePreparation>(const CancelFlag& cancel)>;

class Strategy
{
public:
  virtual ~Strategy() = default;
  // `local` carries its surface fit and its albedo (none for white). With a preparation
  // adopted for these inputs, only what remains.
  virtual bool bake(const StepContext& context, const LocalSurfels& local,
    const Material& material, const Dipole& dipole, StepReport& report, std::string& error) = 0;
  // The CPU part of bake for `local` and `dipole` as work of its own, or none where the
  // strategy's bake has no such part worth a thread; its result goes to adopt() before bake().
  virtual BakeWork bake_work(const LocalSurfels& /*local*/, const Dipole& /*dipole*/) const
  {
    return {};
  }
  virtual void adopt(std::unique_ptr<BakePreparation> /*prepared*/) {}
  // What the light maps must hold for it (after its bake).
  virtual LightMapRequest light_map_request(const QualitySettings& settings) const = 0;
  // B for the maps just drawn, handed to `resolve` at the surfels' `positions`
  // (sssSurfelBuffers).
  virtual bool light(const StepContext& context, const GpuLightMaps& maps, const Dipole& dipole,
    SurfelResolve& resolve, vtkOpenGLBufferObject* positions, StepReport& report,
    std::string& error) = 0;
  virtual void release(vtkWindow* window) = 0;
};

}

#endif
