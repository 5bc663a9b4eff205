#include <truth/TruthCase.h>

namespace truth
{
void addStaticsCases(std::vector<TruthCase>& /*cases*/)
{
}
}  // namespace truth
