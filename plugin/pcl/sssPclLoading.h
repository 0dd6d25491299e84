// Reading point clouds for the translucency renderer with PCL: PCD (ascii, binary,
// binary_compressed, organised with NaN), PLY and OBJ (points, or a mesh's vertices or samples
// of its triangles), gzip-compressed PLY, and ASCII point lists (.xyz, .txt, .csv, .asc: x y z,
// normals and colours, named by a header or told by the column count).
#pragma once

#include <pcl/point_cloud.h>

#include <cstddef>
#include <stdexcept>
#include <string>

namespace sss {

// Bad input (unreadable file, unknown extension, no points, nothing usable); the message names
// the file and what is wrong.
class InputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct LoadOptions {
  // PLY and OBJ meshes: 0 keeps the vertices (normals from the faces when the file has none);
  // N > 0 samples N points uniformly over the triangles' area instead, as pcl_mesh_sampling
  // does.
  std::size_t mesh_samples = 0;
  unsigned sampling_seed = 1;
  // Bytes a load may claim (PCL's data, the cloud, samples, an inflated .gz); a header that
  // claims more is refused before anything is allocated. 0: half the physical memory.
  std::size_t memory_cap = 0;
};

template <typename PointT>
struct LoadedPointCloud {
  std::string path;
  typename pcl::PointCloud<PointT>::Ptr cloud;  // as read: organised clouds keep their NaN
  bool has_normals = false;  // the file, or the mesh's faces, gave normals
  bool has_colours = false;  // the file gave rgb or rgba
  std::string description;   // what was read, for a log line
};

// Throws InputError. PCL's own console messages are silenced while reading so that a bad
// file gives one message. Instantiated for PointXYZ, PointNormal, PointXYZRGB,
// PointXYZRGBNormal and PointSurfel.
template <typename PointT>
LoadedPointCloud<PointT> loadPointCloud(const std::string& path, const LoadOptions& options = {});

}  // namespace sss
