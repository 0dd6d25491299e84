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
  std::ofstream("points.xyz") << "1 2 3\n";
  expect_refused("points.xyz", "unknown extension");
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

// Setting names are checked before anything is loaded or drawn: a wrong one is refused with
// the names that exist.
TEST(RenderInput, UnknownSettingNamesAreRefusedWithTheKnownOnes) {
  const std::pair<const char*, const char*> cases[] = {
      {"--quality fastest", "--quality: 'fastest' is not a quality preset: use interactive, "
                            "balanced or accurate"},
      {"--strategy fast", "--strategy: 'fast' is not near-far or paper"}};
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
