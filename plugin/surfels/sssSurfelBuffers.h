// An actor's surfels as GL vertex buffers for the passes that draw one GL point per surfel
// (the light maps and the per-surfel resolve), in the actor's local frame (mm).
#ifndef sssSurfelBuffers_h
#define sssSurfelBuffers_h

#include "vtkNew.h"

#include <cstdint>
#include <vector>

class vtkOpenGLBufferObject;

namespace sss
{

struct LocalSurfels;

struct SurfelBuffers
{
  vtkNew<vtkOpenGLBufferObject> points, normals, colours, curvatures, disc_radii;
  std::size_t count = 0;

  // Each disc's curvature is clamped at one over the disc radius, as core/light_map/light_map.cpp
  // does; each disc's radius is the one that closes the surface in the light's view.
  void upload(const LocalSurfels& local, const std::vector<std::uint8_t>& rgba);
  void release();
};

}

#endif
