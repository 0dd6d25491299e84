// The table of kernel strategies (sssStrategy.h), one row each: a new strategy is a row in
// sssKernelStrategies.cxx (and its name in core/settings/quality_settings.h), its class and its
// shaders.
#ifndef sssKernelStrategies_h
#define sssKernelStrategies_h

#include "sssStrategy.h"

#include <memory>

namespace sss
{

// The table's row for `strategy`.
std::unique_ptr<Strategy> make_strategy(KernelStrategy strategy);

}

#endif
