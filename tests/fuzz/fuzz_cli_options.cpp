// libFuzzer target: sss_render's option parsing (programs/support/cli_options.h) on any
// argument list, the bytes split at NUL into at most 64 arguments. A bad list must end in
// std::invalid_argument; any other exception, a crash or a sanitizer report is a defect.
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "cli_options.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  std::vector<std::string> args{"sss_render"};
  std::string current;
  for (std::size_t i = 0; i < size && args.size() < 64; ++i) {
    if (data[i] == 0) {
      args.push_back(current);
      current.clear();
    } else {
      current.push_back(static_cast<char>(data[i]));
    }
  }
  if (!current.empty()) args.push_back(current);
  std::vector<char*> argv;
  for (std::string& a : args) argv.push_back(a.data());
  try {
    const sss::cli::Options o = sss::cli::parse(static_cast<int>(argv.size()), argv.data());
    const std::size_t lights = o.light_dirs.size() + o.point_lights.size();
    if (o.width < 1 || o.height < 1 || lights < 1 || lights > 4)
      __builtin_trap();  // parse promises these
  } catch (const std::invalid_argument&) {
  }
  return 0;
}
