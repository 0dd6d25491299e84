// sss_render's refusals: every kind of bad input gives one message, a non-zero exit and no
// output file; a good organised cloud with holes and colours renders.
#include <gtest/gtest.h>
#include <pcl/io/pcd_io.h>
#include <pcl/point_types.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>
#include <tuple>

namespace {

namespace fs = std::filesystem;

struct RenderRun {
  int status;
  std::string errors;
};

RenderRun render(const std::string& input, const std::string& stem) {
  const std::string log = stem + ".err";
  const std::string command = std::string("env -u DISPLAY '") + SSS_RENDER_PATH + "' '" + input +
                              "' --size 64x64 --output " + stem + ".png --linear " + stem +
                              ".pfm --bake " + stem + ".ply --stats " + stem + ".json 2> " + log;
  RenderRun run{std::system(command.c_str()), ""};
  std::ifstream in(log);
  std::stringstream text;
  text << in.rdbuf();
  run.errors = text.str();
  return run;
}

bool any_output(const std::string& stem) {
  for (const char* ext : {".png", ".pfm", ".ply", ".json"})
    if (fs::exists(stem + ext)) return true;
  return false;
}

void expect_refused(const std::string& input, const std::string& words) {
  const std::string stem = "refused_" + fs::path(input).filename().string();
  const RenderRun run = render(input, stem);
  EXPECT_NE(run.status, 0) << input;
  EXPECT_NE(run.errors.find(words), std::string::npos) << run.errors;
  EXPECT_EQ(std::count(run.errors.begin(), run.errors.end(), '\n'), 1) << run.errors;
  EXPECT_FALSE(any_output(stem)) << input << ": an output file was written";
}

TEST(RenderInput, BadInputGivesOneMessageNonZeroExitAndNoFile) {
  expect_refused("absent.pcd", "absent.pcd: cannot be opened");
  std::ofstream("points.las") << "1 2 3\n";
  expect_refused("points.las", "unknown extension (use .pcd, .ply, .ply.gz, .obj, .xyz, .txt, "
                               ".csv or .asc)");
  std::ofstream("empty.pcd")
    << "VERSION 0.7\nFIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nCOUNT 1 1 1\nWIDTH 0\nHEIGHT 1\n"
       "VIEWPOINT 0 0 0 1 0 0 0\nPOINTS 0\nDATA ascii\n";
  expect_refused("empty.pcd", "the file has no points");

  const float nan = std::numeric_limits<float>::quiet_NaN();
  pcl::PointCloud<pcl::PointXYZ> holes(8, 8, pcl::PointXYZ(nan, nan, nan));
  holes.is_dense = false;
  pcl::io::savePCDFileBinaryCompressed("all_nan.pcd", holes);
  expect_refused("all_nan.pcd", "no point has a finite position");

  pcl::PointCloud<pcl::PointXYZ> two;
  two.push_back(pcl::PointXYZ(0, 0, 0));
  two.push_back(pcl::PointXYZ(1, 0, 0));
  pcl::io::savePCDFileASCII("two_points.pcd", two);
  expect_refused("two_points.pcd", "too few to estimate normals");

  // A header PCL's reader crashed on, and one that made it allocate until killed.
  pcl::io::savePCDFileASCII("version.pcd", two);
  {
    std::ifstream in("version.pcd");
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    text.replace(text.find("VERSION"), 7, "V@RSION");
    std::ofstream("version.pcd", std::ios::trunc) << text;
  }
  expect_refused("version.pcd", "'V@RSION 0.7', is not a PCD header line");
  std::ofstream("billion.ply")
    << "ply\nformat binary_little_endian 1.0\nelement vertex 2000000000\nproperty float x\n"
       "property float y\nproperty float z\nend_header\n";
  expect_refused("billion.ply", "billion.ply: its header claims 2000000000 vertices");
}

// OBJ and ASCII point lists: the line that is wrong and why.
TEST(RenderInput, BadObjAndAsciiLinesAreNamed) {
  const std::string obj = ": not a readable OBJ file (line ";
  const std::tuple<std::string, std::string, std::string> cases[] = {
    {"garbage.obj", "this is garbage\n", obj + "1, 'this is garbage' is not an OBJ line)"},
    {"forward.obj", "f 1 2 3\nv 0 0 0\n", obj + "1, vertex index 1 names none of the 0"},
    {"word.obj", "v 0 0 0\nv 1 x 0\n", obj + "2, 'x' is not a number)"},
    {"short.obj", "v 0 0\n", obj + "1, 'v 0 0' has 2 numbers, not 3 to 6)"},
    {"corners.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2\n", obj + "4, a face needs 3 corners)"},
    {"columns.xyz", "1 2 3\n\n4 5\n", ": line 3: 2 columns, not 3 as line 1 has"},
    {"header.txt", "x y z r g b\n1 2 3 4 5 6\n1 2 3\n",
     ": line 3: 3 columns, not 6 as its header names"},
    {"word.csv", "1,2,3\n4,five,6\n", ": line 2: column 2, 'five', is not a number"},
    {"five.asc", "1 2 3 4 5\n",
     ": line 1: 5 columns; without a header naming them, use 3 (x y z), 4, 6, 7 or 9"},
    {"names.txt", "a b c\n1 2 3\n",
     ": line 1: 'a b c' is not a point, a comment or a header naming x, y and z"},
    {"late_header.xyz", "1 2 3\nx y z\n", ": line 2: 'x y z' is not a point"},
    {"count_only.xyz", "# a comment\n12\n", ": the file has no points"}};
  for (const auto& [name, text, message] : cases) {
    std::ofstream(name) << text;
    expect_refused(name, name + message);
  }
}

// Setting names are checked before anything is loaded or drawn: a wrong one is refused with
// the names that exist.
TEST(RenderInput, UnknownSettingNamesAreRefusedWithTheKnownOnes) {
  const std::pair<const char*, const char*> cases[] = {
      {"--quality fastest", "--quality: 'fastest' is not a quality preset: use interactive, "
                            "balanced or accurate"},
      {"--strategy fast", "--strategy: 'fast' is not near-far or paper"},
      {"--fit sideways", "--fit: needs surface or all, not 'sideways'"},
      {"--isolated 1", "--isolated: needs a ratio above 1 (up to 1e6) or keep"}};
  for (const auto& [flags, words] : cases) {
    const std::string command = std::string("env -u DISPLAY '") + SSS_RENDER_PATH + "' " + flags +
                                " --output refused_setting.png 2> refused_setting.err";
    EXPECT_NE(std::system(command.c_str()), 0) << flags;
    std::ifstream in("refused_setting.err");
    const std::string errors((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    EXPECT_NE(errors.find(words), std::string::npos) << errors;
    EXPECT_FALSE(fs::exists("refused_setting.png")) << flags;
  }
}

TEST(RenderInput, OrganisedCloudWithHolesAndColoursRenders) {
  pcl::PointCloud<pcl::PointXYZRGB> dome(48, 48);  // a coloured cap seen from the sensor
  for (int v = 0; v < 48; ++v)
    for (int u = 0; u < 48; ++u) {
      pcl::PointXYZRGB& p = dome.at(u, v);
      const float x = (u - 23.5f) * 0.5f, y = (v - 23.5f) * 0.5f;
      const bool hole = x * x + y * y > 120.0f || (u + v) % 13 == 0;
      const float nan = std::numeric_limits<float>::quiet_NaN();
      p.x = hole ? nan : x;
      p.y = hole ? nan : y;
      p.z = hole ? nan : 40.0f + 0.02f * (x * x + y * y);
      p.r = 250, p.g = static_cast<std::uint8_t>(4 * u), p.b = 60;
    }
  dome.is_dense = false;
  pcl::io::savePCDFileBinary("dome.pcd", dome);
  const RenderRun run = render("dome.pcd", "dome");
  EXPECT_EQ(run.status, 0) << run.errors;
  EXPECT_NE(run.errors.find("colours as albedo"), std::string::npos) << run.errors;
  EXPECT_NE(run.errors.find("non-finite dropped"), std::string::npos) << run.errors;
  EXPECT_TRUE(fs::exists("dome.png"));
}

}  // namespace
