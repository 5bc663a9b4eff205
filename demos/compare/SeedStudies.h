// bsp_demo --seed: the source presentation's studies, regenerated as tables (the pictures come with
// the viewer). Every study runs its solvers side by side in lockstep.
#pragma once

#include <iosfwd>
#include <string>

namespace compare
{
/// Prints the three studies to `out`; writes every measured row to `csvPath` if it is not empty.
///  1. convergence: the 200-piece wall and the 320-brick round tower after 4 s, stock SI at 10 and
///     100 iterations against shock propagation at 10;
///  2. frame 6 of a 20-box tower without (stock SI) and with shock propagation;
///  3. sequences: the seed scenes at 2, 4, 6 and 8 s.
void runSeedStudies(std::ostream& out, const std::string& csvPath, bool progress);
}  // namespace compare
