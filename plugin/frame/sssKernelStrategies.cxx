#include "sssKernelStrategies.h"

#include "sssPaperVirtualPoints.h"
#include "sssSurfelPipeline.h"

namespace sss
{

namespace
{
template <typename T>
std::unique_ptr<Step2> Make()
{
  return std::make_unique<T>();
}

// The kernel strategies, one row each.
struct Row
{
  KernelStrategy strategy;
  std::unique_ptr<Step2> (*make)();
};
const Row kStrategies[] = {
  { KernelStrategy::Paper, &Make<PaperVirtualPoints> },
  { KernelStrategy::NearFar, &Make<SurfelPipeline> },
};
}

std::unique_ptr<Step2> make_step2(KernelStrategy strategy)
{
  for (const Row& row : kStrategies)
  {
    if (row.strategy == strategy)
    {
      return row.make();
    }
  }
  return nullptr;
}

}
