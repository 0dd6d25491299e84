#include "whole_file.h"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <fstream>
#include <random>
#include <stdexcept>

namespace sss {
namespace {

// Creates an empty file beside `path` under a name no other writer uses, on this machine or
// another sharing the folder (64 random bits, created exclusively), with the permissions a
// new file gets here.
std::string temporary_beside(const std::string& path) {
  std::random_device entropy;
  for (int attempt = 0; attempt < 16; ++attempt) {
    char suffix[32];
    std::snprintf(suffix, sizeof suffix, ".%08x%08x.partial", entropy(), entropy());
    const std::string name = path + suffix;
    const int fd = open(name.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
    if (fd >= 0) {
      close(fd);
      return name;
    }
    if (errno != EEXIST) break;
  }
  throw std::runtime_error("cannot write " + path + ": cannot create a file in its folder");
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
