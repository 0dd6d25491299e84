// The PCL glue: every file form the loader accepts, normals kept or estimated and oriented,
// the radius from the spacing, colours as albedo, and one clear error per kind of bad input.
#include <gtest/gtest.h>
#include <pcl/PolygonMesh.h>
#include <pcl/conversions.h>
#include <pcl/io/pcd_io.h>
#include <pcl/io/ply_io.h>
#include <pcl/point_types.h>
#include <unistd.h>
#include <vtkDataArray.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkUnsignedCharArray.h>
#include <zlib.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <tuple>

#include "scan_io.h"
#include "sssPclLoading.h"
#include "sssPclMeshSampling.h"
#include "sssPclSurfels.h"

namespace {

namespace fs = std::filesystem;
constexpr double kPi = 3.14159265358979323846;

class PclGlue : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("sss-pcl-glue-" + std::to_string(getpid()));
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  std::string file(const std::string& name) const { return (dir_ / name).string(); }
  fs::path dir_;
};

// Points on a sphere of radius r on a latitude-longitude lattice, coloured by height.
pcl::PointCloud<pcl::PointXYZRGB> sphere_cloud(float r, int rings, int segments) {
  pcl::PointCloud<pcl::PointXYZRGB> cloud;
  for (int i = 1; i < rings; ++i)
    for (int j = 0; j < segments; ++j) {
      const double theta = kPi * i / rings, phi = 2.0 * kPi * j / segments;
      pcl::PointXYZRGB p;
      p.x = r * std::sin(theta) * std::cos(phi);
      p.y = r * std::sin(theta) * std::sin(phi);
      p.z = r * std::cos(theta);
      p.r = static_cast<std::uint8_t>(i * 255 / rings);
      p.g = 100;
      p.b = static_cast<std::uint8_t>(j * 255 / segments);
      cloud.push_back(p);
    }
  return cloud;
}

// An icosphere-like closed mesh: the lattice above triangulated, poles included.
pcl::PolygonMesh sphere_mesh(float r, int rings, int segments) {
  pcl::PointCloud<pcl::PointXYZ> vertices;
  vertices.push_back(pcl::PointXYZ(0, 0, r));
  for (const auto& p : sphere_cloud(r, rings, segments)) vertices.push_back(pcl::PointXYZ(p.x, p.y, p.z));
  vertices.push_back(pcl::PointXYZ(0, 0, -r));
  const auto at = [&](int ring, int segment) {  // ring 1..rings-1
    return static_cast<pcl::index_t>(1 + (ring - 1) * segments + (segment % segments));
  };
  pcl::PolygonMesh mesh;
  const auto add = [&](pcl::index_t a, pcl::index_t b, pcl::index_t c) {
    pcl::Vertices v;
    v.vertices = {a, b, c};
    mesh.polygons.push_back(v);
  };
  const pcl::index_t south = static_cast<pcl::index_t>(vertices.size() - 1);
  for (int j = 0; j < segments; ++j) {
    add(0, at(1, j), at(1, j + 1));
    add(south, at(rings - 1, j + 1), at(rings - 1, j));
    for (int i = 1; i + 1 < rings; ++i) {
      add(at(i, j), at(i + 1, j), at(i + 1, j + 1));
      add(at(i, j), at(i + 1, j + 1), at(i, j + 1));
    }
  }
  pcl::toPCLPointCloud2(vertices, mesh.cloud);
  return mesh;
}

Eigen::Vector3d point(vtkPolyData* p, vtkIdType i) {
  double x[3];
  p->GetPoint(i, x);
  return {x[0], x[1], x[2]};
}

Eigen::Vector3d normal(vtkPolyData* p, vtkIdType i) {
  double n[3];
  p->GetPointData()->GetNormals()->GetTuple(i, n);
  return {n[0], n[1], n[2]};
}

// Smallest n . x / |x| over the surfels: 1 for exact outward normals of a sphere at the origin.
double worst_radial_alignment(vtkPolyData* p) {
  double worst = 1.0;
  for (vtkIdType i = 0; i < p->GetNumberOfPoints(); ++i)
    worst = std::min(worst, normal(p, i).dot(point(p, i).normalized()));
  return worst;
}

TEST_F(PclGlue, PcdInEveryEncodingGivesTheSameSurfelsForEveryPointType) {
  const auto cloud = sphere_cloud(10.0f, 30, 60);
  pcl::PCDWriter writer;
  writer.writeASCII(file("a.pcd"), cloud);
  writer.writeBinary(file("b.pcd"), cloud);
  writer.writeBinaryCompressed(file("c.pcd"), cloud);
  for (const char* name : {"a.pcd", "b.pcd", "c.pcd"}) {
    const auto rgb = sss::makeSurfels(sss::loadPointCloud<pcl::PointXYZRGB>(file(name)));
    const auto xyz = sss::makeSurfels(sss::loadPointCloud<pcl::PointXYZ>(file(name)));
    const auto normal_type = sss::makeSurfels(sss::loadPointCloud<pcl::PointNormal>(file(name)));
    const auto both = sss::makeSurfels(sss::loadPointCloud<pcl::PointXYZRGBNormal>(file(name)));
    const auto surfel = sss::makeSurfels(sss::loadPointCloud<pcl::PointSurfel>(file(name)));
    for (const auto* s : {&rgb, &xyz, &normal_type, &both, &surfel}) {
      EXPECT_EQ(s->size(), cloud.size()) << name;
      EXPECT_TRUE(s->estimated_normals) << name;  // the file has none
      EXPECT_GT(worst_radial_alignment(s->polydata), 0.99) << name;
      EXPECT_DOUBLE_EQ(s->spacing, xyz.spacing) << name;
    }
    EXPECT_TRUE(rgb.has_colours);
    EXPECT_TRUE(both.has_colours);
    EXPECT_TRUE(surfel.has_colours);
    EXPECT_FALSE(xyz.has_colours);  // PointXYZ cannot keep them
    EXPECT_FALSE(normal_type.has_colours);
  }
}

TEST_F(PclGlue, NormalsInTheFileAreKeptAsGiven) {
  pcl::PointCloud<pcl::PointNormal> cloud;
  for (const auto& p : sphere_cloud(5.0f, 20, 40)) {
    pcl::PointNormal q;
    q.x = p.x, q.y = p.y, q.z = p.z;
    q.getNormalVector3fMap() = -q.getVector3fMap().normalized();  // inward on purpose
    cloud.push_back(q);
  }
  pcl::io::savePCDFileBinary(file("n.pcd"), cloud);
  const auto loaded = sss::loadPointCloud<pcl::PointXYZRGBNormal>(file("n.pcd"));
  EXPECT_TRUE(loaded.has_normals);
  const auto s = sss::makeSurfels(loaded);
  EXPECT_FALSE(s.estimated_normals);
  for (vtkIdType i = 0; i < s.polydata->GetNumberOfPoints(); ++i)
    ASSERT_NEAR(normal(s.polydata, i).dot(point(s.polydata, i).normalized()), -1.0, 1e-6);
}

TEST_F(PclGlue, OrganisedCloudKeepsItsShapeAndDropsItsHoles) {
  pcl::PointCloud<pcl::PointXYZ> grid(40, 30);  // a plane at z = 2 seen from the origin
  std::size_t holes = 0;
  for (int v = 0; v < 30; ++v)
    for (int u = 0; u < 40; ++u) {
      auto& p = grid.at(u, v);
      const bool hole = (u * 7 + v * 3) % 11 == 0;
      holes += hole;
      const float nan = std::numeric_limits<float>::quiet_NaN();
      p = hole ? pcl::PointXYZ(nan, nan, nan) : pcl::PointXYZ(0.01f * u, 0.01f * v, 2.0f);
    }
  grid.is_dense = false;
  pcl::io::savePCDFileBinaryCompressed(file("o.pcd"), grid);
  const auto loaded = sss::loadPointCloud<pcl::PointXYZ>(file("o.pcd"));
  EXPECT_EQ(loaded.cloud->width, 40u);
  EXPECT_EQ(loaded.cloud->height, 30u);
  const auto s = sss::makeSurfels(loaded);
  EXPECT_EQ(s.nonfinite_points, holes);
  EXPECT_EQ(s.size(), 1200 - holes);
  for (vtkIdType i = 0; i < s.polydata->GetNumberOfPoints(); ++i)  // towards the sensor at 0
    ASSERT_LT(normal(s.polydata, i).z(), -0.999);
}

TEST_F(PclGlue, SpacingIsTheMeanNearestNeighbourDistance) {
  pcl::PointCloud<pcl::PointXYZ> plane;
  const float h = 0.25f;
  for (int i = 0; i < 50; ++i)
    for (int j = 0; j < 50; ++j) plane.push_back(pcl::PointXYZ(h * i, h * j, 0.0f));
  EXPECT_NEAR(sss::makeSurfels(plane).spacing, h, 1e-6);
  plane.push_back(plane[0]);  // a duplicate does not make the spacing zero
  EXPECT_NEAR(sss::makeSurfels(plane).spacing, h, 1e-6);
}

TEST_F(PclGlue, ColoursBecomeTheAlbedoArray) {
  const auto cloud = sphere_cloud(3.0f, 10, 20);
  const auto s = sss::makeSurfels(cloud);
  auto* colours = vtkUnsignedCharArray::SafeDownCast(s.polydata->GetPointData()->GetScalars());
  ASSERT_NE(colours, nullptr);
  ASSERT_EQ(colours->GetNumberOfComponents(), 3);
  for (vtkIdType i = 0; i < colours->GetNumberOfTuples(); ++i) {
    EXPECT_EQ(colours->GetValue(3 * i), cloud[i].r);
    EXPECT_EQ(colours->GetValue(3 * i + 1), cloud[i].g);
    EXPECT_EQ(colours->GetValue(3 * i + 2), cloud[i].b);
  }
}

TEST_F(PclGlue, PlyPointsMeshVerticesAndGzip) {
  pcl::io::savePLYFileASCII(file("p.ply"), sphere_cloud(10.0f, 20, 40));
  const auto points = sss::loadPointCloud<pcl::PointXYZRGB>(file("p.ply"));
  EXPECT_EQ(points.cloud->size(), 19u * 40u);
  EXPECT_TRUE(points.has_colours);

  const pcl::PolygonMesh mesh = sphere_mesh(10.0f, 20, 40);
  pcl::io::savePLYFile(file("m.ply"), mesh);
  const auto vertices = sss::loadPointCloud<pcl::PointNormal>(file("m.ply"));
  EXPECT_EQ(vertices.cloud->size(), 19u * 40u + 2u);
  EXPECT_TRUE(vertices.has_normals);  // from the faces
  const auto s = sss::makeSurfels(vertices);
  EXPECT_FALSE(s.estimated_normals);
  EXPECT_GT(worst_radial_alignment(s.polydata), 0.98);

  {  // the same file gzipped
    std::ifstream in(file("m.ply"), std::ios::binary);
    const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    gzFile out = gzopen(file("m.ply.gz").c_str(), "wb");
    gzwrite(out, bytes.data(), static_cast<unsigned>(bytes.size()));
    gzclose(out);
  }
  const auto inflated = sss::makeSurfels(sss::loadPointCloud<pcl::PointNormal>(file("m.ply.gz")));
  ASSERT_EQ(inflated.size(), s.size());
  for (vtkIdType i = 0; i < s.polydata->GetNumberOfPoints(); ++i)
    ASSERT_EQ(point(inflated.polydata, i), point(s.polydata, i));
}

TEST_F(PclGlue, MeshSamplingIsUniformOnTheSurface) {
  const float r = 10.0f;
  pcl::io::savePLYFile(file("m.ply"), sphere_mesh(r, 40, 80));
  sss::LoadOptions options;
  options.mesh_samples = 20000;
  const auto loaded = sss::loadPointCloud<pcl::PointXYZRGBNormal>(file("m.ply"), options);
  ASSERT_EQ(loaded.cloud->size(), 20000u);
  EXPECT_TRUE(loaded.has_normals);
  EXPECT_FALSE(loaded.has_colours);  // the mesh has none
  // On the faceted sphere: between the inscribed faces' depth and r; normals are face normals.
  const double chord_depth = r * (1.0 - std::cos(kPi / 40.0));
  std::size_t upper = 0;
  for (const auto& p : *loaded.cloud) {
    const Eigen::Vector3f x = p.getVector3fMap();
    ASSERT_LE(x.norm(), r + 1e-4);
    ASSERT_GE(x.norm(), r - chord_depth - 1e-4);
    ASSERT_GT(p.getNormalVector3fMap().dot(x.normalized()), 0.99);
    upper += x.z() > 0.5f * r;
  }
  // Area above z = r/2 on a sphere is a quarter of the whole: 5000 expected, binomial sd 61.
  EXPECT_NEAR(static_cast<double>(upper), 5000.0, 4 * 61.0);
}

// A tetrahedron's corners (one at the origin) and the unit cube in quads, wound outward.
const char* const kTetrahedron = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\n";
const char* const kCube =
  "# a cube\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\n"
  "f 1 4 3 2\nf 5 6 7 8\nf 1 2 6 5\nf 2 3 7 6\nf -5 -1 -2 -6\nf 4 1 5 8\n";

TEST_F(PclGlue, ObjMeshVerticesAndSamples) {
  // Normals from the faces, area-weighted, outward: the corner's diagonal and the three axes;
  // vn given per corner (v/vt/vn, v//vn, relative indices) kept, normalised; a vertex given two
  // different vn (flat shading): all from the faces.
  const Eigen::Vector3f diagonal = Eigen::Vector3f::Ones().normalized(),
                        x = Eigen::Vector3f::UnitX(), y = Eigen::Vector3f::UnitY(),
                        z = Eigen::Vector3f::UnitZ();
  const std::tuple<std::string, std::string, std::vector<Eigen::Vector3f>, std::string> meshes[] = {
    {"faces.obj", "o tet\ns off\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n", {-diagonal, x, y, z},
     "OBJ mesh vertices, normals from 4 faces, 4 points, normals"},
    {"given.obj", "vt 0 0\nvn 0 0 2\nvn 0 3 0\nvn 4 0 0\nvn 1 1 1\nf -4//-4 -2//-2 -3//-3\n"
                  "f 1/1/1 2/1/2 4/1/4\nf 1//1 4//4 3//3\n", {z, y, x, diagonal},
     "OBJ mesh vertices, 4 points, normals"},
    {"flat.obj", "vn 0 0 1\nvn 0 1 0\nf 1//1 3//1 2//1\nf 1//2 2//2 4//2\nf 1 4 3\nf 2 3 4\n",
     {-diagonal, x, y, z}, "normals from 4 faces"}};
  for (const auto& [name, faces, normals, description] : meshes) {
    std::ofstream(file(name)) << kTetrahedron << faces;
    const auto mesh = sss::loadPointCloud<pcl::PointNormal>(file(name));
    ASSERT_EQ(mesh.cloud->size(), 4u) << name;
    for (int i = 0; i < 4; ++i)
      EXPECT_LT(((*mesh.cloud)[i].getNormalVector3fMap() - normals[i]).norm(), 1e-6) << name << i;
    EXPECT_NE(mesh.description.find(description), std::string::npos) << mesh.description;
  }

  // Quads, fanned: each corner's normal points out of all three faces it is on.
  std::ofstream(file("cube.obj")) << kCube;
  const auto cube = sss::loadPointCloud<pcl::PointNormal>(file("cube.obj"));
  for (const auto& p : *cube.cloud) {
    const Eigen::Vector3f outward = p.getVector3fMap() - Eigen::Vector3f::Constant(0.5f);
    EXPECT_TRUE((p.getNormalVector3fMap().array() * outward.array() > 0.1f).all()) << p;
    EXPECT_NEAR(p.getNormalVector3fMap().norm(), 1.0f, 1e-6) << p;
  }
  sss::LoadOptions sampled;
  sampled.mesh_samples = 3000;
  const auto samples = sss::loadPointCloud<pcl::PointNormal>(file("cube.obj"), sampled);
  ASSERT_EQ(samples.cloud->size(), 3000u);
  EXPECT_NE(samples.description.find("OBJ mesh, 6 faces sampled"), std::string::npos);
  int per_face[6] = {};
  for (const auto& p : *samples.cloud) {  // on a face, inside it, with its outward normal
    const Eigen::Vector3f at = p.getVector3fMap(), n = p.getNormalVector3fMap();
    int axis;
    ASSERT_NEAR(n.cwiseAbs().maxCoeff(&axis), 1.0f, 1e-6) << p;
    ASSERT_NEAR(at[axis], n[axis] > 0 ? 1.0f : 0.0f, 1e-6) << p;
    ASSERT_TRUE((at.array() >= -1e-6f).all() && (at.array() <= 1 + 1e-6f).all()) << p;
    ++per_face[2 * axis + (n[axis] > 0)];
  }
  for (int count : per_face) EXPECT_NEAR(count, 500, 4 * 20.4);  // binomial sd
}

void expect_input_error(const std::function<void()>& load, const std::string& words) {
  try {
    load();
    ADD_FAILURE() << "no error; expected one saying \"" << words << "\"";
  } catch (const sss::InputError& e) {
    EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << e.what();
  }
}

TEST_F(PclGlue, BadInputGivesOneClearError) {
  expect_input_error([&] { sss::loadPointCloud<pcl::PointXYZ>(file("absent.pcd")); },
                     "absent.pcd: cannot be opened");
  std::ofstream(file("cloud.las")) << "1 2 3\n";
  expect_input_error([&] { sss::loadPointCloud<pcl::PointXYZ>(file("cloud.las")); },
                     "unknown extension (use .pcd, .ply, .ply.gz, .obj, .xyz, .txt, .csv or .asc)");
  std::ofstream(file("garbage.pcd")) << "this is not a point cloud\n";
  expect_input_error([&] { sss::loadPointCloud<pcl::PointXYZ>(file("garbage.pcd")); },
                     "garbage.pcd: not a readable PCD file");
  std::ofstream(file("garbage.ply")) << "ply\nnonsense\n";
  expect_input_error([&] { sss::loadPointCloud<pcl::PointXYZ>(file("garbage.ply")); },
                     "garbage.ply: not a readable PLY file");
  std::ofstream(file("garbage.ply.gz")) << "not gzip either";
  expect_input_error([&] { sss::loadPointCloud<pcl::PointXYZ>(file("garbage.ply.gz")); },
                     "garbage.ply.gz");
  std::ofstream(file("empty.pcd"))
    << "VERSION 0.7\nFIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nCOUNT 1 1 1\nWIDTH 0\nHEIGHT 1\n"
       "VIEWPOINT 0 0 0 1 0 0 0\nPOINTS 0\nDATA ascii\n";
  expect_input_error([&] { sss::loadPointCloud<pcl::PointXYZ>(file("empty.pcd")); },
                     "empty.pcd: the file has no points");

  pcl::io::savePCDFileBinary(file("cut.pcd"), sphere_cloud(1.0f, 30, 60));
  fs::resize_file(file("cut.pcd"), fs::file_size(file("cut.pcd")) / 2);
  expect_input_error([&] { sss::loadPointCloud<pcl::PointXYZ>(file("cut.pcd")); },
                     "cut.pcd: its header claims 1740 points of 16 bytes (binary), at least 27 KiB "
                     "of data, but the file holds 14 KiB after its header");
  pcl::io::savePLYFileBinary(file("cut.ply"), sphere_cloud(1.0f, 30, 60));
  fs::resize_file(file("cut.ply"), fs::file_size(file("cut.ply")) / 2);
  expect_input_error([&] { sss::loadPointCloud<pcl::PointXYZ>(file("cut.ply")); },
                     "cut.ply: its header claims 1740 vertices, 1 camera element "
                     "(binary_little_endian), at least 26 KiB of data, but the file holds 12 KiB");

  pcl::PointCloud<pcl::PointXYZ> nan_cloud;
  const float nan = std::numeric_limits<float>::quiet_NaN();
  for (int i = 0; i < 100; ++i) nan_cloud.push_back(pcl::PointXYZ(nan, nan, nan));
  nan_cloud.is_dense = false;
  pcl::io::savePCDFileBinary(file("nan.pcd"), nan_cloud);
  expect_input_error(
    [&] { sss::makeSurfels(sss::loadPointCloud<pcl::PointXYZ>(file("nan.pcd"))); },
    "nan.pcd: no point has a finite position (100 points");

  pcl::PointCloud<pcl::PointXYZ> two;
  two.push_back(pcl::PointXYZ(0, 0, 0));
  two.push_back(pcl::PointXYZ(1, 0, 0));
  pcl::io::savePCDFileASCII(file("two.pcd"), two);
  expect_input_error(
    [&] { sss::makeSurfels(sss::loadPointCloud<pcl::PointXYZ>(file("two.pcd"))); },
    "two.pcd: 2 finite points, too few to estimate normals");

  pcl::PointCloud<pcl::PointXYZ> line;  // collinear: no plane through any neighbourhood
  for (int i = 0; i < 50; ++i) line.push_back(pcl::PointXYZ(0.1f * i, 0, 0));
  expect_input_error([&] { sss::makeSurfels(line); }, "too few neighbours");

  pcl::PointCloud<pcl::PointXYZ> one_place(20, 1, pcl::PointXYZ(1, 2, 3));
  expect_input_error([&] { sss::makeSurfels(one_place); }, "lie at one place");
}

// ASCII point lists: columns by a header or by their count, separators, comments, colours as
// 0-255 or 0-1, georeferenced coordinates; an OBJ of points.
TEST_F(PclGlue, PointListsReadTheirColumns) {
  struct Case {
    std::string name, text;
    float x[2][3], n[2][3];  // n all 0: no normals
    int rgb[2][3];           // all 0: no colours
  };
  const Case cases[] = {
    {"a.xyz", "# x, y, z of a scan\n1.5 -2 3e2\n4\t5 6\n", {{1.5f, -2, 300}, {4, 5, 6}}, {}, {}},
    {"points.obj", "v 1.5 -2 3e2\nv 4 5 6 1\n\nvt 0 1\n", {{1.5f, -2, 300}, {4, 5, 6}}, {}, {}},
    {"unit.txt", "0 0 0 0 0 1\n1 0 0 0.6 0.8 0\n", {{0, 0, 0}, {1, 0, 0}},
     {{0, 0, 1}, {0.6f, 0.8f, 0}}, {}},
    {"rgb.csv", "0,0,0,255,128,0\n1, 2, 3, 10, 20, 30\n", {{0, 0, 0}, {1, 2, 3}}, {},
     {{255, 128, 0}, {10, 20, 30}}},
    {"unit_rgb.asc", "0;0;0;1;0.5;0\n1;0;0;0.2;0.2;0.2\n", {{0, 0, 0}, {1, 0, 0}}, {},
     {{255, 128, 0}, {51, 51, 51}}},
    {"pts.txt", "2\n0 0 0 -100 255 128 0\n1 0 0 5 10 20 30\n", {{0, 0, 0}, {1, 0, 0}}, {},
     {{255, 128, 0}, {10, 20, 30}}},
    {"cc.txt", "//X,Y,Z,R,G,B\n1,2,3,1,0,0\n4,5,6,0,1,0\n",  // unit vectors, but named colours
     {{1, 2, 3}, {4, 5, 6}}, {}, {{255, 0, 0}, {0, 255, 0}}},
    {"nine.xyz", "1 2 3 255 0 0 0 0 1\n4 5 6 0 255 0 1 0 0\n", {{1, 2, 3}, {4, 5, 6}},
     {{0, 0, 1}, {1, 0, 0}}, {{255, 0, 0}, {0, 255, 0}}},
    {"nine_normals_first.xyz", "1 2 3 0 0 1 255 0 0\n4 5 6 1 0 0 0 255 0\n",
     {{1, 2, 3}, {4, 5, 6}}, {{0, 0, 1}, {1, 0, 0}}, {{255, 0, 0}, {0, 255, 0}}},
    {"named.txt",
     "# scan of 2 points\n\nX\tY\tZ\tIntensity\tNX\tNY\tNZ\n// a comment\n"
     "1 2 3 0.5 0 1 0\n# another\n4 5 6 7 0 0 -1\n",
     {{1, 2, 3}, {4, 5, 6}}, {{0, 1, 0}, {0, 0, -1}}, {}},
    {"utm.xyz", "500000.25 4000000.5 123.125\r\n500001 4000001 124\r\n",
     {{500000.25f, 4000000.5f, 123.125f}, {500001, 4000001, 124}}, {}, {}}};
  for (const Case& c : cases) {
    std::ofstream(file(c.name)) << c.text;
    const auto loaded = sss::loadPointCloud<pcl::PointXYZRGBNormal>(file(c.name));
    ASSERT_EQ(loaded.cloud->size(), 2u) << c.name;
    EXPECT_EQ(loaded.has_normals, Eigen::Vector3f::Map(c.n[0]).any()) << c.name;
    EXPECT_EQ(loaded.has_colours, Eigen::Vector3i::Map(c.rgb[0]).any()) << c.name;
    for (int i = 0; i < 2; ++i) {  // normals and colours the file lacks stay 0
      const auto& p = (*loaded.cloud)[i];
      EXPECT_EQ(p.getVector3fMap(), Eigen::Vector3f::Map(c.x[i])) << c.name;
      EXPECT_EQ(p.getNormalVector3fMap(), Eigen::Vector3f::Map(c.n[i])) << c.name;
      EXPECT_EQ(Eigen::Vector3i(p.r, p.g, p.b), Eigen::Vector3i::Map(c.rgb[i])) << c.name;
    }
  }
}

// Bad OBJ and ASCII files: one message naming the file and what is wrong (test_render_input too).
TEST_F(PclGlue, BadObjAndAsciiFilesGiveOneClearError) {
  const sss::LoadOptions sampled{10}, capped{0, 1, 1 << 10};  // 10 samples; a cap of 1 KiB
  const std::string obj = std::string(kTetrahedron), unreadable = "not a readable OBJ file (line ";
  const std::tuple<std::string, std::string, std::string, sss::LoadOptions> cases[] = {
    {"a.obj", obj + "f 1 2 9\n",
     unreadable + "5, vertex index 9 names none of the 4 vertices before it)", {}},
    {"b.obj", obj + "vn 0 0 1\nf 1//1 2//1 3//2\n",
     unreadable + "6, normal index 2 names none of the 1 normals before it)", {}},
    {"c.obj", "# nothing\no thing\n", "the file has no points", {}},
    {"d.obj", "v 0 0 0\n", "mesh sampling asked for, but the OBJ file has no faces", sampled},
    {"e.obj", kCube, "its lines hold 8 vertices, 0 normals, 6 faces, which would need 1.5 KiB in "
                     "memory, over the memory cap of 1.0 KiB", capped},
    {"b.xyz", "", "the file has no points", {}},
    {"c.csv", std::string(100, '\n'), "its 100 lines (a point each at most), which would need "
                                      "14 KiB in memory, over the memory cap of 1.0 KiB", capped}};
  for (const auto& [name, text, words, options] : cases) {
    std::ofstream(file(name)) << text;
    expect_input_error([&] { sss::loadPointCloud<pcl::PointXYZ>(file(name), options); },
                       file(name) + ": " + words);
  }
}

// The text of a file, with `from` replaced by `to` once.
void rewrite(const std::string& path, const std::string& from, const std::string& to) {
  std::ifstream in(path, std::ios::binary);
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::size_t at = text.find(from);
  ASSERT_NE(at, std::string::npos) << from;
  text.replace(at, from.size(), to);
  std::ofstream(path, std::ios::binary | std::ios::trunc) << text;
}

void gzip(const std::string& from, const std::string& to) {
  std::ifstream in(from, std::ios::binary);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  gzFile out = gzopen(to.c_str(), "wb");
  gzwrite(out, text.data(), static_cast<unsigned>(text.size()));
  gzclose(out);
}

// Headers that claim more than the file holds, or than the memory cap allows, are refused by
// a message naming the file, the claim and the size, before PCL allocates for the claim.
TEST_F(PclGlue, LyingHeadersAreRefusedBeforeAllocating) {
  const pcl::PointCloud<pcl::PointXYZRGB> cloud = sphere_cloud(1.0f, 30, 60);  // 1740 points
  struct Case {
    std::string name, words;
    sss::LoadOptions options;
  };
  std::vector<Case> cases;
  auto add = [&](const std::string& name, const std::string& words, std::size_t cap = 0,
                 std::size_t samples = 0) {
    sss::LoadOptions options;
    options.memory_cap = cap;
    options.mesh_samples = samples;
    cases.push_back({name, words, options});
  };

  pcl::io::savePCDFileASCII(file("version.pcd"), cloud);
  rewrite(file("version.pcd"), "VERSION", "V@RSION");  // crashed PCL's reader
  add("version.pcd", "header line 2, 'V@RSION 0.7', is not a PCD header line");
  pcl::io::savePCDFileASCII(file("billion.pcd"), cloud);
  rewrite(file("billion.pcd"), "WIDTH 1740", "WIDTH 1000000000");
  rewrite(file("billion.pcd"), "POINTS 1740", "POINTS 1000000000");
  add("billion.pcd", "claims 1000000000 points of 16 bytes (ascii), at least 7.5 GiB of data");
  pcl::io::savePCDFileBinary(file("more.pcd"), cloud);
  rewrite(file("more.pcd"), "WIDTH 1740", "WIDTH 1741");
  rewrite(file("more.pcd"), "POINTS 1740", "POINTS 1741");
  add("more.pcd", "claims 1741 points of 16 bytes (binary), at least 27856 bytes of data, but "
                  "the file holds 27840 bytes after its header");
  pcl::io::savePCDFileBinaryCompressed(file("inflate.pcd"), cloud);
  rewrite(file("inflate.pcd"), "WIDTH 1740", "WIDTH 1739");
  rewrite(file("inflate.pcd"), "POINTS 1740", "POINTS 1739");
  add("inflate.pcd", "claims 1739 points of 16 bytes (27824 bytes), but its compressed data "
                     "inflate to 27840 bytes");
  pcl::io::savePCDFileASCII(file("points.pcd"), cloud);
  rewrite(file("points.pcd"), "POINTS 1740", "POINTS 1739");
  add("points.pcd", "WIDTH 1740 x HEIGHT 1 is not POINTS 1739");
  pcl::io::savePCDFileASCII(file("size.pcd"), cloud);
  rewrite(file("size.pcd"), "SIZE 4 4 4 4", "SIZE 4 4 4 4 4");
  add("size.pcd", "FIELDS names 4 fields, but SIZE, TYPE or COUNT has 5 entries");
  pcl::io::savePCDFileASCII(file("negative.pcd"), cloud);
  rewrite(file("negative.pcd"), "WIDTH 1740", "WIDTH -1740");
  add("negative.pcd", "WIDTH '-1740' is not a whole number");
  pcl::io::savePCDFileBinary(file("capped.pcd"), cloud);
  add("capped.pcd", "claims 1740 points of 16 bytes, which would need 82 KiB in memory, over "
                    "the memory cap of 64 KiB", 64 << 10);

  std::ofstream(file("order.pcd"))  // PCL sized its buffer at POINTS, then wrote 3x past it
    << "FIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nWIDTH 2\nHEIGHT 1\nPOINTS 2\nCOUNT 3 3 3\n"
       "DATA ascii\n1 2 3 4 5 6 7 8 9\n1 2 3 4 5 6 7 8 9\n";
  add("order.pcd", "needs FIELDS, SIZE, TYPE and COUNT in that order, before POINTS");
  pcl::io::savePCDFileBinary(file("after.pcd"), cloud);  // PCL reads header lines after DATA
  rewrite(file("after.pcd"), "DATA binary\n", "DATA binary\nPOINTS 3000000000\n");
  add("after.pcd", "a POINTS line after DATA");

  std::ofstream(file("billion.ply"), std::ios::binary)
    << "ply\nformat binary_little_endian 1.0\nelement vertex 2000000000\nproperty float x\n"
       "property float y\nproperty float z\nend_header\n";
  add("billion.ply", "claims 2000000000 vertices (binary_little_endian), at least 22 GiB of "
                     "data, but the file holds 0 bytes after its header");
  pcl::io::savePLYFile(file("faces.ply"), sphere_mesh(1.0f, 30, 60));  // ascii
  rewrite(file("faces.ply"), "element face 3480", "element face 34800000");
  add("faces.ply", "claims 1742 vertices, 34800000 faces (ascii)");
  pcl::io::savePLYFileBinary(file("type.ply"), cloud);
  rewrite(file("type.ply"), "property float x", "property float128 x");
  add("type.ply", "not a readable PLY file (header line 5, 'property float128 x')");
  pcl::io::savePLYFileBinary(file("sizes.ply"), cloud);  // PCL's atoi: 1 x 1 for 1740
  rewrite(file("sizes.ply"), "element vertex", "obj_info num_cols -4294967295\n"
                                               "obj_info num_rows -4294967295\nelement vertex");
  add("sizes.ply", "obj_info gives 1 x 1 points for its 1740 vertices");
  pcl::io::savePLYFileBinary(file("indent.ply"), cloud);  // PCL's reader aborted on this
  rewrite(file("indent.ply"), "element vertex", " obj_info is_mesh 0\nelement vertex");
  add("indent.ply", "obj_info after white space");
  gzip(file("billion.ply"), file("billion.ply.gz"));
  add("billion.ply.gz", "billion.ply.gz: its header claims 2000000000 vertices");
  pcl::io::savePLYFileBinary(file("capped.ply"), cloud);
  gzip(file("capped.ply"), file("capped.ply.gz"));
  add("capped.ply.gz", "inflates to more than the memory cap of 16 KiB", 16 << 10);
  pcl::io::savePLYFileBinary(file("mesh.ply"), sphere_mesh(1.0f, 30, 60));
  add("mesh.ply", "1000000000 mesh samples would need 75 GiB in memory, over the memory cap of "
                  "1.0 GiB", std::size_t{1} << 30, 1000000000);

  for (const Case& c : cases) {
    try {
      sss::loadPointCloud<pcl::PointXYZRGB>(file(c.name), c.options);
      ADD_FAILURE() << c.name << ": loaded; expected \"" << c.words << "\"";
    } catch (const sss::InputError& e) {
      std::printf("[ lying header ] %s\n", e.what());
      EXPECT_NE(std::string(e.what()).find(c.words), std::string::npos) << e.what();
      EXPECT_EQ(std::string(e.what()).rfind(file(c.name), 0), 0u) << "names the file";
    }
  }
  // Forms PCL reads that the checks let through: a PCD without WIDTH and HEIGHT (before 0.7),
  // a blank line in a PLY header.
  pcl::io::savePCDFileASCII(file("old.pcd"), cloud);
  rewrite(file("old.pcd"), "WIDTH 1740\nHEIGHT 1\n", "");
  EXPECT_EQ(sss::loadPointCloud<pcl::PointXYZRGB>(file("old.pcd")).cloud->size(), 1740u);
  pcl::io::savePLYFileBinary(file("blank.ply"), cloud);
  rewrite(file("blank.ply"), "element vertex", "\nelement vertex");
  EXPECT_EQ(sss::loadPointCloud<pcl::PointXYZRGB>(file("blank.ply")).cloud->size(), 1740u);
  // The honest files these came from still load, under a cap that fits them.
  sss::LoadOptions fits;
  fits.memory_cap = 1 << 20;
  EXPECT_EQ(sss::loadPointCloud<pcl::PointXYZRGB>(file("capped.pcd"), fits).cloud->size(), 1740u);
  EXPECT_EQ(sss::loadPointCloud<pcl::PointXYZRGB>(file("capped.ply.gz"), fits).cloud->size(), 1740u);
}

// Every shared file passes the header checks and loads with its header's point count.
TEST(PclGlueScans, EverySharedFileLoadsWithItsHeadersCount) {
  const std::pair<const char*, std::size_t> files[] = {
    {"bunny.pcd", 397}, {"bun0.pcd", 397}, {"milk.pcd", 13704}, {"milk_color.pcd", 13704},
    {"milk_cartoon_all_small_clorox.pcd", 307200}, {"table_scene_mug_stereo_textured.pcd", 307200},
    {"stanford_bunny.ply", 35947}, {"dragon_vrip_res2.ply.gz", 100250},
    {"CSite1_red1-utm.pcd", 522674}};
  int found = 0;
  for (const auto& [name, points] : files) {
    const std::string path = sss::test::shared_data(name);
    if (path.empty()) continue;
    ++found;
    EXPECT_EQ(sss::loadPointCloud<pcl::PointXYZ>(path).cloud->size(), points) << name;
  }
  if (found == 0) GTEST_SKIP() << "the shared data folder is absent";
}

TEST(PclGlueScans, SharedCloudsLoad) {
  const std::string organised = sss::test::shared_data("milk_cartoon_all_small_clorox.pcd");
  const std::string with_normals = sss::test::shared_data("bun0.pcd");
  if (organised.empty() || with_normals.empty())
    GTEST_SKIP() << "milk_cartoon_all_small_clorox.pcd or bun0.pcd is not in the shared data folder";
  const auto kinect = sss::loadPointCloud<pcl::PointXYZRGB>(organised);
  EXPECT_EQ(kinect.cloud->height, 480u);
  const auto s = sss::makeSurfels(kinect);
  std::printf("%s\n%s\n", kinect.description.c_str(), s.summary().c_str());
  EXPECT_EQ(s.nonfinite_points, 307200u - 241407u);  // the shared data README's counts
  EXPECT_TRUE(s.has_colours);
  EXPECT_LT(s.points_without_normal, 241407u / 1000);  // isolated points only
  const auto bunny = sss::loadPointCloud<pcl::PointNormal>(with_normals);
  EXPECT_TRUE(bunny.has_normals);
  EXPECT_FALSE(sss::makeSurfels(bunny).estimated_normals);
}

}  // namespace
