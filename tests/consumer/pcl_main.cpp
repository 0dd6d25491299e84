// The installed PCL component: surfels from a PCL cloud (normals estimated, radius from the
// spacing) through SSS::PCL; exits non-zero when the numbers are off.
#include <pcl/point_types.h>
#include <sssPclSurfels.h>

#include <cmath>
#include <cstdio>

int main() {
  pcl::PointCloud<pcl::PointXYZ> plane;
  for (int i = 0; i < 30; ++i)
    for (int j = 0; j < 30; ++j) plane.push_back(pcl::PointXYZ(0.5f * i, 0.5f * j, 0.0f));
  const sss::Surfels surfels = sss::makeSurfels(plane);
  std::printf("SSS::PCL: %s\n", surfels.summary().c_str());
  return surfels.size() == 900 && std::abs(surfels.spacing - 0.5) < 1e-6 ? 0 : 1;
}
