#include "sssKernelStrategies.h"

#include "sssPaperStrategy.h"
#include "sssNearFarStrategy.h"

namespace sss
{

namespace
{
template <typename T>
std::unique_ptr<Strategy> Make()
{
  return std::make_unique<T>();
}

// The kernel strategies, one row each.
struct Row
{
  KernelStrategy strategy;
  std::unique_ptr<Strategy> (*make)();
};
const Row kStrategies[] = {
  { KernelStrategy::Paper, &Make<PaperStrategy> },
  { KernelStrategy::NearFar, &Make<NearFarStrategy> },
};
}

std::unique_ptr<Strategy> make_strategy(KernelStrategy strategy)
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
