// An actor's surfels as GL vertex buffers, uploaded once by its vtkSurfelMapper and shared by
// the camera view and the views from the lights: positions in scene units relative to the
// frame origin (PreparedSurfels::centre, Bounds::frame_origin, also LocalSurfels' origin),
// unit normals and RGBA colours, one per prepared surfel, ghosts included. The views from the
// lights scale the positions to millimetres in their matrices.
#ifndef sssSurfelBuffers_h
#define sssSurfelBuffers_h

#include "vtkNew.h"
#include "vtkTimeStamp.h"

#include <cstddef>

class vtkOpenGLBufferObject;

namespace sss
{

struct PreparedSurfels;

struct SurfelBuffers
{
  vtkNew<vtkOpenGLBufferObject> positions, normals, colours;
  std::size_t count = 0;
  vtkTimeStamp upload_time;  // when they were last uploaded; zero when released

  void upload(const PreparedSurfels& prepared);
  void release();
};

}

#endif
