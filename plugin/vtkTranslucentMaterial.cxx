#include "vtkTranslucentMaterial.h"

#include "sssCoreMaterial.h"

#include "vtkInformation.h"
#include "vtkInformationObjectBaseKey.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkProp.h"

#include "dipole.h"
#include "material.h"

#include <stdexcept>

vtkStandardNewMacro(vtkTranslucentMaterial);
vtkInformationKeyMacro(vtkTranslucentMaterial, MATERIAL, ObjectBase);

vtkTranslucentMaterial::vtkTranslucentMaterial()
{
  this->SetPreset(sss::kDefaultPreset);
  this->Eta = sss::kDefaultEta;
}

bool vtkTranslucentMaterial::SetPreset(const char* name)
{
  try
  {
    const sss::Material preset = sss::Material::preset(name ? name : "");
    this->Name = preset.name;
    for (int c = 0; c < 3; ++c)
    {
      this->SigmaA[c] = preset.sigma_a[c];
      this->SigmaSPrime[c] = preset.sigma_s_prime[c];
    }
    this->Modified();
    return true;
  }
  catch (const std::invalid_argument& error)
  {
    vtkErrorMacro(<< error.what());
    return false;
  }
}

void vtkTranslucentMaterial::SetSigmaA(double r, double g, double b)
{
  this->SigmaA[0] = r;
  this->SigmaA[1] = g;
  this->SigmaA[2] = b;
  this->Name = "custom";
  this->Modified();
}

void vtkTranslucentMaterial::SetSigmaSPrime(double r, double g, double b)
{
  this->SigmaSPrime[0] = r;
  this->SigmaSPrime[1] = g;
  this->SigmaSPrime[2] = b;
  this->Name = "custom";
  this->Modified();
}

sss::Material sss::core_material(const vtkTranslucentMaterial& material)
{
  auto& from = const_cast<vtkTranslucentMaterial&>(material);  // VTK's getters are not const
  sss::Material m;
  m.name = from.GetName();
  for (int c = 0; c < 3; ++c)
  {
    m.sigma_a[c] = from.GetSigmaA()[c];
    m.sigma_s_prime[c] = from.GetSigmaSPrime()[c];
    m.eta[c] = from.GetEta();
  }
  m.mm_per_unit = from.GetMillimetresPerUnit();
  return m;
}

std::string vtkTranslucentMaterial::Validate() const
{
  const sss::Material m = sss::core_material(*this);
  try
  {
    m.validate();
  }
  catch (const std::invalid_argument& error)
  {
    return error.what();
  }
  return {};
}

double vtkTranslucentMaterial::GetKernelReachMillimetres() const
{
  if (!this->Validate().empty())
  {
    return 0.0;
  }
  return sss::Dipole(sss::core_material(*this)).max_support_radius(sss::kKernelSupportFraction);
}

void vtkTranslucentMaterial::ApplyTo(vtkProp* prop)
{
  if (!prop)
  {
    vtkErrorMacro(<< "ApplyTo: no prop given");
    return;
  }
  vtkInformation* keys = prop->GetPropertyKeys();
  if (!keys)
  {
    vtkNew<vtkInformation> created;
    prop->SetPropertyKeys(created);
    keys = created;
  }
  keys->Set(MATERIAL(), this);
  prop->Modified();
}

void vtkTranslucentMaterial::RemoveFrom(vtkProp* prop)
{
  if (prop && prop->GetPropertyKeys())
  {
    prop->GetPropertyKeys()->Remove(MATERIAL());
    prop->Modified();
  }
}

vtkTranslucentMaterial* vtkTranslucentMaterial::GetFrom(vtkProp* prop)
{
  if (!prop || !prop->GetPropertyKeys())
  {
    return nullptr;
  }
  return vtkTranslucentMaterial::SafeDownCast(prop->GetPropertyKeys()->Get(MATERIAL()));
}

void vtkTranslucentMaterial::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Name: " << this->Name << "\n";
  os << indent << "SigmaA (1/mm): " << this->SigmaA[0] << " " << this->SigmaA[1] << " "
     << this->SigmaA[2] << "\n";
  os << indent << "SigmaSPrime (1/mm): " << this->SigmaSPrime[0] << " " << this->SigmaSPrime[1]
     << " " << this->SigmaSPrime[2] << "\n";
  os << indent << "Eta: " << this->Eta << "\n";
  os << indent << "MillimetresPerUnit: " << this->MillimetresPerUnit << "\n";
  os << indent << "ColoursAsAlbedo: " << this->ColoursAsAlbedo << "\n";
}
