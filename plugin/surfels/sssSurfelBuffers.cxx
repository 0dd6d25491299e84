#include "sssSurfelBuffers.h"

#include "local_surfels.h"

#include "vtkOpenGLBufferObject.h"

#include <algorithm>

namespace sss
{

void SurfelBuffers::upload(const LocalSurfels& local, const std::vector<std::uint8_t>& rgba)
{
  count = local.size();
  std::vector<float> p(3 * count), n(3 * count), curvature(count), radius(count);
  const double lift_limit = 1.0 / local.cell_radius;
  for (std::size_t i = 0; i < count; ++i)
  {
    for (int c = 0; c < 3; ++c)
    {
      p[3 * i + c] = static_cast<float>(local.positions[i][c]);
      n[3 * i + c] = static_cast<float>(local.normals[i][c]);
    }
    curvature[i] = static_cast<float>(std::clamp(local.curvature[i], -lift_limit, lift_limit));
    radius[i] = static_cast<float>(local.disc_radius(i));
  }
  points->Upload(p, vtkOpenGLBufferObject::ArrayBuffer);
  normals->Upload(n, vtkOpenGLBufferObject::ArrayBuffer);
  colours->Upload(rgba, vtkOpenGLBufferObject::ArrayBuffer);
  curvatures->Upload(curvature, vtkOpenGLBufferObject::ArrayBuffer);
  disc_radii->Upload(radius, vtkOpenGLBufferObject::ArrayBuffer);
}

void SurfelBuffers::release()
{
  for (vtkOpenGLBufferObject* b :
    { points.Get(), normals.Get(), colours.Get(), curvatures.Get(), disc_radii.Get() })
  {
    b->ReleaseGraphicsResources();
  }
  count = 0;
}

}
