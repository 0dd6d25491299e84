#include "whole_file.h"

#include <unistd.h>

#include <atomic>
#include <cstdio>
#include <fstream>
#include <stdexcept>

namespace sss {
namespace {

// A name beside `path` that no other process or write of this one uses at the same time.
std::string temporary_beside(const std::string& path) {
  static std::atomic<unsigned> counter{0};
  return path + "." + std::to_string(getpid()) + "-" + std::to_string(counter++) + ".partial";
}

void fail(const std::string& path, const std::string& temporary, const std::string& why) {
  std::remove(temporary.c_str());
  throw std::runtime_error("cannot write " + path + ": " + why);
}

void publish(const std::string& path, const std::string& temporary) {
  if (std::rename(temporary.c_str(), path.c_str()) != 0)
    fail(path, temporary, "cannot rename the finished temporary file onto it");
}

}  // namespace

void write_whole_file(const std::string& path, const std::function<void(std::ostream&)>& fill) {
  const std::string temporary = temporary_beside(path);
  {
    std::ofstream out(temporary, std::ios::binary);
    if (!out) fail(path, temporary, "cannot create a file in its folder");
    try {
      fill(out);
    } catch (const std::exception& e) {
      out.close();
      fail(path, temporary, e.what());
    }
    if (!out.flush()) fail(path, temporary, "the write failed (disk full?)");
  }
  publish(path, temporary);
}

void write_whole_file_named(const std::string& path,
                            const std::function<bool(const std::string& temporary)>& write) {
  const std::string temporary = temporary_beside(path);
  bool written = false;
  try {
    written = write(temporary);
  } catch (const std::exception& e) {
    fail(path, temporary, e.what());
  }
  if (!written || !std::ifstream(temporary).good()) fail(path, temporary, "the write failed");
  publish(path, temporary);
}

}  // namespace sss
