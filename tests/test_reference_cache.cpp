#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <functional>
#include <random>
#include <regex>
#include <string>

#include "procedural_shapes.h"
#include "reference_cache.h"

namespace sss {
namespace {

namespace fs = std::filesystem;

// A marble sphere of 3 mm (718 surfels) lit from one side, with a small light map and few
// samples per cell: a reference in about 0.1 s.
struct Scene {
  SurfelCloud cloud = make_sphere(3.0, 0.4);
  Material material = Material::preset("marble");
  std::vector<Light> lights{{Eigen::Vector3d(0.3, 0.2, 1.0), 1.0}};
  ReferenceSettings settings;
  Scene() {
    settings.light_map.texel_per_radius = 0.5;
    settings.light_map.max_map_size = 128;
    settings.irradiance_samples = 16;
  }
  ReferenceKey key() const { return ReferenceKey::of(cloud, material, lights, settings); }
};

class ReferenceCache : public ::testing::Test {
 protected:
  void SetUp() override {
    std::random_device entropy;
    dir_ = fs::temp_directory_path() / ("sss_reference_cache_test_" + std::to_string(entropy()));
    fs::remove_all(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path dir_;
};

void expect_same(const SurfelRadiance& a, const SurfelRadiance& b) {
  ASSERT_EQ(a.B.size(), b.B.size());
  for (std::size_t i = 0; i < a.B.size(); ++i)
    for (int c = 0; c < 3; ++c) ASSERT_EQ(a.B[i][c], b.B[i][c]) << "surfel " << i;
  EXPECT_EQ(a.stats.surfels, b.stats.surfels);
  EXPECT_EQ(a.stats.lit_cells, b.stats.lit_cells);
  EXPECT_EQ(a.stats.texel_mm, b.stats.texel_mm);
  EXPECT_EQ(a.stats.map_width, b.stats.map_width);
  EXPECT_EQ(a.stats.map_height, b.stats.map_height);
}

TEST_F(ReferenceCache, HitReturnsExactlyTheStoredValuesWithoutRecomputing) {
  Scene scene;
  std::size_t progress_calls = 0;
  scene.settings.progress = [&](std::size_t, std::size_t) { ++progress_calls; };

  ReferenceCacheStatus first;
  const SurfelRadiance computed = cached_reference(dir_, scene.cloud, scene.material,
                                                   scene.lights, scene.settings, &first);
  EXPECT_FALSE(first.hit);
  EXPECT_TRUE(first.stored) << first.message;
  EXPECT_GT(progress_calls, 0u);  // the convenience function passes the progress through
  ASSERT_EQ(computed.B.size(), scene.cloud.size());
  EXPECT_GT(computed.stats.lit_cells, 0u);

  progress_calls = 0;
  ReferenceCacheStatus second;
  const SurfelRadiance read = cached_reference(dir_, scene.cloud, scene.material, scene.lights,
                                               scene.settings, &second);
  EXPECT_TRUE(second.hit) << second.message;
  EXPECT_FALSE(second.stored);
  EXPECT_EQ(progress_calls, 0u);
  expect_same(read, computed);
  // The seconds are those of the run that computed it.
  EXPECT_EQ(read.stats.seconds_surfels, computed.stats.seconds_surfels);

  // One file, named by the material and the key, and no temporary left behind.
  std::vector<fs::path> files;
  for (const auto& entry : fs::directory_iterator(dir_)) files.push_back(entry.path());
  ASSERT_EQ(files.size(), 1u);
  EXPECT_EQ(files[0], first.file);
  EXPECT_TRUE(std::regex_match(files[0].filename().string(),
                               std::regex("marble-[0-9a-f]{16}\\.sssref")));
}

TEST_F(ReferenceCache, ChangingAnyKeyFieldIsAMiss) {
  const Scene base;
  store_cached_reference(dir_, base.key(),
                         render_reference(base.cloud, base.material, base.lights, base.settings));
  ASSERT_TRUE(load_cached_reference(dir_, base.key()).has_value());

  const std::vector<std::pair<std::string, std::function<void(Scene&)>>> changes{
      {"one light direction component", [](Scene& s) { s.lights[0].direction.y() += 1e-9; }},
      {"light irradiance", [](Scene& s) { s.lights[0].irradiance = 2.0; }},
      {"a second light", [](Scene& s) { s.lights.push_back(s.lights[0]); }},
      {"eta", [](Scene& s) { s.material.eta[1] = 1.31; }},
      {"sigma_a", [](Scene& s) { s.material.sigma_a[2] *= 1.01; }},
      {"sigma_s'", [](Scene& s) { s.material.sigma_s_prime[0] *= 1.01; }},
      {"mm per unit", [](Scene& s) { s.material.mm_per_unit = 1.5; }},
      {"one point's position", [](Scene& s) { s.cloud.positions[17].z() += 1e-6; }},
      {"one point's normal", [](Scene& s) { s.cloud.normals[17] = -s.cloud.normals[17]; }},
      {"albedo", [](Scene& s) { s.cloud.albedo.assign(s.cloud.size(), Rgb{1, 1, 1}); }},
      {"radius", [](Scene& s) { s.cloud.radius *= 1.5; }},
      {"texel per radius", [](Scene& s) { s.settings.light_map.texel_per_radius = 0.25; }},
      {"largest map", [](Scene& s) { s.settings.light_map.max_map_size = 256; }},
      {"samples per cell", [](Scene& s) { s.settings.irradiance_samples = 8; }},
      {"refined samples", [](Scene& s) { s.settings.irradiance_refined = 256; }},
      {"receivers", [](Scene& s) { s.settings.receivers = {1, 2, 3}; }},
      {"tree opening", [](Scene& s) { s.settings.tree.theta = 0.2; }},
      {"tree leaf size", [](Scene& s) { s.settings.tree.leaf_size = 16; }},
      {"kernel tolerance", [](Scene& s) { s.settings.tree.kernel_tolerance = 1e-6; }},
  };
  for (const auto& [what, change] : changes) {
    Scene changed;
    change(changed);
    EXPECT_NE(changed.key().hash, base.key().hash) << what;
    std::string problem;
    EXPECT_FALSE(load_cached_reference(dir_, changed.key(), &problem).has_value()) << what;
    EXPECT_EQ(problem, "") << what;  // simply absent
  }

  // What does not change the result does not change the key: the material's name aside from
  // the file name, the progress callback, and the sign of a zero.
  Scene same;
  same.material.name = "another name";
  same.settings.progress = [](std::size_t, std::size_t) {};
  same.lights[0].direction = Eigen::Vector3d(0.3, 0.2, 1.0);
  EXPECT_EQ(same.key().hash, base.key().hash);
  Scene zeros, negative_zeros;
  zeros.lights[0].direction = Eigen::Vector3d(0.0, 0.0, 1.0);
  negative_zeros.lights[0].direction = Eigen::Vector3d(-0.0, -0.0, 1.0);
  EXPECT_EQ(zeros.key().hash, negative_zeros.key().hash);

  // End to end: a changed eta is computed anew, and its B differs.
  Scene changed;
  changed.material.eta = {1.5, 1.5, 1.5};
  ReferenceCacheStatus status;
  const SurfelRadiance other = cached_reference(dir_, changed.cloud, changed.material,
                                                changed.lights, changed.settings, &status);
  EXPECT_FALSE(status.hit);
  EXPECT_TRUE(status.stored) << status.message;
  const SurfelRadiance original = *load_cached_reference(dir_, base.key());
  EXPECT_NE(other.B[0], original.B[0]);
}

TEST_F(ReferenceCache, TruncatedOrCorruptFileIsRecomputedAndRewritten) {
  const Scene scene;
  ReferenceCacheStatus status;
  const SurfelRadiance original = cached_reference(dir_, scene.cloud, scene.material,
                                                   scene.lights, scene.settings, &status);
  ASSERT_TRUE(status.stored) << status.message;
  const fs::path file = status.file;
  const std::uintmax_t whole = fs::file_size(file);

  const auto recomputes_and_rewrites = [&](const std::string& expected_problem) {
    std::string problem;
    EXPECT_FALSE(load_cached_reference(dir_, scene.key(), &problem).has_value());
    EXPECT_NE(problem.find(expected_problem), std::string::npos) << problem;
    ReferenceCacheStatus again;
    const SurfelRadiance recomputed = cached_reference(dir_, scene.cloud, scene.material,
                                                       scene.lights, scene.settings, &again);
    EXPECT_FALSE(again.hit);
    EXPECT_TRUE(again.stored) << again.message;
    EXPECT_NE(again.message.find(expected_problem), std::string::npos) << again.message;
    expect_same(recomputed, original);
    EXPECT_EQ(fs::file_size(file), whole);
    EXPECT_TRUE(load_cached_reference(dir_, scene.key()).has_value());
  };

  fs::resize_file(file, whole - 12);
  recomputes_and_rewrites("truncated");

  fs::resize_file(file, 20);  // shorter than the header
  recomputes_and_rewrites("truncated");

  {  // one flipped bit inside B
    std::fstream bytes(file, std::ios::binary | std::ios::in | std::ios::out);
    bytes.seekg(static_cast<std::streamoff>(whole / 2));
    const char c = static_cast<char>(bytes.get());
    bytes.seekp(static_cast<std::streamoff>(whole / 2));
    bytes.put(static_cast<char>(c ^ 0x10));
  }
  recomputes_and_rewrites("checksum");

  {  // the right size, not a cache file at all
    std::ofstream garbage(file, std::ios::binary | std::ios::trunc);
    garbage << std::string(whole, 'x');
  }
  recomputes_and_rewrites("not a reference cache file");

  // The same name and hash with another surfel count: the file is for another cloud.
  ReferenceKey other_count = scene.key();
  other_count.surfels += 1;
  std::string problem;
  EXPECT_FALSE(load_cached_reference(dir_, other_count, &problem).has_value());
  EXPECT_NE(problem.find("surfels"), std::string::npos) << problem;
  EXPECT_THROW(store_cached_reference(dir_, other_count, original), std::invalid_argument);
}

TEST_F(ReferenceCache, UnwritableFolderStillReturnsTheResult) {
  const Scene scene;
  fs::create_directories(dir_);
  { std::ofstream(dir_ / "plain_file") << "not a folder"; }
  const fs::path unwritable = dir_ / "plain_file" / "cache";  // holds even for root

  ReferenceCacheStatus status;
  const SurfelRadiance result = cached_reference(unwritable, scene.cloud, scene.material,
                                                 scene.lights, scene.settings, &status);
  EXPECT_FALSE(status.hit);
  EXPECT_FALSE(status.stored);
  EXPECT_NE(status.message.find("not stored"), std::string::npos) << status.message;
  EXPECT_NE(status.message.find("cannot create folder"), std::string::npos) << status.message;
  expect_same(result, render_reference(scene.cloud, scene.material, scene.lights, scene.settings));
  EXPECT_THROW(store_cached_reference(unwritable, scene.key(), result), std::runtime_error);

  ReferenceCacheStatus uncached;
  expect_same(cached_reference({}, scene.cloud, scene.material, scene.lights, scene.settings,
                               &uncached),
              result);
  EXPECT_FALSE(uncached.hit || uncached.stored);
}

}  // namespace
}  // namespace sss
