/**
 * @class vtkSubsurfacePass
 * @brief Subsurface scattering for translucent surfel actors (Oda et al. 2005, extended).
 *
 * Renders its delegate (the usual camera/sequence passes) into a float image and composites
 * it into the output. Actors that carry a vtkTranslucentMaterial and draw with a
 * vtkSurfelMapper get, in three steps:
 *  1. a light map from every switched-on light of the renderer (up to GetMaxLights(), 5: a
 *     ParaView view's headlight and light kit; beyond, the first five): orthographic along
 *     a directional light, perspective from a positional one (a point light, or a spot below
 *     a cone angle of 90 degrees, its irradiance falling off with VTK's attenuation values and
 *     exponent; one among the points is taken as directional, from its focal point, with a
 *     warning): the discs the light sees, lifted onto their local surfaces;
 *  2. B (eq. 17) at every surfel. Each surfel stands for its cell (the part of the surface
 *     nearer to it than to any other surfel) lit with the irradiance of eq. 15 averaged over
 *     CellSamples points of the cell, so shadow edges resolve below the surfel size. The near
 *     field (out to two disc radii) comes from a table of weights on the neighbours' irradiance
 *     that only the geometry and the material change; the far field, where the kernel reaches
 *     farther, from a walk of the lit cells' pyramid. The CPU reference
 *     (core/reference/reference_renderer.h) computes the same model at higher precision;
 *  3. the camera view: Lo = Ft(eta, wo) B per surfel (eq. 14), tone mapped in the composite.
 * The table is rebuilt when the geometry, the material or a setting changes; steps 1-2 run
 * when a light changes; a camera move runs step 3 alone. Other actors draw as before.
 *
 * KernelStrategy PAPER is the paper's method for comparison: 49 Gaussian taps in a 40 x 40
 * window of a 512 x 512 map at 64^3 grid points, interpolated trilinearly.
 */
#ifndef vtkSubsurfacePass_h
#define vtkSubsurfacePass_h

#include "sssTranslucencyModule.h"

#include "vtkImageProcessingPass.h"
#include "vtkSurfelMapper.h"

#include <memory>
#include <string>

class vtkOpenGLRenderWindow;
class vtkRenderer;
namespace sss
{
struct StepReport;
}

class vtkActor;
class vtkFloatArray;
class vtkSubsurfacePieces;

class SSSTRANSLUCENCY_EXPORT vtkSubsurfacePass
  : public vtkImageProcessingPass
#ifndef __VTK_WRAP__
  , public vtkSurfelMapper::RadianceSource
#endif
{
public:
  static vtkSubsurfacePass* New();
  vtkTypeMacro(vtkSubsurfacePass, vtkImageProcessingPass);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /** The most lights that light translucent actors (5); the renderer's first ones are taken. */
  static int GetMaxLights();

  enum KernelStrategies
  {
    PAPER = 0,
    NEAR_FAR = 1
  };

  ///@{
  /** How B is summed (see the class comment). Default NEAR_FAR. */
  vtkSetClampMacro(KernelStrategy, int, PAPER, NEAR_FAR);
  vtkGetMacro(KernelStrategy, int);
  void SetKernelStrategyToPaper() { this->SetKernelStrategy(PAPER); }
  void SetKernelStrategyToNearFar() { this->SetKernelStrategy(NEAR_FAR); }
  /** "paper" or "near-far". */
  const char* GetKernelStrategyAsString();
  /** Sets the strategy by its name; returns false (and changes nothing) for an unknown one. */
  bool SetKernelStrategyByName(const std::string& name);
  ///@}

  ///@{
  /**
   * Named presets of the settings below (and NEAR_FAR): "interactive" (16 cell samples,
   * maps of at most 2048 texels, opening angle 0.6), "balanced" (the defaults) and "accurate"
   * (128 cell samples, opening angle 0.3). Costs and errors of each: docs/benchmark/bench.md.
   * SetQualityPreset returns false (and changes nothing) for an unknown name;
   * GetQualityPresetAsString returns "" when the settings match no preset.
   */
  bool SetQualityPreset(const std::string& name);
  std::string GetQualityPresetAsString();
  ///@}

  ///@{
  /**
   * Light maps: texel edge over the surfel disc radius (default 0.0625, as the reference's, so
   * each cell is many texels across) and the largest map side (default 4096; a larger scene
   * gets coarser texels). NEAR_FAR's map holds which surfel each texel sees (8 bytes a texel
   * and 4 of depth: 192 MiB per light at 4096 x 4096). PAPER always uses a 512 x 512 map.
   */
  vtkSetClampMacro(TexelPerRadius, double, 0.01, 16.0);
  vtkGetMacro(TexelPerRadius, double);
  vtkSetClampMacro(MaxMapSize, int, 16, 16384);
  vtkGetMacro(MaxMapSize, int);
  ///@}

  ///@{
  /**
   * Points of each cell whose light the map is asked for, per light (default 64); eight times
   * as many where they disagree (a shadow edge or the terminator crosses the cell). Fewer miss
   * thin lit or shadowed slivers: 16 put the dragon's p99 error at 13 % against 4 %.
   */
  vtkSetClampMacro(CellSamples, int, 1, 256);
  vtkGetMacro(CellSamples, int);
  ///@}

  ///@{
  /**
   * Far field: a group of cells counts as one source once its spread (twice the RMS distance
   * of its cells from their mean) is below this fraction of its distance (default 0.4; smaller
   * is more accurate and slower), and only while it spans at most MaxGroupDiffusionLengths
   * diffusion lengths (1 / s_tr) of every channel whose kernel still matters at its distance
   * (default 4).
   */
  vtkSetClampMacro(OpeningAngle, double, 0.05, 2.0);
  vtkGetMacro(OpeningAngle, double);
  vtkSetClampMacro(MaxGroupDiffusionLengths, double, 0.1, VTK_DOUBLE_MAX);
  vtkGetMacro(MaxGroupDiffusionLengths, double);
  ///@}

  ///@{
  /** PAPER: 2^GridLevel virtual points per axis (default 0: the paper's 64). */
  vtkSetClampMacro(GridLevel, int, 0, 10);
  vtkGetMacro(GridLevel, int);
  ///@}

  ///@{
  /** Tone mapping of translucent pixels: sRGB(clamp(Exposure * Lo)). Default 1. */
  vtkSetClampMacro(Exposure, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(Exposure, double);
  ///@}

  ///@{
  /** Keep the last frame's linear radiance (translucent pixels; 0 elsewhere). Default off. */
  vtkSetMacro(CaptureLinearImage, bool);
  vtkGetMacro(CaptureLinearImage, bool);
  vtkBooleanMacro(CaptureLinearImage, bool);
  ///@}

  /**
   * The last captured linear image: 3 components, width * height tuples, bottom row first.
   * Empty unless CaptureLinearImage was on.
   */
  vtkFloatArray* GetLinearImage();
  int GetLinearImageWidth() const { return this->LinearWidth; }
  int GetLinearImageHeight() const { return this->LinearHeight; }

  /**
   * The q-quantile (q in [0, 1]) of the largest channel of Lo over the translucent pixels of
   * the last captured frame; 0 when nothing was captured. 1 / GetLinearImageQuantile(0.995) is
   * an exposure that shows the visible surface without clipping more than 0.5 % of it.
   */
  double GetLinearImageQuantile(double q);

  /**
   * B (eq. 17, radiance before the exit Fresnel term) of each input point of a translucent
   * actor rendered in the last frame, in input order; NaN for points left out. Returns false
   * when the actor has no result.
   */
  bool GetSurfelRadiance(vtkActor* actor, vtkFloatArray* B);

  /**
   * Whether the pass gives this actor's surfels their radiance in the frame being drawn (the
   * actor carries a material and its steps are ready): vtkSurfelMapper then draws them as
   * translucent, with the pass's shader replacements.
   */
#ifdef __VTK_WRAP__
  bool GivesRadianceTo(vtkActor* actor);
#else
  bool GivesRadianceTo(vtkActor* actor) override;  // vtkSurfelMapper::RadianceSource
#endif

  /**
   * Shows the given B per input point (3 components, e.g. from the CPU reference) for this
   * actor instead of computing it; nullptr goes back to computing. Points left out by the
   * mapper are skipped.
   */
  void SetPrecomputedRadiance(vtkActor* actor, vtkFloatArray* B);

  ///@{
  /**
   * The other pieces of a cloud split over processes (vtkSubsurfacePieces): each light map is
   * then fitted over all pieces and keeps the surface nearest the light over all of them, so
   * that a piece in front of another shadows it. Positional lights are then taken as
   * directional. Default none: the renderer's actors are the whole scene.
   */
  void SetPieces(vtkSubsurfacePieces* pieces);
  vtkSubsurfacePieces* GetPieces();
  ///@}

  /**
   * Runs steps 1-2 for the renderer's visible translucent actors now (the window's context
   * must exist: after its first render); the next Render then only draws. With pieces, every
   * process must call it before each frame: the reductions over pieces are collective, and a
   * compositing pass (IceT) renders only the processes whose piece it sees, so they cannot
   * happen inside Render, which without it draws translucent actors plain.
   */
  void PrepareFrame(vtkRenderer* renderer);

  /**
   * Runs steps 1-2 for the renderer's visible translucent actors as a frame would, without
   * drawing one: with refinement, the next part when IsRefinementPartDue(). Unlike PrepareFrame,
   * the next Render runs its own steps (a change made meanwhile is drawn), so an application can
   * run the parts between its frames and draw when it likes. Not with pieces.
   */
  void RunRefinementPart(vtkRenderer* renderer);

  ///@{
  /**
   * Refinement (default off): a frame whose lights, material or geometry changed shows B from
   * the 2005 paper's method first (its light move costs a few frames of plain points; it is
   * tens of percent off at the default's scales, docs/benchmark/bench.md). The frames drawn
   * once the inputs have not changed for RefinementRestSeconds (default 0.3) compute B at the
   * settings above, a part each: the light map, the cells and the near field in the first, then
   * the far field for about RefinementFrameSeconds (default 0.1) a frame (at least one of its
   * parts: a walk root's sum over a band of receivers, the bands narrowed to that time as they
   * are measured; with 0, one root's over every receiver), and the last shows it. Until then
   * every frame (a camera move, an overlay's update) shows the preview. An application keeps
   * rendering while GetRefinementPending() is true and its input rests, or runs the parts with
   * RunRefinementPart between its frames when IsRefinementPartDue() says one is due, drawing
   * only when it likes (the last part's B shows in the next frame): a frame drawn for nothing
   * redraws the preview and takes processor time from the parts and the bake's thread. A bake (new geometry, material or settings) runs its CPU part (the cells
   * and the near-field table's weights, most of its time) on a thread of its own meanwhile, and
   * its uploads in the first frame that finds it done. Each method keeps its own bake. Off with
   * pieces: there every frame is refined.
   */
  vtkSetMacro(Refinement, bool);
  vtkGetMacro(Refinement, bool);
  vtkBooleanMacro(Refinement, bool);
  vtkSetClampMacro(RefinementRestSeconds, double, 0.0, 3600.0);
  vtkGetMacro(RefinementRestSeconds, double);
  vtkSetClampMacro(RefinementFrameSeconds, double, 0.0, 3600.0);
  vtkGetMacro(RefinementFrameSeconds, double);
  ///@}

  /** Whether the last frame showed a preview that later frames at rest refine. */
  vtkGetMacro(RefinementPending, bool);
  /**
   * Whether the last frame showed a preview whose refinement failed (reported as an error);
   * it stays, and is not pending, until the inputs change.
   */
  vtkGetMacro(RefinementFailed, bool);
  /** While pending, the share of the refinement done (0 to 1); 1 otherwise. */
  vtkGetMacro(RefinedShare, double);
  /**
   * While pending, whether a bake's CPU part (new geometry, material or settings) still runs on
   * its thread; the refinement's light move starts once it is done (RefinedShare stays 0).
   */
  vtkGetMacro(RefinementPreparing, bool);
  /**
   * Whether a frame drawn now, with the inputs of the last, would take a pending refinement
   * further: the inputs have rested for RefinementRestSeconds and no bake's CPU part is still at
   * work on its thread. Unlike the values above, it is read live (between frames, with no
   * render), so that a loop can poll it and render only when it is true.
   */
  bool IsRefinementPartDue();
  /** The last preview's steps 1-2 in seconds (0 before the first; exact with MeasureStepTimes). */
  vtkGetMacro(LastPreviewSeconds, double);
  /**
   * The mean relative error (per point, as the benchmark measures it) of the last refined
   * preview against the B that replaced it: 0.01 is 1 %; negative before the first.
   */
  vtkGetMacro(LastPreviewError, double);

  ///@{
  /** Wait for the GPU after each step so the step times below are real (default off). */
  vtkSetMacro(MeasureStepTimes, bool);
  vtkGetMacro(MeasureStepTimes, bool);
  vtkBooleanMacro(MeasureStepTimes, bool);
  ///@}

  ///@{
  /**
   * Statistics: how often each step ran (the bake: the near-field table, on geometry,
   * material or setting changes), and what the last run of each measured. With refinement the
   * bake's seconds are its thread's plus those of the frame that made its uploads.
   */
  vtkGetMacro(BakeRuns, int);
  vtkGetMacro(IlluminationRuns, int);
  vtkGetMacro(SurfelRuns, int);
  vtkGetMacro(ViewRuns, int);
  vtkGetMacro(LastBakeSeconds, double);
  vtkGetMacro(LastIlluminationSeconds, double);
  vtkGetMacro(LastSurfelSeconds, double);
  vtkGetMacro(LastViewSeconds, double);
  /**
   * NEAR_FAR, the last light move by step, within LastSurfelSeconds (the light map's is
   * LastIlluminationSeconds): lighting the cells, the upward pass (the source pyramids), the
   * near field's table, the far field, and handing B to the view. Exact with
   * MeasureStepTimes on.
   */
  vtkGetMacro(LastCellSeconds, double);
  vtkGetMacro(LastPyramidSeconds, double);
  vtkGetMacro(LastNearFieldSeconds, double);
  vtkGetMacro(LastFarFieldSeconds, double);
  vtkGetMacro(LastHandOverSeconds, double);
  /** The last light move by step in one line: "map 0.11 s, cells 0.21 s, ...". */
  std::string GetLastLightMoveProfile() const;
  /** NEAR_FAR: the lit cells in the source pyramids (a cell lit on both sides is in both;
   * 0 where the kernel ends inside the near-field table: no far field, no pyramid). */
  vtkGetMacro(LastLitCells, vtkIdType);
  /** NEAR_FAR: the cells whose first samples disagreed for some light (a shadow edge or the
   * terminator crosses them), lit again with eight times as many for those lights. */
  vtkGetMacro(LastRefinedCells, vtkIdType);
  vtkGetMacro(LastSurfels, vtkIdType);
  vtkGetMacro(LastMapWidth, int);
  vtkGetMacro(LastMapHeight, int);
  vtkGetMacro(LastTexelMillimetres, double);
  /** NEAR_FAR: the near field's reach and where the far field starts (0: none), in mm. */
  vtkGetMacro(LastNearReachMillimetres, double);
  vtkGetMacro(LastFarFromMillimetres, double);
  /** NEAR_FAR: entries of the near-field table (16 bytes each on the GPU). */
  vtkGetMacro(LastNearFieldEntries, vtkIdType);
  /** PAPER: its grid. */
  vtkGetMacro(LastVirtualPoints, vtkIdType);
  vtkGetMacro(LastGridLevel, int);
  vtkGetMacro(LastGridSpacingMillimetres, double);
  /** Translucent actors drawn with subsurface scattering in the last frame. */
  vtkGetMacro(LastTranslucentActors, int);
  ///@}

  void Render(const vtkRenderState* s) override;
  void ReleaseGraphicsResources(vtkWindow* w) override;

  bool PreReplaceShaderValues(std::string& vertexShader, std::string& geometryShader,
    std::string& fragmentShader, vtkAbstractMapper* mapper, vtkProp* prop) override;
  bool SetShaderParameters(vtkShaderProgram* program, vtkAbstractMapper* mapper, vtkProp* prop,
    vtkOpenGLVertexArrayObject* VAO = nullptr) override;

protected:
  vtkSubsurfacePass();
  ~vtkSubsurfacePass() override;

  // Their defaults are core/settings/quality_settings.h's, set by the constructor.
  int KernelStrategy;
  double TexelPerRadius;
  int MaxMapSize;
  int CellSamples;
  double OpeningAngle;
  double MaxGroupDiffusionLengths;
  int GridLevel;
  double Exposure = 1.0;
  bool CaptureLinearImage = false;
  bool MeasureStepTimes = false;
  bool Refinement = false;
  double RefinementRestSeconds = 0.3;
  double RefinementFrameSeconds = 0.1;
  double RefinedShare = 1.0;
  bool RefinementPreparing = false;
  bool RefinementPending = false;
  bool RefinementFailed = false;
  double LastPreviewSeconds = 0;
  double LastPreviewError = -1;

  int BakeRuns = 0;
  int IlluminationRuns = 0;
  int SurfelRuns = 0;
  int ViewRuns = 0;
  double LastBakeSeconds = 0;
  double LastIlluminationSeconds = 0;
  double LastSurfelSeconds = 0;
  double LastViewSeconds = 0;
  double LastCellSeconds = 0;
  double LastPyramidSeconds = 0;
  double LastNearFieldSeconds = 0;
  double LastFarFieldSeconds = 0;
  double LastHandOverSeconds = 0;
  vtkIdType LastLitCells = 0;
  vtkIdType LastRefinedCells = 0;
  vtkIdType LastSurfels = 0;
  int LastMapWidth = 0;
  int LastMapHeight = 0;
  double LastTexelMillimetres = 0;
  double LastNearReachMillimetres = 0;
  double LastFarFromMillimetres = 0;
  vtkIdType LastNearFieldEntries = 0;
  vtkIdType LastVirtualPoints = 0;
  int LastGridLevel = 0;
  double LastGridSpacingMillimetres = 0;
  int LastTranslucentActors = 0;
  int LinearWidth = 0;
  int LinearHeight = 0;

private:
  vtkSubsurfacePass(const vtkSubsurfacePass&) = delete;
  void operator=(const vtkSubsurfacePass&) = delete;

  struct Internals;
  std::unique_ptr<Internals> Impl;

  // Steps 1-2 for the renderer's visible translucent actors, outside Render (PrepareFrame,
  // RunRefinementPart: `caller` names it in the error); false without an OpenGL window.
  bool RunSteps(vtkRenderer* ren, const char* caller);
  // The steps of Render, in order.
  // The renderer's switched-on lights into Impl (world frame).
  void GatherLights(vtkRenderer* ren);
  // Steps 1-2 for every visible translucent actor whose inputs changed; fills Impl->Ready.
  void UpdateTranslucentActors(const vtkRenderState* s, vtkOpenGLRenderWindow* window);
  // Step 3: the delegate draws the scene into the float image, translucent surfels taking B
  // through this pass's shader hooks.
  void RenderScene(const vtkRenderState* s, vtkOpenGLRenderWindow* window, int width, int height);
  // The float image into the output, tone mapping translucent pixels, with depth.
  bool Composite(vtkOpenGLRenderWindow* window, int width, int height, int x0, int y0);
  // The statistics of one actor's steps.
  void Record(const sss::StepReport& report);
};

#endif
