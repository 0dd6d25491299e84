#include "sssSurfelBuffers.h"

#include "sssSurfelPreparation.h"

#include "vtkOpenGLBufferObject.h"

#include <vector>

namespace sss
{

void SurfelBuffers::upload(const PreparedSurfels& prepared)
{
  count = prepared.cloud.size();
  std::vector<float> p(3 * count), n(3 * count);
  for (std::size_t i = 0; i < count; ++i)
  {
    for (int c = 0; c < 3; ++c)
    {
      p[3 * i + c] = static_cast<float>(prepared.cloud.positions[i][c] - prepared.centre[c]);
      n[3 * i + c] = static_cast<float>(prepared.cloud.normals[i][c]);
    }
  }
  positions->Upload(p, vtkOpenGLBufferObject::ArrayBuffer);
  normals->Upload(n, vtkOpenGLBufferObject::ArrayBuffer);
  colours->Upload(prepared.rgba, vtkOpenGLBufferObject::ArrayBuffer);
  upload_time.Modified();
}

void SurfelBuffers::release()
{
  for (vtkOpenGLBufferObject* b : { positions.Get(), normals.Get(), colours.Get() })
  {
    b->ReleaseGraphicsResources();
  }
  count = 0;
  upload_time = vtkTimeStamp();
}

}
