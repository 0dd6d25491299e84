// A request, from another thread, that a long computation stop early: it checks the flag
// between items and throws Cancelled once it is set (its result is no longer wanted).
#pragma once

#include <atomic>
#include <stdexcept>

namespace sss {

using CancelFlag = std::atomic<bool>;

struct Cancelled : std::runtime_error {
  Cancelled() : std::runtime_error("cancelled") {}
};

// Whether `flag` (none: never) is set.
inline bool cancelled(const CancelFlag* flag) {
  return flag && flag->load(std::memory_order_relaxed);
}

}  // namespace sss
