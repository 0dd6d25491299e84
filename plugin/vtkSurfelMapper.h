/**
 * @class vtkSurfelMapper
 * @brief Draws a vtkPolyData's points as oriented discs (surfels), blended into a closed surface.
 *
 * Each point with a finite position and normal becomes a disc in the plane its normal defines.
 * Discs are expanded on the GPU into quads that lie in that plane, so depth is exact and there
 * is no point-size limit at close zoom. The radius is chosen so that the discs close the
 * surface (a measured coverage target, see SetCoverageTarget), one per point where the density
 * varies. By default overlapping discs are blended (Botsch and Kobbelt's splatting): a
 * visibility pass keeps the depth of the front surface, pushed back by a fraction of the
 * radius; an accumulation pass adds the colour and normal of every disc within that offset,
 * weighted by a Gaussian of the distance to its centre, and each pixel's largest coverage by
 * a disc; a normalisation pass divides by the weights, shades with the blended normal and
 * writes colour and the front surface's depth, so opaque actors in the same renderer stay in
 * front or behind as they should. Silhouettes fade over a pixel by that coverage (translucent
 * ones in vtkSubsurfacePass's composite). SetSplattingToDiscs draws hard discs with a depth
 * test instead. On its own the mapper shades discs with a two-sided Lambert term under a
 * headlight, using point colours (ScalarVisibility) or the actor's colour. With a
 * vtkTranslucentMaterial on the actor and a vtkSubsurfacePass in the renderer,
 * the pass supplies each surfel's radiance instead (it follows vtkOpenGLRenderPass's shader
 * replacement protocol). Cells are ignored: every point is a surfel.
 *
 * Points need 3-component point normals; points with a non-finite position or normal, or a
 * zero normal, are left out (the report says how many). Points that VTK's ghost array
 * (vtkGhostType) marks DUPLICATEPOINT belong to another piece of a distributed cloud: they
 * are lit and scatter light to the others, and in blended splatting they hide what lies
 * behind them and cover pixels (so that the piece's edge is not faded like a silhouette), but
 * they give no colour: the rank that owns them draws them.
 */
#ifndef vtkSurfelMapper_h
#define vtkSurfelMapper_h

#include "sssTranslucencyModule.h"

#include "vtkPolyDataMapper.h"

#include <memory>
#include <string>

class vtkOpenGLRenderWindow;
class vtkShaderProgram;

namespace sss
{
struct PreparedSurfels;
struct SurfelBuffers;
struct SplatView;
}

class SSSTRANSLUCENCY_EXPORT vtkSurfelMapper : public vtkPolyDataMapper
{
public:
  static vtkSurfelMapper* New();
  vtkTypeMacro(vtkSurfelMapper, vtkPolyDataMapper);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * Disc radius in scene units, for the view, the pass's light maps and its cells. 0 (the
   * default) finds the radius that closes the surface: each point's cell (its Voronoi cell
   * among its neighbours in its tangent plane) is measured, and the radius is the smallest
   * that leaves at most CoverageTarget of the cells' area uncovered, times RadiusScale; the
   * light maps draw the same discs (never under GetCellRadius) and each cell reaches to its
   * disc. The pass's scale (its texels and near field) then takes 1.5 mean nearest-neighbour
   * spacings (GetCellRadius).
   */
  vtkSetClampMacro(Radius, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(Radius, double);
  ///@}

  ///@{
  /** Multiplies the automatic radius (default 1). */
  vtkSetClampMacro(RadiusScale, double, 0.01, 100.0);
  vtkGetMacro(RadiusScale, double);
  ///@}

  ///@{
  /**
   * The fraction of the surface the automatic radius may leave uncovered (default 1e-4). A
   * random sampling needs about 3.4 mean spacings for it, a regular grid 0.6 to 0.7.
   */
  vtkSetClampMacro(CoverageTarget, double, 0.0, 0.5);
  vtkGetMacro(CoverageTarget, double);
  ///@}

  enum RadiusModes
  {
    AUTOMATIC = 0,  // per point where the local spacing spreads (p90 / p10 above 1.6) or a
                    // few large cells would set the uniform radius (over 2.5x the one at 5 %)
    UNIFORM = 1,
    PER_POINT = 2,
  };
  ///@{
  /** Whether each point gets its own radius (its cell's farthest corner, plus 5 %) in the view. */
  vtkSetClampMacro(RadiusMode, int, AUTOMATIC, PER_POINT);
  vtkGetMacro(RadiusMode, int);
  void SetRadiusModeToAutomatic() { this->SetRadiusMode(AUTOMATIC); }
  void SetRadiusModeToUniform() { this->SetRadiusMode(UNIFORM); }
  void SetRadiusModeToPerPoint() { this->SetRadiusMode(PER_POINT); }
  const char* GetRadiusModeAsString();
  ///@}

  ///@{
  /**
   * A point-data array (one component, scene units) that gives each point its radius in the
   * view; empty (the default) for none.
   */
  vtkSetStdStringFromCharMacro(RadiusArrayName);
  vtkGetCharFromStdStringMacro(RadiusArrayName);
  ///@}

  enum SplattingModes
  {
    BLENDED = 0,
    DISCS = 1,
  };
  ///@{
  /** Blended splats (the default) or hard discs. */
  vtkSetClampMacro(Splatting, int, BLENDED, DISCS);
  vtkGetMacro(Splatting, int);
  void SetSplattingToBlended() { this->SetSplatting(BLENDED); }
  void SetSplattingToDiscs() { this->SetSplatting(DISCS); }
  const char* GetSplattingAsString();
  ///@}

  ///@{
  /**
   * How far behind the front surface blended discs still count, in disc radii (default 0.5):
   * enough for the overlapping discs of one surface, less than the gap to the next.
   */
  vtkSetClampMacro(BlendDepth, double, 0.0, 10.0);
  vtkGetMacro(BlendDepth, double);
  ///@}

  /**
   * The view's radius (scene units) after the last update, the median with per-point radii;
   * 0 before the first.
   */
  double GetEffectiveRadius();

  /**
   * The radius that sets the pass's scale (scene units): light-map texels are TexelPerRadius
   * of it, the near field reaches two of it, and every cell reaches at least to it. Radius
   * when set, else 1.5 mean nearest-neighbour spacings (times RadiusScale).
   */
  double GetCellRadius();

  /** Whether the last update gave each point its own radius in the view. */
  bool GetUsesPerPointRadii();

  /** The measured uncovered fraction at the automatic uniform radius (0 when it was set). */
  double GetUncoveredFraction();

  /** Surfels drawn: input points with a finite position and normal. */
  vtkIdType GetNumberOfSurfels();

  /** Why nothing is drawn (no points, no normals), or an empty string. */
  std::string GetInputProblem();

  void RenderPiece(vtkRenderer* ren, vtkActor* act) override;
  void ReleaseGraphicsResources(vtkWindow* window) override;

#ifndef __VTK_WRAP__
  /**
   * What a render pass declares when it gives the surfels their radiance (vtkSubsurfacePass
   * does): for the actors it names, the mapper draws the surfels as translucent, with the
   * pass's shader replacements (vtkOpenGLRenderPass's protocol).
   */
  class RadianceSource
  {
  public:
    virtual ~RadianceSource() = default;
    virtual bool GivesRadianceTo(vtkActor* actor) = 0;
  };

  /**
   * Brings the prepared surfels up to date with the input and returns them (for the pass).
   * Positions stay in scene units; the GPU buffers hold them relative to the bounds centre.
   */
  const sss::PreparedSurfels& UpdateSurfels(vtkActor* act);
  /**
   * Brings the prepared surfels and their vertex buffers up to date (the buffers the views
   * from the lights share; needs the window's context current) and returns the buffers.
   */
  const sss::SurfelBuffers& UpdateBuffers(vtkActor* act);
#endif

protected:
  vtkSurfelMapper();
  ~vtkSurfelMapper() override;

  double Radius = 0.0;
  double RadiusScale = 1.0;
  double CoverageTarget;  // core/view/splat_coverage.h's default, set by the constructor
  int RadiusMode = AUTOMATIC;
  std::string RadiusArrayName;
  int Splatting = BLENDED;
  double BlendDepth = 0.5;

private:
#ifndef __VTK_WRAP__
  // The draws of a frame, as VTK's point mappers split them: the buffers are built in
  // Internals; each draw readies its shaders (the passes' replacements) and draws.
  vtkShaderProgram* ReadySplatProgram(
    vtkOpenGLRenderWindow* renWin, vtkActor* act, int splatPass, const sss::SplatView& view);
  bool DrawSplats(
    vtkOpenGLRenderWindow* renWin, vtkActor* act, int splatPass, const sss::SplatView& view);
  // Blended splatting: visibility, accumulation, then Normalise; false when the scene's depth
  // cannot be copied (the caller draws hard discs).
  bool DrawBlended(vtkOpenGLRenderWindow* renWin, vtkActor* act, const sss::SplatView& view);
  void Normalise(vtkOpenGLRenderWindow* renWin, vtkActor* act, const sss::SplatView& view);
#endif

  vtkSurfelMapper(const vtkSurfelMapper&) = delete;
  void operator=(const vtkSurfelMapper&) = delete;

  struct Internals;
  std::unique_ptr<Internals> Impl;
};

#endif
