// Step 2's near field on the GPU (near_field.glsl): the table of weights that
// core/near_field/near_field.h bakes on the CPU when the geometry or the material changes (each
// receiver's row: the sources within the near reach, each with its kernel integrated over its
// cell), one row per texel of the surfel list. A light move only re-weights it by the new E.
#ifndef sssNearFieldTable_h
#define sssNearFieldTable_h

#include "vtkSmartPointer.h"

#include <string>

class vtkOpenGLRenderWindow;
class vtkShaderProgram;
class vtkTextureObject;
class vtkWindow;

namespace sss
{

class SurfelList;
struct NearFieldWeights;

class NearFieldTable
{
public:
  bool upload(vtkOpenGLRenderWindow* window, const SurfelList& list,
    const NearFieldWeights& weights, std::string& error);
  // near_field.glsl's table samplers, bound for `program`.
  void activate(vtkShaderProgram* program) const;
  void deactivate() const;
  void release(vtkWindow* window);

private:
  vtkSmartPointer<vtkTextureObject> rows_, entries_;
};

}

#endif
