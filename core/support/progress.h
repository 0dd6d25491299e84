// Progress of long computations: called with (done, total) from the calling thread.
#pragma once

#include <cstddef>
#include <functional>

namespace sss {
using Progress = std::function<void(std::size_t done, std::size_t total)>;
}
