/**
 * @class vtkTranslucentMaterial
 * @brief Optical coefficients of a translucent medium, attached to an actor.
 *
 * An actor that carries a vtkTranslucentMaterial (ApplyTo) and draws with a vtkSurfelMapper is
 * rendered with subsurface scattering by a vtkSubsurfacePass in its renderer. Coefficients are
 * per RGB channel in 1/mm (Jensen et al. 2001); MillimetresPerUnit says how long one scene unit
 * is (1000 for a scan in metres). Defaults: the "marble" preset, eta 1.3, 1 mm per unit.
 */
#ifndef vtkTranslucentMaterial_h
#define vtkTranslucentMaterial_h

#include "sssTranslucencyModule.h"

#include "vtkObject.h"

#include <string>

class vtkInformationObjectBaseKey;
class vtkProp;

class SSSTRANSLUCENCY_EXPORT vtkTranslucentMaterial : public vtkObject
{
public:
  static vtkTranslucentMaterial* New();
  vtkTypeMacro(vtkTranslucentMaterial, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * Loads a measured preset (apple, chicken1, chicken2, cream, ketchup, marble, potato,
   * skimmilk, skin1, skin2, spectralon, wholemilk) and keeps the current eta and scale.
   * Returns false, with an error naming the known presets, for an unknown name.
   */
  bool SetPreset(const char* name);
  const char* GetName() const { return this->Name.c_str(); }

  ///@{
  /** Absorption coefficient sigma_a, 1/mm per channel. Setting it makes the material custom. */
  void SetSigmaA(double r, double g, double b);
  vtkGetVector3Macro(SigmaA, double);
  ///@}

  ///@{
  /** Reduced scattering coefficient sigma_s', 1/mm per channel. */
  void SetSigmaSPrime(double r, double g, double b);
  vtkGetVector3Macro(SigmaSPrime, double);
  ///@}

  ///@{
  /** Relative index of refraction (default 1.3). */
  vtkSetMacro(Eta, double);
  vtkGetMacro(Eta, double);
  ///@}

  ///@{
  /** Millimetres per scene unit (default 1). */
  vtkSetMacro(MillimetresPerUnit, double);
  vtkGetMacro(MillimetresPerUnit, double);
  ///@}

  ///@{
  /** Whether the mapper's point colours scale the light entering each point (default off). */
  vtkSetMacro(ColoursAsAlbedo, bool);
  vtkGetMacro(ColoursAsAlbedo, bool);
  vtkBooleanMacro(ColoursAsAlbedo, bool);
  ///@}

  /**
   * An empty string when the coefficients describe a physical medium; otherwise what is wrong
   * (negative or NaN coefficient, eta <= 0, sigma_t' = 0, scale <= 0).
   */
  std::string Validate() const;

  /**
   * How far the kernel reaches, in mm: beyond this distance the sources of every channel carry
   * less than 1e-7 of its integral (the distance past which the pass ignores them). 0 when the
   * material is invalid.
   */
  double GetKernelReachMillimetres() const;

  /** Marks the actor translucent with this material (replaces an earlier one). */
  void ApplyTo(vtkProp* prop);
  /** Removes the mark. */
  static void RemoveFrom(vtkProp* prop);
  /** The material a prop carries, or nullptr. */
  static vtkTranslucentMaterial* GetFrom(vtkProp* prop);

  /** The key under which props carry their material (in vtkProp::GetPropertyKeys). */
  static vtkInformationObjectBaseKey* MATERIAL();

protected:
  vtkTranslucentMaterial();
  ~vtkTranslucentMaterial() override = default;

  std::string Name;
  double SigmaA[3];
  double SigmaSPrime[3];
  double Eta;  // sss::kDefaultEta
  double MillimetresPerUnit = 1.0;
  bool ColoursAsAlbedo = false;

private:
  vtkTranslucentMaterial(const vtkTranslucentMaterial&) = delete;
  void operator=(const vtkTranslucentMaterial&) = delete;
};

#endif
