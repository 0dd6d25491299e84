/**
 * @class vtkSubsurfacePass
 * @brief Subsurface scattering for translucent surfel actors (Oda et al. 2005, extended).
 *
 * Renders its delegate (the usual camera/sequence passes) into a float image and composites
 * it into the output. Actors that carry a vtkTranslucentMaterial and draw with a
 * vtkSurfelMapper get, in three steps:
 *  1. an illumination map from every switched-on light of the renderer (treated as
 *     directional, from its focal point towards its position), with E dA per texel (eq. 15),
 *     and a pyramid of it;
 *  2. B (eq. 17) at the pruned virtual grid points, into a 3-D texture, and at every surfel
 *     (the near part of the kernel, or all of it, plus the grid's trilinear far part);
 *  3. the camera view: Lo = Ft(eta, wo) B per surfel (eq. 14), tone mapped in the composite.
 * Steps 1-2 run only when a light, the geometry, the material or a setting changed; a camera
 * move runs step 3 alone. Other actors draw as before.
 *
 * The kernel strategy chooses how B is summed (KernelStrategy): PAPER is the paper's 49
 * Gaussian taps over a 40 x 40 window of a 512 x 512 map at the grid points; GRID (the
 * default) walks the map's pyramid at the virtual points, each moved onto the surface along
 * its nearest surfel's normal (grid alone); GRID_NEAR carries the far part on the grid and
 * sums the near part at each surfel; SURFEL walks the pyramid at every surfel. All sums
 * reach as far as the material's kernel does (1e-7 of its integral).
 *
 * The defaults (GRID, 512 map, opening angle 2, no group limit, at most 16384 virtual
 * points) cost what the paper's setting costs and are more accurate than it (about 15-30 %
 * mean error on the Stanford bunny against the paper's 23-35 %); SURFEL with a 4096 map,
 * opening angle 0.5 and groups of 2 diffusion lengths is under 1 % at 15-30 times the cost
 * of a light change (docs/benchmark/bench.md).
 */
#ifndef vtkSubsurfacePass_h
#define vtkSubsurfacePass_h

#include "sssTranslucencyModule.h"

#include "vtkImageProcessingPass.h"

#include <memory>

class vtkActor;
class vtkFloatArray;

class SSSTRANSLUCENCY_EXPORT vtkSubsurfacePass : public vtkImageProcessingPass
{
public:
  static vtkSubsurfacePass* New();
  vtkTypeMacro(vtkSubsurfacePass, vtkImageProcessingPass);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum KernelStrategies
  {
    PAPER = 0,
    GRID = 1,
    GRID_NEAR = 2,
    SURFEL = 3,
    NEAR_FAR = 4
  };

  ///@{
  /** How B is summed (see the class comment). Default NEAR_FAR. */
  vtkSetClampMacro(KernelStrategy, int, PAPER, NEAR_FAR);
  vtkGetMacro(KernelStrategy, int);
  ///@}

  ///@{
  /**
   * Pyramid walk: a group of map texels counts as one source once its size is below this
   * fraction of its distance (default 2; smaller is more accurate and slower).
   */
  vtkSetClampMacro(OpeningAngle, double, 0.05, 2.0);
  vtkGetMacro(OpeningAngle, double);
  ///@}

  ///@{
  /**
   * Pyramid walk: a group also counts as one source only while it spans at most this many
   * diffusion lengths (1 / s_tr) of every channel whose kernel still matters at its distance;
   * over more, the kernel's exponential leaves its second-order expansion (default 1000: no
   * limit in practice; 2 keeps strongly absorbing channels accurate at a fine setting).
   */
  vtkSetClampMacro(MaxGroupDiffusionLengths, double, 0.1, VTK_DOUBLE_MAX);
  vtkGetMacro(MaxGroupDiffusionLengths, double);
  ///@}

  ///@{
  /**
   * NEAR_FAR: the near field's quadrature on each surfel's local surface: this many rings,
   * each holding an equal share of the kernel's near integral (default 8), with at most
   * NearFieldNodes nodes on each (default 8; at least 4).
   */
  vtkSetClampMacro(NearFieldRings, int, 1, 32);
  vtkGetMacro(NearFieldRings, int);
  vtkSetClampMacro(NearFieldNodes, int, 1, 64);
  vtkGetMacro(NearFieldNodes, int);
  ///@}

  ///@{
  /**
   * GRID_NEAR: the kernel is split between r0 = NearFieldCells grid spacings and 2 r0
   * (default 2).
   */
  vtkSetClampMacro(NearFieldCells, double, 0.5, 8.0);
  vtkGetMacro(NearFieldCells, double);
  ///@}

  ///@{
  /**
   * Virtual grid: 2^GridLevel points per axis; 0 (default) chooses from the material's
   * diffusion length and a budget of 16384 kept points; for PAPER, the paper's 64 per axis.
   */
  vtkSetClampMacro(GridLevel, int, 0, 10);
  vtkGetMacro(GridLevel, int);
  ///@}

  ///@{
  /**
   * Illumination map texel as a fraction of the material's smallest z_r (default 0.25), and
   * the largest map side (default 512). PAPER always uses a 512 x 512 map.
   */
  vtkSetClampMacro(TexelPerZr, double, 0.01, 64.0);
  vtkGetMacro(TexelPerZr, double);
  vtkSetClampMacro(MaxMapSize, int, 16, 16384);
  vtkGetMacro(MaxMapSize, int);
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
   * Shows the given B per input point (3 components, e.g. from the CPU reference) for this
   * actor instead of computing it; nullptr goes back to computing. Points left out by the
   * mapper are skipped.
   */
  void SetPrecomputedRadiance(vtkActor* actor, vtkFloatArray* B);

  ///@{
  /** Wait for the GPU after each step so the step times below are real (default off). */
  vtkSetMacro(MeasureStepTimes, bool);
  vtkGetMacro(MeasureStepTimes, bool);
  vtkBooleanMacro(MeasureStepTimes, bool);
  ///@}

  ///@{
  /** Statistics: how often each step ran, and what the last run of each measured. */
  vtkGetMacro(IlluminationRuns, int);
  vtkGetMacro(VirtualPointRuns, int);
  vtkGetMacro(SurfelRuns, int);
  vtkGetMacro(ViewRuns, int);
  vtkGetMacro(LastIlluminationSeconds, double);
  vtkGetMacro(LastVirtualPointSeconds, double);
  vtkGetMacro(LastSurfelSeconds, double);
  vtkGetMacro(LastViewSeconds, double);
  vtkGetMacro(LastLitSamples, vtkIdType);
  vtkGetMacro(LastVirtualPoints, vtkIdType);
  vtkGetMacro(LastSurfels, vtkIdType);
  vtkGetMacro(LastMapWidth, int);
  vtkGetMacro(LastMapHeight, int);
  vtkGetMacro(LastTexelMillimetres, double);
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

  int KernelStrategy = NEAR_FAR;
  double OpeningAngle = 2.0;
  double MaxGroupDiffusionLengths = 1000.0;
  double NearFieldCells = 2.0;
  int NearFieldRings = 8;
  int NearFieldNodes = 8;
  int GridLevel = 0;
  double TexelPerZr = 0.25;
  int MaxMapSize = 512;
  double Exposure = 1.0;
  bool CaptureLinearImage = false;
  bool MeasureStepTimes = false;

  int IlluminationRuns = 0;
  int VirtualPointRuns = 0;
  int SurfelRuns = 0;
  int ViewRuns = 0;
  double LastIlluminationSeconds = 0;
  double LastVirtualPointSeconds = 0;
  double LastSurfelSeconds = 0;
  double LastViewSeconds = 0;
  vtkIdType LastLitSamples = 0;
  vtkIdType LastVirtualPoints = 0;
  vtkIdType LastSurfels = 0;
  int LastMapWidth = 0;
  int LastMapHeight = 0;
  double LastTexelMillimetres = 0;
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
};

#endif
