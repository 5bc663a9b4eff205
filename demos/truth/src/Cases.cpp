#include <truth/TruthCase.h>

namespace truth
{
const std::vector<TruthCase>& truthCases()
{
	static const std::vector<TruthCase> cases = [] {
		std::vector<TruthCase> all;
		addStaticsCases(all);
		addDynamicsCases(all);
		return all;
	}();
	return cases;
}
}  // namespace truth
