#include <Eigen/Geometry>
#include "scan_io.h"

#include <zlib.h>

#include <fstream>
#include <sstream>
#include <stdexcept>
#include <vector>

namespace sss::test {

std::string shared_data(const std::string& name) {
  const std::string path = std::string(SSS_DATA_DIR) + "/" + name;
  return std::ifstream(path).good() ? path : std::string();
}

namespace {

class GzLines {
 public:
  explicit GzLines(const std::string& path) : file_(gzopen(path.c_str(), "rb")) {
    if (!file_) throw std::runtime_error("cannot open " + path);
  }
  ~GzLines() { gzclose(file_); }
  bool next(std::string& line) {
    line.clear();
    char buffer[4096];
    while (gzgets(file_, buffer, sizeof buffer)) {
      line += buffer;
      if (!line.empty() && line.back() == '\n') return true;
    }
    return !line.empty();
  }

 private:
  gzFile file_;
};

}  // namespace

SurfelCloud load_ply_mesh(const std::string& path) {
  GzLines lines(path);
  std::string line;
  std::size_t vertices = 0, faces = 0;
  int vertex_properties = 0;
  bool in_vertex = false;
  while (lines.next(line)) {
    std::istringstream words(line);
    std::string word;
    words >> word;
    if (word == "element") {
      std::string kind;
      std::size_t count;
      words >> kind >> count;
      in_vertex = kind == "vertex";
      (in_vertex ? vertices : faces) = count;
    } else if (word == "property" && in_vertex) {
      ++vertex_properties;
    } else if (word == "end_header") {
      break;
    }
  }
  SurfelCloud cloud;
  cloud.positions.resize(vertices);
  cloud.normals.assign(vertices, Eigen::Vector3d::Zero());
  for (std::size_t v = 0; v < vertices && lines.next(line); ++v) {
    std::istringstream values(line);
    values >> cloud.positions[v].x() >> cloud.positions[v].y() >> cloud.positions[v].z();
  }
  double edge_sum = 0.0;
  std::size_t edge_count = 0;
  for (std::size_t f = 0; f < faces && lines.next(line); ++f) {
    std::istringstream values(line);
    int n = 0;
    values >> n;
    std::vector<std::size_t> ids(n);
    for (auto& id : ids) values >> id;
    for (int k = 1; k + 1 < n; ++k) {
      const Eigen::Vector3d& a = cloud.positions[ids[0]];
      const Eigen::Vector3d& b = cloud.positions[ids[k]];
      const Eigen::Vector3d& c = cloud.positions[ids[k + 1]];
      const Eigen::Vector3d area_normal = 0.5 * (b - a).cross(c - a);
      for (std::size_t id : {ids[0], ids[k], ids[k + 1]}) cloud.normals[id] += area_normal;
    }
    for (int k = 0; k < n; ++k) {
      edge_sum += (cloud.positions[ids[k]] - cloud.positions[ids[(k + 1) % n]]).norm();
      ++edge_count;
    }
  }
  if (vertices == 0 || edge_count == 0) throw std::runtime_error(path + ": no mesh found");
  cloud.radius = 0.8 * edge_sum / edge_count;
  cloud.validate();  // drops the vertices no face uses (zero normal)
  return cloud;
}

}  // namespace sss::test
