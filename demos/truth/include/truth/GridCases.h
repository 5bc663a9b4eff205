// The shape grid of the truth suite (issue 37) as truth cases, for bsp_truth --grid: one case per
// (statement, shape, ground) cell, with exactly the statements of tests/truth/ShapeGridTest.cpp (a
// column of 10 equal bodies stands: every body within 1 cm for 10 s) and tests/truth/PushedGridTest.cpp
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
/// The 75 grid cases in a fixed order: the 25 columns, then the 25 pushed stacks that slide, then
/// the 25 that stay (each shape-major: box, hull, prism, cylinder, compound; grounds 0-4 within).
/// Groups: "grid_column", "grid_slides", "grid_stays".
const std::vector<TruthCase>& gridCases();

/// A column of 10 equal bodies of `shape` (1 m wide, 0.5 m tall, 1 kg, mu 0.6) on `ground` stands:
/// every body within 1 cm for 10 s (figure: the largest drift, m). The statement of the grid_column
/// cases and of tests/truth/ShapeGridTest.cpp.
Verdict columnStandsVerdict(const harness::SolverSpec& spec, int shape, int ground);
}  // namespace truth
