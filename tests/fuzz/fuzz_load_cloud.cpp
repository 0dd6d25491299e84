// libFuzzer target: the PCL glue's loader on any bytes, as a PCD, PLY, gzip-compressed PLY,
// OBJ or ASCII point list. The first byte picks the form (its value mod 5) and whether a mesh
// is sampled (the parity of its value / 5); the rest is the file (for .ply.gz, deflated here so
// that the fuzzer mutates the PLY inside). A bad file must end in sss::InputError; any other
// exception, a crash or a sanitizer report is a defect.
#include <pcl/point_types.h>
#include <unistd.h>
#include <zlib.h>

#include <cstdint>
#include <cstdio>
#include <string>

#include "sssPclLoading.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size < 1) return 0;
  const int form = data[0] % 5;
  const char* suffixes[] = {".pcd", ".ply", ".ply.gz", ".obj", ".xyz"};
  const char* suffix = suffixes[form];
  const std::string path = "/tmp/sss-fuzz-" + std::to_string(getpid()) + suffix;
  if (form == 2) {
    gzFile out = gzopen(path.c_str(), "wb1");
    if (size > 1) gzwrite(out, data + 1, static_cast<unsigned>(size - 1));
    gzclose(out);
  } else {
    std::FILE* out = std::fopen(path.c_str(), "wb");
    std::fwrite(data + 1, 1, size - 1, out);
    std::fclose(out);
  }
  sss::LoadOptions options;
  options.memory_cap = std::size_t{256} << 20;  // under libFuzzer's default 2 GiB RSS limit
  options.mesh_samples = (data[0] / 5) % 2 ? 64 : 0;
  try {
    const auto loaded = sss::loadPointCloud<pcl::PointXYZRGBNormal>(path, options);
    if (loaded.cloud->empty()) __builtin_trap();  // the loader promises points
  } catch (const sss::InputError&) {
  }
  std::remove(path.c_str());
  return 0;
}
