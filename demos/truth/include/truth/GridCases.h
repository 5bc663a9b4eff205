// The shape grid of the truth suite (issue 37) as truth cases, for bsp_truth --grid: one case per
// (statement, shape, ground) cell, with exactly the statements of tests/truth/ShapeGridTest.cpp (a
// column of 10 equal bodies stands: every body within 1 cm for 10 s; a 100 kg sphere or capsule on a
// 1 kg box stands; a compound table carrying a stack and a crib of planks stand, a stack off the table's edge falls) and tests/truth/PushedGridTest.cpp
// (5 stacked bodies pushed at the bottom with 1.4 mu W slide as one at Coulomb's (F - mu W) / M within
// 10%, no body more than 1 cm from where the bottom one carries it; pushed with 0.6 mu W no body drifts
// 1 cm). Shapes {0 box, 1 hull, 3 hexagonal prism, 4 cylinder, 5 compound} x grounds {0 box, 1 plane,
// 2 triangle mesh, 3 mesh + internal edges, 4 heightfield} (demos/scenes/src/ShapeKinds.cpp).
// A case states physics only: unlike the ctest grid, no cell is skipped where the converged reference
// (stock SI, 8 sub-steps x 100 iterations, bsp_truth --grid --configs si-sub8:100) loses it.
// Not part of the shipped plugin.
#pragma once

#include <truth/TruthCase.h>

#include <vector>

namespace truth
{
/// The 105 grid cases in a fixed order: the 25 columns, the 10 heavy round bodies on a light box
/// (capsule, sphere; grounds 0-4 within), the 5 tables carrying a stack, the 5 tables whose stack
/// falls off the edge and the 10 plank cribs (box, hull planks), then the 25 pushed stacks that slide, then the 25 that stay (each
/// shape-major: box, hull, prism, cylinder, compound; grounds 0-4 within).
/// Groups: "grid_column", "grid_round", "grid_structure", "grid_slides", "grid_stays".
const std::vector<TruthCase>& gridCases();

/// A column of 10 equal bodies of `shape` (1 m wide, 0.5 m tall, 1 kg, mu 0.6) on `ground` stands:
/// every body within 1 cm for 10 s (figure: the largest drift, m). The statement of the grid_column
/// cases and of tests/truth/ShapeGridTest.cpp.
Verdict columnStandsVerdict(const harness::SolverSpec& spec, int shape, int ground);

/// A 100 kg round body (`shape` 6 a capsule on its side, 7 a sphere; radius 0.25 m) on the middle of
/// a 1 kg box on `ground` stands: both bodies within 1 cm for 10 s (figure: the largest drift, m).
/// The statement of the grid_round cases and of tests/truth/ShapeGridTest.cpp.
Verdict roundOnBlockVerdict(const harness::SolverSpec& spec, int shape, int ground);

/// A 10 kg compound table (top and four legs) carrying 5 boxes on `ground` stands: every body within
/// 1 cm for 10 s (figure: the largest drift, m).
Verdict tableStackVerdict(const harness::SolverSpec& spec, int ground);

/// The same table with its column 1 m off the middle (beyond the top's edge at 0.8 m): the column
/// falls off, its top box's centre below the table top after 3 s (figure: its height above the
/// table top, m).
Verdict tableStackFallsVerdict(const harness::SolverSpec& spec, int ground);

/// A crib of 10 layers of two interlocking planks (`shape` 0 box, 1 hull) on `ground` stands: every
/// plank within 1 cm for 10 s (figure: the largest drift, m).
Verdict plankCribVerdict(const harness::SolverSpec& spec, int shape, int ground);
}  // namespace truth
