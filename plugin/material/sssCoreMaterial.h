// A vtkTranslucentMaterial as the core's Material (the coefficients, eta per channel and the
// millimetres per unit), for the pass and the material's own validation.
#ifndef sssCoreMaterial_h
#define sssCoreMaterial_h

#include "material.h"

class vtkTranslucentMaterial;

namespace sss
{
Material core_material(const vtkTranslucentMaterial& material);
}

#endif
