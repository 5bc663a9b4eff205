#include <truth/TruthCase.h>

namespace truth
{
void addDynamicsCases(std::vector<TruthCase>& /*cases*/)
{
}
}  // namespace truth
