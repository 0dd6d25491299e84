#include "reference_cache.h"

#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <limits>
#include <stdexcept>
#include <system_error>
#include <utility>

#include "whole_file.h"

namespace sss {
namespace {

// 64-bit FNV-1a (Fowler, Noll, Vo): per byte, xor then multiply by the FNV prime.
class Fnv1a64 {
 public:
  void add_bytes(const char* bytes, std::size_t count) {
    for (std::size_t i = 0; i < count; ++i) {
      state_ ^= static_cast<unsigned char>(bytes[i]);
      state_ *= 0x100000001b3ULL;
    }
  }
  // Little-endian bytes, so the hash is the same on any machine.
  void add_word(std::uint64_t word) {
    for (int b = 0; b < 8; ++b) {
      state_ ^= (word >> (8 * b)) & 0xffU;
      state_ *= 0x100000001b3ULL;
    }
  }
  void add(double v) { add_word(canonical_bits(v)); }
  void add(const Eigen::Vector3d& v) {
    for (int c = 0; c < 3; ++c) add(v[c]);
  }
  void add(const Rgb& v) {
    for (double c : v) add(c);
  }
  template <typename T>
  void add_all(const std::vector<T>& values) {
    add_word(values.size());  // so that where one array ends is part of the hash
    for (const T& v : values) add(v);
  }
  std::uint64_t value() const { return state_; }

  // -0.0 hashes as 0.0 and every NaN as one NaN: equal values, equal hashes.
  static std::uint64_t canonical_bits(double v) {
    if (v == 0.0) v = 0.0;
    if (std::isnan(v)) v = std::numeric_limits<double>::quiet_NaN();
    std::uint64_t bits;
    std::memcpy(&bits, &v, sizeof bits);
    return bits;
  }

 private:
  std::uint64_t state_ = 0xcbf29ce484222325ULL;  // FNV-1a 64-bit offset basis
};

// File layout, all 8-byte little-endian words: magic, version, key hash, surfel count, the
// stats, B (surfel count x RGB), FNV-1a of every byte before it.
constexpr char kMagic[9] = "SSS-REF\n";
constexpr std::size_t kHeaderWords = 4;
constexpr std::size_t kStatsWords = 12;

std::size_t file_bytes(std::size_t surfels) {
  return 8 * (kHeaderWords + kStatsWords + 3 * surfels + 1);
}

std::uint64_t magic_word() {
  std::uint64_t w = 0;
  for (int b = 0; b < 8; ++b)
    w |= static_cast<std::uint64_t>(static_cast<unsigned char>(kMagic[b])) << (8 * b);
  return w;
}

std::uint64_t bits_of(double v) {
  std::uint64_t bits;
  std::memcpy(&bits, &v, sizeof bits);
  return bits;
}

double double_of(std::uint64_t bits) {
  double v;
  std::memcpy(&v, &bits, sizeof v);
  return v;
}

std::uint64_t signed_word(long long v) { return static_cast<std::uint64_t>(v); }
int int_of(std::uint64_t w) { return static_cast<int>(static_cast<long long>(w)); }

class WordWriter {
 public:
  explicit WordWriter(std::size_t words) { bytes_.reserve(8 * words); }
  void word(std::uint64_t w) {
    for (int b = 0; b < 8; ++b) bytes_.push_back(static_cast<char>((w >> (8 * b)) & 0xffU));
  }
  void real(double v) { word(bits_of(v)); }
  const std::string& bytes() const { return bytes_; }

 private:
  std::string bytes_;
};

class WordReader {
 public:
  explicit WordReader(const std::string& bytes) : bytes_(bytes) {}
  std::uint64_t word() {
    std::uint64_t w = 0;
    for (int b = 0; b < 8; ++b)
      w |= static_cast<std::uint64_t>(static_cast<unsigned char>(bytes_[at_ + b])) << (8 * b);
    at_ += 8;
    return w;
  }
  double real() { return double_of(word()); }
  std::size_t offset() const { return at_; }

 private:
  const std::string& bytes_;
  std::size_t at_ = 0;
};

std::string hex16(std::uint64_t v) {
  char text[17];
  std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(v));
  return text;
}

std::string read_bytes(const std::filesystem::path& file, std::size_t count) {
  std::ifstream in(file, std::ios::binary);
  std::string bytes(count, '\0');
  if (!in.read(bytes.data(), static_cast<std::streamsize>(count))) return {};
  return bytes;
}

// Why the header of a file does not belong to `key` (empty when it does).
std::string header_mismatch(WordReader& in, const ReferenceKey& key) {
  if (in.word() != magic_word()) return "not a reference cache file";
  const std::uint64_t version = in.word();
  if (version != kReferenceCacheVersion)
    return "format version " + std::to_string(version) + ", expected " +
           std::to_string(kReferenceCacheVersion);
  const std::uint64_t hash = in.word();
  if (hash != key.hash) return "key " + hex16(hash) + ", expected " + hex16(key.hash);
  const std::uint64_t surfels = in.word();
  if (surfels != key.surfels)
    return std::to_string(surfels) + " surfels, expected " + std::to_string(key.surfels);
  return {};
}

}  // namespace

ReferenceKey ReferenceKey::of(const SurfelCloud& cloud, const Material& material,
                              const std::vector<Light>& lights,
                              const ReferenceSettings& settings) {
  Fnv1a64 h;
  h.add_word(kReferenceCacheVersion);
  h.add_all(cloud.positions);
  h.add_all(cloud.normals);
  h.add_all(cloud.albedo);
  h.add(cloud.radius);
  h.add_all(cloud.radii);
  h.add(material.sigma_a);
  h.add(material.sigma_s_prime);
  h.add(material.eta);
  h.add(material.mm_per_unit);
  h.add_word(lights.size());
  for (const Light& light : lights) {
    h.add(light.direction);
    h.add(light.irradiance);
    if (light.positional) {  // directional lights keep the keys they had
      h.add(light.position);
      h.add(light.attenuation);
      h.add(light.cone_angle);
      h.add(light.exponent);
    }
  }
  h.add(settings.light_map.texel_per_radius);
  h.add_word(signed_word(settings.light_map.max_map_size));
  h.add_word(signed_word(settings.irradiance_samples));
  h.add_word(signed_word(settings.irradiance_refined));
  h.add(settings.tree.theta);
  h.add_word(signed_word(settings.tree.leaf_size));
  h.add(settings.tree.kernel_tolerance);
  h.add_word(settings.receivers.size());
  for (std::size_t i : settings.receivers) h.add_word(i);

  ReferenceKey key;
  key.hash = h.value();
  key.surfels = cloud.size();
  key.label = material.name;
  return key;
}

std::string ReferenceKey::file_name() const {
  std::string prefix;
  for (char c : label) {
    if (prefix.size() == 40) break;
    const bool plain = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') ||
                       (c >= '0' && c <= '9') || c == '_' || c == '-';
    prefix += plain ? c : '_';
  }
  if (prefix.empty()) prefix = "reference";
  return prefix + "-" + hex16(hash) + ".sssref";
}

std::optional<SurfelRadiance> load_cached_reference(const std::filesystem::path& dir,
                                                    const ReferenceKey& key,
                                                    std::string* problem) {
  if (problem) problem->clear();
  const std::filesystem::path file = dir / key.file_name();
  const auto unusable = [&](const std::string& why) -> std::optional<SurfelRadiance> {
    if (problem) *problem = file.string() + ": " + why;
    return std::nullopt;
  };
  std::error_code error;
  if (!std::filesystem::is_regular_file(file, error)) return std::nullopt;
  const std::uintmax_t size = std::filesystem::file_size(file, error);
  if (error) return unusable("cannot read its size (" + error.message() + ")");
  const std::size_t expected = file_bytes(key.surfels);
  if (size != expected) {
    // Say what is wrong when the header can be read; otherwise it is the size.
    if (size >= 8 * kHeaderWords) {
      const std::string header = read_bytes(file, 8 * kHeaderWords);
      if (header.empty()) return unusable("cannot be read");
      WordReader in(header);
      const std::string mismatch = header_mismatch(in, key);
      if (!mismatch.empty()) return unusable(mismatch);
    }
    return unusable("truncated or padded: " + std::to_string(size) + " bytes, expected " +
                    std::to_string(expected));
  }
  const std::string bytes = read_bytes(file, expected);
  if (bytes.empty()) return unusable("cannot be read");
  WordReader in(bytes);
  const std::string mismatch = header_mismatch(in, key);
  if (!mismatch.empty()) return unusable(mismatch);

  SurfelRadiance result;
  RadianceStats& s = result.stats;
  s.surfels = in.word();
  s.lit_cells = in.word();
  s.texel_mm = in.real();
  s.map_width = int_of(in.word());
  s.map_height = int_of(in.word());
  s.near_entries = in.word();
  s.near_reach_mm = in.real();
  s.far_field = in.word() != 0;
  s.seconds_light = in.real();
  s.seconds_tree = in.real();
  s.seconds_geometry = in.real();
  s.seconds_surfels = in.real();
  result.B.resize(key.surfels);
  for (Rgb& b : result.B)
    for (double& c : b) c = in.real();
  Fnv1a64 checksum;
  checksum.add_bytes(bytes.data(), in.offset());
  if (in.word() != checksum.value()) return unusable("checksum mismatch (corrupt)");
  return result;
}

void store_cached_reference(const std::filesystem::path& dir, const ReferenceKey& key,
                            const SurfelRadiance& radiance) {
  if (radiance.B.size() != key.surfels)
    throw std::invalid_argument("[sss::store_cached_reference] " +
                                std::to_string(radiance.B.size()) + " values of B for a key of " +
                                std::to_string(key.surfels) + " surfels");
  WordWriter out(file_bytes(key.surfels) / 8);
  out.word(magic_word());
  out.word(kReferenceCacheVersion);
  out.word(key.hash);
  out.word(key.surfels);
  const RadianceStats& s = radiance.stats;
  out.word(s.surfels);
  out.word(s.lit_cells);
  out.real(s.texel_mm);
  out.word(signed_word(s.map_width));
  out.word(signed_word(s.map_height));
  out.word(s.near_entries);
  out.real(s.near_reach_mm);
  out.word(s.far_field ? 1 : 0);
  out.real(s.seconds_light);
  out.real(s.seconds_tree);
  out.real(s.seconds_geometry);
  out.real(s.seconds_surfels);
  for (const Rgb& b : radiance.B)
    for (double c : b) out.real(c);
  Fnv1a64 checksum;
  checksum.add_bytes(out.bytes().data(), out.bytes().size());
  out.word(checksum.value());

  const std::string where = "[sss::store_cached_reference] ";
  std::error_code error;
  std::filesystem::create_directories(dir, error);
  if (error)
    throw std::runtime_error(where + "cannot create folder " + dir.string() + ": " +
                             error.message());
  // Written whole: runs sharing the folder never read another's half-written entry.
  const std::filesystem::path file = dir / key.file_name();
  try {
    write_whole_file(file.string(), [&](std::ostream& stream) {
      stream.write(out.bytes().data(), static_cast<std::streamsize>(out.bytes().size()));
    });
  } catch (const std::runtime_error& e) {
    throw std::runtime_error(where + e.what());
  }
}

SurfelRadiance cached_reference(const std::filesystem::path& dir, const SurfelCloud& cloud,
                                const Material& material,
                                const std::vector<Light>& lights,
                                const ReferenceSettings& settings,
                                ReferenceCacheStatus* status) {
  ReferenceCacheStatus ignored;
  ReferenceCacheStatus& report = status ? *status : ignored;
  report = {};
  if (dir.empty()) {
    report.message = "no cache folder: computed";
    return render_reference(cloud, material, lights, settings);
  }
  const ReferenceKey key = ReferenceKey::of(cloud, material, lights, settings);
  report.file = dir / key.file_name();
  std::string problem;
  if (std::optional<SurfelRadiance> stored = load_cached_reference(dir, key, &problem)) {
    report.hit = true;
    report.message = "read " + report.file.string();
    return std::move(*stored);
  }
  SurfelRadiance result = render_reference(cloud, material, lights, settings);
  const std::string before = problem.empty() ? "" : problem + "; ";
  try {
    store_cached_reference(dir, key, result);
    report.stored = true;
    report.message = before + "computed and stored " + report.file.string();
  } catch (const std::exception& e) {
    report.message = before + "computed, not stored: " + e.what();
  }
  return result;
}

}  // namespace sss
