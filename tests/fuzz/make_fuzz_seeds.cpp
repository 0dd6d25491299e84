// Writes the fuzz targets' seed corpora: small clouds in every form the loader reads (PCD
// ascii, binary and binary_compressed, organised with NaN; PLY ascii and binary, points and a
// mesh; OBJ points and meshes; ASCII point lists of each column layout), each prefixed by the
// form byte fuzz_load_cloud.cpp reads (+5: the mesh sampled), and typical sss_render argument
// lists for fuzz_cli_options.cpp.
#include <pcl/PolygonMesh.h>
#include <pcl/conversions.h>
#include <pcl/io/pcd_io.h>
#include <pcl/io/ply_io.h>
#include <pcl/point_types.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <string>
#include <tuple>
#include <vector>

namespace fs = std::filesystem;

void seed(const fs::path& dir, const std::string& name, char form, const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  std::ofstream(dir / name, std::ios::binary) << form << bytes;
}

int main(int argc, char** argv) {
  if (argc != 2) return 2;
  const fs::path root = argv[1], load = root / "load_cloud", cli = root / "cli_options";
  fs::create_directories(load);
  fs::create_directories(cli);
  const fs::path tmp = root / "tmp";
  fs::create_directories(tmp);

  pcl::PointCloud<pcl::PointXYZRGBNormal> cloud(4, 3);  // organised, one hole
  for (int v = 0; v < 3; ++v)
    for (int u = 0; u < 4; ++u) {
      auto& p = cloud.at(u, v);
      p.x = 0.1f * u, p.y = 0.1f * v, p.z = 1.0f;
      p.normal_x = 0, p.normal_y = 0, p.normal_z = -1;
      p.r = 200, p.g = 100, p.b = static_cast<std::uint8_t>(20 * u);
    }
  cloud.at(1, 1).x = std::numeric_limits<float>::quiet_NaN();
  cloud.is_dense = false;
  pcl::PointCloud<pcl::PointXYZ> xyz;
  for (int i = 0; i < 6; ++i) xyz.push_back(pcl::PointXYZ(0.2f * i, 0.1f * (i % 2), 0.0f));

  pcl::io::savePCDFileASCII((tmp / "a.pcd").string(), cloud);
  seed(load, "pcd_ascii", 0, tmp / "a.pcd");
  pcl::io::savePCDFileBinary((tmp / "b.pcd").string(), cloud);
  seed(load, "pcd_binary", 0, tmp / "b.pcd");
  pcl::io::savePCDFileBinaryCompressed((tmp / "c.pcd").string(), cloud);
  seed(load, "pcd_binary_compressed", 0, tmp / "c.pcd");
  pcl::io::savePCDFileASCII((tmp / "x.pcd").string(), xyz);
  seed(load, "pcd_xyz", 0, tmp / "x.pcd");
  pcl::io::savePLYFileASCII((tmp / "a.ply").string(), xyz);
  seed(load, "ply_ascii_points", 1, tmp / "a.ply");
  pcl::io::savePLYFileBinary((tmp / "b.ply").string(), cloud);
  seed(load, "ply_binary_points", 1, tmp / "b.ply");

  pcl::PolygonMesh mesh;  // a square of two triangles
  pcl::PointCloud<pcl::PointXYZ> corners;
  for (const auto& [x, y] : std::vector<std::pair<float, float>>{{0, 0}, {1, 0}, {1, 1}, {0, 1}})
    corners.push_back(pcl::PointXYZ(x, y, 0));
  pcl::toPCLPointCloud2(corners, mesh.cloud);
  for (const auto& face : std::vector<std::vector<pcl::index_t>>{{0, 1, 2}, {0, 2, 3}}) {
    pcl::Vertices v;
    v.vertices = face;
    mesh.polygons.push_back(v);
  }
  pcl::io::savePLYFile((tmp / "m.ply").string(), mesh);
  seed(load, "ply_ascii_mesh", 1, tmp / "m.ply");
  seed(load, "ply_ascii_mesh_sampled", 1 + 5, tmp / "m.ply");
  seed(load, "ply_gz_mesh", 2, tmp / "m.ply");
  pcl::io::savePLYFileBinary((tmp / "n.ply").string(), mesh);
  seed(load, "ply_binary_mesh", 1, tmp / "n.ply");
  fs::remove_all(tmp);

  const std::vector<std::tuple<std::string, char, std::string>> texts = {
    {"obj_points", 3, "# points\nv 0 0 0\nv 1 0 0 1\nv 0 1 0\nvn 0 0 1\nvn 0 0 1\nvn 0 0 1\n"},
    {"obj_tetrahedron", 3,
     "o tet\nv 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nvt 0 0\nvn 0 0 -1\nvn 1 1 1\n"
     "f 1/1/1 3/1/1 2/1/1\nf 1//2 2//2 4//2\nf -4 -1 -2\ns off\nf 2 3 4\n"},
    {"obj_cube_sampled", 3 + 5,
     "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\n"
     "f 1 4 3 2\nf 5 6 7 8\nf 1 2 6 5\nf 2 3 7 6\nf 3 4 8 7 \nf 4 1 5 8\n"},
    {"xyz", 4, "0 0 0\n1 0 0\n0 1 0\n1 1 0.5\n"},
    {"xyz_normals", 4, "0 0 0 0 0 1\n1 0 0 0 0.6 0.8\n0 1 0 0 0 -1\n"},
    {"csv_colours", 4, "# colours\n0,0,0,255,128,0\n1,0,0,0.5,20,30\n0,1,0,1,2,3\n"},
    {"pts_intensity", 4, "3\n0 0 0 -12 255 128 0\n1 0 0 5 10 20 30\n0 1 0 7 1 2 3\n"},
    {"txt_cloudcompare", 4,
     "//X,Y,Z,R,G,B,Nx,Ny,Nz\n0;0;0;255;0;0;0;0;1\n1;0;0;0;255;0;1;0;0\n0;1;0;1;1;1;0;1;0\n"},
    {"txt_named", 4, "x\ty\tz\tintensity\tnx\tny\tnz\r\n0 0 0 1 0 0 1\r\n1 0 0 2 0 0 1\r\n"
                     "// a comment\r\n0 1 0 3 0 0 1\r\n"}};
  for (const auto& [name, form, text] : texts)
    std::ofstream(load / name, std::ios::binary) << form << text;

  const std::vector<std::vector<std::string>> lists = {
    {"scan.pcd", "--mm-per-unit", "1000", "--material", "marble", "--light-dir", "0.3,-0.5,-1"},
    {"--size", "64x48", "--method", "reference", "--ortho", "--view-dir", "0,0,1", "--up", "0,1,0"},
    {"m.ply", "--samples", "1000", "--memory-cap", "512", "--strategy", "paper", "--grid-level", "6"},
    {"--sigma-a", "0.1,0.2,0.3", "--sigma-s", "1,2,3", "--eta", "1.5", "--max-map", "1024",
     "--cell-samples", "16", "--opening-angle", "0.5", "--group-lengths", "4", "--exposure", "2"},
    {"--radius-mode", "per-point", "--coverage", "1e-3", "--radius-scale", "1.2", "--splatting",
     "discs", "--frames", "4", "--backend", "osmesa", "--texel-per-radius", "0.1"},
    {"--output", "o.png", "--linear", "o.pfm", "--stats", "o.json", "--bake", "o.ply", "--help"}};
  int n = 0;
  for (const auto& list : lists) {
    std::ofstream out(cli / ("args" + std::to_string(n++)), std::ios::binary);
    for (std::size_t i = 0; i < list.size(); ++i) out << (i ? std::string(1, '\0') : "") << list[i];
  }
  return 0;
}
