// A disk cache of the CPU reference (render_reference): per-surfel B and its stats in one file
// per input, named by a 64-bit hash of everything the result depends on.
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "light_map.h"
#include "material.h"
#include "reference_renderer.h"
#include "surfel_cloud.h"

namespace sss {

// Raise when the file layout or what render_reference computes changes: old files then miss.
constexpr std::uint32_t kReferenceCacheVersion = 13;

// What identifies one reference result.
struct ReferenceKey {
  // FNV-1a over the cloud (positions, normals, albedo, radius, radii), the material (sigma_a,
  // sigma_s', eta, mm per unit), the lights in order (direction, irradiance), every field of
  // ReferenceSettings that changes the result (light map, samples, tree and
  // the receivers asked for), and kReferenceCacheVersion.
  std::uint64_t hash = 0;
  std::size_t surfels = 0;  // a stored file must hold exactly this many values of B
  std::string label;        // readable prefix of the file name: the material's name

  static ReferenceKey of(const SurfelCloud& cloud, const Material& material,
                         const std::vector<Light>& lights,
                         const ReferenceSettings& settings);

  // "<label>-<hash as 16 hex digits>.sssref"; the label keeps only [A-Za-z0-9_-].
  std::string file_name() const;
};

// The stored result for `key`, or nothing when the file is absent, truncated, corrupt (its
// checksum), of another version, or for another key or surfel count. `problem`, when given,
// says why a file that exists was not used (empty otherwise).
std::optional<SurfelRadiance> load_cached_reference(const std::filesystem::path& dir,
                                                    const ReferenceKey& key,
                                                    std::string* problem = nullptr);

// Writes `radiance` for `key` into `dir` (created if missing) through a temporary file renamed
// into place, so the file is whole or absent. Throws std::invalid_argument when the surfel
// count differs from the key's and std::runtime_error when the file cannot be written.
void store_cached_reference(const std::filesystem::path& dir, const ReferenceKey& key,
                            const SurfelRadiance& radiance);

struct ReferenceCacheStatus {
  bool hit = false;     // the result came from the file
  bool stored = false;  // the result was computed and written
  std::filesystem::path file;
  std::string message;  // one line: what happened, naming a file that was unusable or unwritable
};

// render_reference through the cache in `dir`: a hit returns the stored result; a miss computes
// (settings.progress reports as usual) and stores it, replacing an unusable file. A folder that
// cannot be written costs only the storing (status->message says why). An empty `dir` computes
// without the cache. Throws what render_reference throws.
SurfelRadiance cached_reference(const std::filesystem::path& dir, const SurfelCloud& cloud,
                                const Material& material,
                                const std::vector<Light>& lights,
                                const ReferenceSettings& settings = {},
                                ReferenceCacheStatus* status = nullptr);

}  // namespace sss
