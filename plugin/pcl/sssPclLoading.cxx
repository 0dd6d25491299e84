#include "sssPclLoading.h"

#include <pcl/PCLPointCloud2.h>
#include <pcl/PolygonMesh.h>
#include <pcl/common/io.h>
#include <pcl/console/print.h>
#include <pcl/conversions.h>
#include <pcl/io/pcd_io.h>
#include <pcl/io/ply_io.h>
#include <pcl/point_types.h>

#include <zlib.h>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string_view>
#include <unistd.h>

#include <vector>

#include "sssAsciiPoints.h"
#include "sssFileClaims.h"
#include "sssPclMeshSampling.h"

namespace sss {
namespace {

bool ends_with(std::string s, const std::string& tail) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return std::tolower(c); });
  return s.size() >= tail.size() && s.compare(s.size() - tail.size(), tail.size(), tail) == 0;
}

bool has_field(const pcl::PCLPointCloud2& blob, const std::string& name) {
  return std::any_of(blob.fields.begin(), blob.fields.end(),
                     [&](const pcl::PCLPointField& f) { return f.name == name; });
}

// PCL reports parse problems on its console; the caller reports one message instead.
class QuietPclConsole {
 public:
  QuietPclConsole() : saved_(pcl::console::getVerbosityLevel()) {
    pcl::console::setVerbosityLevel(pcl::console::L_ALWAYS);
  }
  ~QuietPclConsole() { pcl::console::setVerbosityLevel(saved_); }

 private:
  pcl::console::VERBOSITY_LEVEL saved_;
};

// A gzip file inflated into a temporary file that is removed with this object; one that
// inflates to more than `cap` bytes is refused (a PLY that large cannot load under the cap).
class InflatedCopy {
 public:
  InflatedCopy(const std::string& path, const std::string& suffix, std::size_t cap) {
    std::string pattern =
      (std::filesystem::temp_directory_path() / ("sss-inflated-XXXXXX" + suffix)).string();
    const int fd = mkstemps(pattern.data(), static_cast<int>(suffix.size()));
    if (fd < 0) throw InputError(path + ": cannot create a temporary file to inflate it into");
    path_ = pattern;
    gzFile in = gzopen(path.c_str(), "rb");
    bool ok = in != nullptr;
    std::vector<char> buffer(1 << 20);
    std::size_t inflated = 0;
    bool over_cap = false;
    while (ok) {
      const int n = gzread(in, buffer.data(), static_cast<unsigned>(buffer.size()));
      if (n < 0) ok = false;
      if (n <= 0) break;
      inflated += static_cast<std::size_t>(n);
      if (inflated > cap) {
        ok = false;
        over_cap = true;
        break;
      }
      ok = write(fd, buffer.data(), static_cast<std::size_t>(n)) == n;
    }
    if (in) gzclose(in);
    close(fd);
    if (over_cap) {
      std::remove(path_.c_str());
      throw InputError(path + ": inflates to more than the memory cap of " + byteSize(cap) +
                       " (LoadOptions::memory_cap, --memory-cap)");
    }
    if (!ok) {
      std::remove(path_.c_str());
      throw InputError(path + ": not a readable gzip file");
    }
  }
  ~InflatedCopy() { std::remove(path_.c_str()); }
  InflatedCopy(const InflatedCopy&) = delete;
  InflatedCopy& operator=(const InflatedCopy&) = delete;
  const std::string& path() const { return path_; }

 private:
  std::string path_;
};

struct Blob {
  pcl::PCLPointCloud2 points;
  Eigen::Vector4f sensor_origin = Eigen::Vector4f::Zero();
  Eigen::Quaternionf sensor_orientation = Eigen::Quaternionf::Identity();
  std::string kind;
};

// PCL's PLY reader takes the cloud's width and height from the file's camera element, which
// can disagree with the vertices it read, and conversion trusts the layout: check it first.
void check_layout(const std::string& path, const pcl::PCLPointCloud2& points) {
  const std::uint64_t step = points.point_step;
  bool ok = step > 0 && points.row_step >= std::uint64_t{points.width} * step &&
            points.data.size() >= std::uint64_t{points.row_step} * points.height;
  for (const pcl::PCLPointField& f : points.fields)
    ok = ok && std::uint64_t{f.offset} + std::uint64_t{f.count} * pcl::getFieldSize(f.datatype) <= step;
  if (!ok)
    throw InputError(path + ": not a readable point cloud (its layout, " +
                     std::to_string(points.width) + " x " + std::to_string(points.height) +
                     " points of " + std::to_string(step) + " bytes, does not match the " +
                     std::to_string(points.data.size()) + " bytes read)");
}

Blob read_pcd(const std::string& path, std::size_t cap, std::size_t point_bytes) {
  checkPcdClaims(path, path, cap, point_bytes);  // PCL's reader trusts its header
  Blob blob;
  if (pcl::io::loadPCDFile(path, blob.points, blob.sensor_origin, blob.sensor_orientation) < 0)
    throw InputError(path + ": not a readable PCD file");
  blob.kind = "PCD";
  return blob;
}

// A mesh read from a `format` file as its points, its vertices with their normals (the file's,
// else from the faces), or samples of its surface.
Blob from_mesh(const std::string& shown, pcl::PolygonMesh& mesh, const LoadOptions& options,
               const std::string& format) {
  Blob blob;
  if (mesh.polygons.empty()) {
    if (options.mesh_samples > 0)
      throw InputError(shown + ": mesh sampling asked for, but the " + format +
                       " file has no faces");
    blob.points = std::move(mesh.cloud);
    blob.kind = format + " points";
    return blob;
  }
  const bool colours = has_field(mesh.cloud, "rgb") || has_field(mesh.cloud, "rgba");
  if (options.mesh_samples > 0) {
    pcl::PointCloud<pcl::PointXYZRGBNormal> samples;
    try {
      samples = sampleMeshSurface(mesh, options.mesh_samples, options.sampling_seed);
    } catch (const std::invalid_argument& e) {
      throw InputError(shown + ": " + e.what());
    }
    pcl::toPCLPointCloud2(samples, blob.points);
    blob.kind = format + " mesh, " + std::to_string(mesh.polygons.size()) + " faces sampled";
  } else if (has_field(mesh.cloud, "normal_x")) {
    blob.points = std::move(mesh.cloud);
    blob.kind = format + " mesh vertices";
    return blob;
  } else {
    pcl::toPCLPointCloud2(meshVerticesWithNormals(mesh), blob.points);
    blob.kind =
      format + " mesh vertices, normals from " + std::to_string(mesh.polygons.size()) + " faces";
  }
  if (!colours) {  // the conversion above added an rgb field; drop it again
    auto& fields = blob.points.fields;
    fields.erase(std::remove_if(fields.begin(), fields.end(),
                                [](const pcl::PCLPointField& f) { return f.name == "rgb"; }),
                 fields.end());
  }
  return blob;
}

Blob read_ply(const std::string& shown_path, const std::string& path, const LoadOptions& options,
              std::size_t cap, std::size_t point_bytes) {
  checkPlyClaims(shown_path, path, cap, point_bytes);
  pcl::PolygonMesh mesh;
  if (pcl::io::loadPLYFile(path, mesh) < 0) throw InputError(shown_path + ": not a readable PLY file");
  check_layout(shown_path, mesh.cloud);
  if (std::uint64_t{mesh.cloud.width} * mesh.cloud.height == 0)  // PCL's conversions need one
    throw InputError(shown_path + ": the file has no points");
  return from_mesh(shown_path, mesh, options, "PLY");
}

// OBJ is parsed here: pcl::io::loadOBJFile writes past its buffer when a file has more vn than
// v lines, reads past a short v line, leaves garbage indices for a face word that is not a
// number, checks no index and opens any file an mtllib line names.
Blob read_obj(const std::string& path, const LoadOptions& options, std::size_t cap,
              std::size_t point_bytes) {
  const ObjCounts counts = checkObjClaims(path, path, cap, point_bytes);
  std::vector<Eigen::Vector3f> positions, normals;
  positions.reserve(counts.vertices);
  normals.reserve(counts.normals);
  constexpr std::int64_t kNone = -1, kSeveral = -2;
  std::vector<std::int64_t> given;  // per vertex: the vn its corners name, kNone or kSeveral
  given.reserve(counts.vertices);
  pcl::PolygonMesh mesh;
  mesh.polygons.reserve(counts.faces);
  TextLines text(path, path);
  std::vector<std::string_view> words;
  const auto refuse = [&](const std::string& what) {
    throw InputError(path + ": not a readable OBJ file (line " + std::to_string(text.number()) +
                     ", " + what + ")");
  };
  const auto quoted = [](std::string_view word) {
    return "'" + std::string(word.substr(0, 40)) + "'";
  };
  // x y z after the key, and up to `more` numbers after them that are not kept (v's w or colour).
  const auto xyz = [&](std::string_view line, std::size_t more) {
    if (words.size() < 4 || words.size() > 4 + more)
      refuse(quoted(line) + " has " + std::to_string(words.size() - 1) + " numbers, not 3" +
             (more ? " to " + std::to_string(3 + more) : ""));
    double value[3];
    for (std::size_t k = 1; k < words.size(); ++k)
      if (double v; parseNumber(words[k], v)) {
        if (k <= 3) value[k - 1] = v;
      } else {
        refuse(quoted(words[k]) + " is not a number");
      }
    return Eigen::Vector3d(value[0], value[1], value[2]).cast<float>().eval();
  };
  // A face corner's index: from 1, or negative counting back from the last one read.
  const auto index = [&](std::string_view word, std::size_t read, const std::string& what,
                         const std::string& all) {
    long long i = 0;
    const auto [end, error] = std::from_chars(word.data(), word.data() + word.size(), i);
    if (error != std::errc() || end != word.data() + word.size())
      refuse(quoted(word) + " is not a " + what + " index");
    const long long at = i < 0 ? static_cast<long long>(read) + i : i - 1;
    if (i == 0 || at < 0 || at >= static_cast<long long>(read))
      refuse(what + " index " + std::string(word) + " names none of the " + std::to_string(read) +
             " " + all + " before it");
    return static_cast<std::size_t>(at);
  };
  static const std::string_view ignored_keys[] = {
    "vt", "vp", "l", "p", "o", "g", "s", "mg", "usemtl", "mtllib", "maplib", "usemap", "cstype",
    "deg", "bmat", "step", "curv", "curv2", "surf", "parm", "trim", "hole", "scrv", "sp", "end",
    "con", "lod", "shadow_obj", "trace_obj", "ctech", "stech", "bevel", "c_interp", "d_interp"};
  for (std::string_view line; text.next(line);) {
    splitWords(line, " \t", words);
    if (words.empty() || words[0][0] == '#') continue;
    if (words[0] == "v") {
      positions.push_back(xyz(line, 3));
      given.push_back(kNone);
    } else if (words[0] == "vn") {
      normals.push_back(xyz(line, 0).normalized());
    } else if (words[0] == "f") {
      if (words.size() < 4) refuse("a face needs 3 corners");
      pcl::Vertices face;
      face.vertices.reserve(words.size() - 1);
      for (std::size_t k = 1; k < words.size(); ++k) {  // v, v/vt, v/vt/vn or v//vn
        const std::string_view corner = words[k];
        const std::size_t slash = corner.find('/');
        const std::size_t second = corner.find('/', slash == corner.npos ? slash : slash + 1);
        const std::size_t v =
          index(corner.substr(0, slash), positions.size(), "vertex", "vertices");
        face.vertices.push_back(static_cast<pcl::index_t>(v));
        if (second == corner.npos) continue;
        const std::size_t n = index(corner.substr(second + 1), normals.size(), "normal", "normals");
        std::int64_t& g = given[v];
        const bool same = g >= 0 && normals[static_cast<std::size_t>(g)] == normals[n];
        g = g == kNone || same ? static_cast<std::int64_t>(n) : kSeveral;
      }
      mesh.polygons.push_back(std::move(face));
    } else if (std::find(std::begin(ignored_keys), std::end(ignored_keys), words[0]) ==
               std::end(ignored_keys)) {
      refuse(quoted(line) + " is not an OBJ line");
    }
  }
  if (positions.empty()) throw InputError(path + ": the file has no points");
  // The file's normals: one per vertex from its corners, or without faces the i-th vn line's
  // for the i-th vertex (as pcl::io::saveOBJFile writes them).
  const bool by_corners = !mesh.polygons.empty() &&
    std::all_of(given.begin(), given.end(), [](std::int64_t g) { return g >= 0; });
  const bool by_order = mesh.polygons.empty() && normals.size() == positions.size();
  if (by_corners || by_order) {
    pcl::PointCloud<pcl::PointNormal> cloud;
    cloud.resize(positions.size());
    for (std::size_t i = 0; i < positions.size(); ++i) {
      cloud[i].getVector3fMap() = positions[i];
      cloud[i].getNormalVector3fMap() =
        normals[by_corners ? static_cast<std::size_t>(given[i]) : i];
    }
    pcl::toPCLPointCloud2(cloud, mesh.cloud);
  } else {
    pcl::PointCloud<pcl::PointXYZ> cloud;
    cloud.resize(positions.size());
    for (std::size_t i = 0; i < positions.size(); ++i) cloud[i].getVector3fMap() = positions[i];
    pcl::toPCLPointCloud2(cloud, mesh.cloud);
  }
  return from_mesh(path, mesh, options, "OBJ");
}

Blob read_ascii(const std::string& path, const LoadOptions& options, std::size_t cap,
                std::size_t point_bytes) {
  if (options.mesh_samples > 0)
    throw InputError(path + ": mesh sampling asked for, but an ASCII point list has no faces");
  AsciiPoints read = readAsciiPoints(path, cap, point_bytes);
  Blob blob;
  blob.points = std::move(read.points);
  blob.kind = "ASCII points, columns " + read.columns;
  return blob;
}

Blob read_any(const std::string& path, const LoadOptions& options, std::size_t point_bytes) {
  if (!std::ifstream(path).good()) throw InputError(path + ": cannot be opened");
  if (std::filesystem::is_directory(path)) throw InputError(path + ": is a folder, not a file");
  const std::size_t cap = options.memory_cap ? options.memory_cap : defaultMemoryCap();
  if (options.mesh_samples > 0) {
    const long double samples =
      static_cast<long double>(options.mesh_samples) * (sizeof(pcl::PointXYZRGBNormal) + point_bytes);
    if (samples > cap)
      throw InputError(path + ": " + std::to_string(options.mesh_samples) +
                       " mesh samples would need " + byteSize(samples) +
                       " in memory, over the memory cap of " + byteSize(cap) +
                       " (LoadOptions::memory_cap, --memory-cap)");
  }
  if (ends_with(path, ".pcd")) return read_pcd(path, cap, point_bytes);
  if (ends_with(path, ".ply")) return read_ply(path, path, options, cap, point_bytes);
  if (ends_with(path, ".ply.gz")) {
    const InflatedCopy plain(path, ".ply", cap);
    return read_ply(path, plain.path(), options, cap, point_bytes);
  }
  if (ends_with(path, ".obj")) return read_obj(path, options, cap, point_bytes);
  for (const char* ascii : {".xyz", ".txt", ".csv", ".asc"})
    if (ends_with(path, ascii)) return read_ascii(path, options, cap, point_bytes);
  throw InputError(path +
                   ": unknown extension (use .pcd, .ply, .ply.gz, .obj, .xyz, .txt, .csv or .asc)");
}

}  // namespace

template <typename PointT>
LoadedPointCloud<PointT> loadPointCloud(const std::string& path, const LoadOptions& options) {
  const QuietPclConsole quiet;
  Blob blob;
  try {
    blob = read_any(path, options, sizeof(PointT));
  } catch (const InputError&) {
    throw;
  } catch (const std::exception& e) {  // PCL's readers throw their own kinds on some files
    throw InputError(path + ": not a readable point cloud (" + e.what() + ")");
  }
  const std::size_t count = std::size_t{blob.points.width} * blob.points.height;
  if (count == 0 || blob.points.data.empty()) throw InputError(path + ": the file has no points");
  check_layout(path, blob.points);

  LoadedPointCloud<PointT> loaded;
  loaded.path = path;
  loaded.cloud.reset(new pcl::PointCloud<PointT>);
  pcl::fromPCLPointCloud2(blob.points, *loaded.cloud);
  loaded.cloud->sensor_origin_ = blob.sensor_origin;
  loaded.cloud->sensor_orientation_ = blob.sensor_orientation;
  const bool file_normals = has_field(blob.points, "normal_x");
  const bool file_colours = has_field(blob.points, "rgb") || has_field(blob.points, "rgba");
  loaded.has_normals = file_normals && pcl::traits::has_normal_v<PointT>;
  loaded.has_colours = file_colours && pcl::traits::has_color_v<PointT>;

  loaded.description = path + ": " + blob.kind + ", " + std::to_string(count) + " points";
  if (blob.points.height > 1)
    loaded.description += " (organised " + std::to_string(blob.points.width) + " x " +
                          std::to_string(blob.points.height) + ")";
  if (file_normals)
    loaded.description += loaded.has_normals ? ", normals" : ", normals not kept by this point type";
  if (file_colours)
    loaded.description += loaded.has_colours ? ", colours" : ", colours not kept by this point type";
  return loaded;
}

#define SSS_INSTANTIATE_LOADING(PointT) \
  template LoadedPointCloud<PointT> loadPointCloud<PointT>(const std::string&, const LoadOptions&);
SSS_INSTANTIATE_LOADING(pcl::PointXYZ)
SSS_INSTANTIATE_LOADING(pcl::PointNormal)
SSS_INSTANTIATE_LOADING(pcl::PointXYZRGB)
SSS_INSTANTIATE_LOADING(pcl::PointXYZRGBNormal)
SSS_INSTANTIATE_LOADING(pcl::PointSurfel)
#undef SSS_INSTANTIATE_LOADING

}  // namespace sss
