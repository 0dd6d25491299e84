#include "baked_ply.h"

#include <stdexcept>

#include "whole_file.h"

namespace sss::cli {

void write_baked_ply(const std::vector<Eigen::Vector3d>& positions,
                     const std::vector<Eigen::Vector3d>& normals, const std::vector<Rgb>& Lo,
                     const std::string& path) {
  if (positions.size() != Lo.size() || positions.size() != normals.size())
    throw std::invalid_argument("[write_baked_ply] positions, normals and radiance differ in count");
  write_whole_file(path, [&](std::ostream& out) {
    out << "ply\nformat binary_little_endian 1.0\n"
        << "comment outgoing radiance Lo (eq. 14) towards the camera, linear\n"
        << "element vertex " << positions.size() << "\n"
        << "property double x\nproperty double y\nproperty double z\n"
        << "property float nx\nproperty float ny\nproperty float nz\n"
        << "property float red\nproperty float green\nproperty float blue\nend_header\n";
    for (std::size_t i = 0; i < positions.size(); ++i) {
      out.write(reinterpret_cast<const char*>(positions[i].data()), 3 * sizeof(double));
      const float n[3] = {static_cast<float>(normals[i].x()), static_cast<float>(normals[i].y()),
                          static_cast<float>(normals[i].z())};
      out.write(reinterpret_cast<const char*>(n), sizeof n);
      const float rgb[3] = {static_cast<float>(Lo[i][0]), static_cast<float>(Lo[i][1]),
                            static_cast<float>(Lo[i][2])};
      out.write(reinterpret_cast<const char*>(rgb), sizeof rgb);
    }
  });
}

}  // namespace sss::cli
