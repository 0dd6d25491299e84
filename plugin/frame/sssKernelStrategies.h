// The table of kernel strategies (sssStep2.h), one row each: a new strategy is a row in
// sssKernelStrategies.cxx (and its name in core/settings/quality_settings.h), its class and its shaders.
#ifndef sssKernelStrategies_h
#define sssKernelStrategies_h

#include "sssStep2.h"

#include <memory>

namespace sss
{

// The table's row for `strategy`.
std::unique_ptr<Step2> make_step2(KernelStrategy strategy);

}

#endif
