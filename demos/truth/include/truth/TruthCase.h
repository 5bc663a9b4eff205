// The truth suite: cases whose expected outcome comes from physics (statics, the lever rule,
// Coulomb friction, g (sin a - mu cos a), a converged reference), never from the plugin's output.
// One definition serves the ctest suite (tests/truth/, which asserts the plugin's default) and the
// report program bsp_truth (every solver configuration, ms per step, the truth chart).
// Not part of the shipped plugin.
#pragma once

#include <harness/Simulation.h>

#include <functional>
#include <string>
#include <utility>
#include <vector>

namespace truth
{
/// What one case measured under one solver.
struct Verdict
{
	bool pass = false;        ///< the physics statement held
	double figure = 0;        ///< the headline measured value (in `unit`)
	double expected = 0;      ///< what physics says it should be (in `unit`)
	std::string unit;         ///< e.g. "m", "-", "s"
	std::string detail;       ///< one line: what was measured against what
	double msPerStep = 0;     ///< wall-clock ms per stepSimulation, for the report only (never asserted)
};

struct TruthCase
{
	std::string name;       ///< unique, gtest-safe: [A-Za-z0-9_]
	std::string group;      ///< e.g. "topple", "statics", "friction", "lever", "dynamics"
	std::string statement;  ///< the physics statement, one sentence, e.g. "stands iff every sub-stack's COM is over its support"
	std::function<Verdict(const harness::SolverSpec&)> run;
};

/// Every case, in a fixed order.
const std::vector<TruthCase>& truthCases();

/// A column over a ledge tipping (scene truth/ledge_column), measured after `seconds` from rest:
/// shared by the case LedgeColumnTipsAsOneBody and tests/behavior/TippingCompositeTest.cpp.
struct LedgeTip
{
	double slowest = 0, fastest = 0, mean = 0;  ///< rad/s, the cubes' turning rates towards the drop
	double expected = 0;                        ///< rad/s, alpha t of rigid-body dynamics
	double kinetic = 0, released = 0;           ///< J: kinetic energy, potential energy given up
	bool nonFinite = false;
	double msPerStep = 0;
};
LedgeTip measureLedgeTip(const harness::SolverSpec& solver, double seconds);

struct PushedStack
{
	double force = 0;         ///< N, on the bottom box every step
	double expected = 0;      ///< m/s^2, Coulomb's (F - mu W) / M when it slides, 0 at rest
	double acceleration = 0;  ///< m/s^2, fitted to the bottom box's travel from 0.25 s on
	double apart = 0;         ///< m, largest displacement of a box relative to the bottom box's motion
	double maxDrift = 0;      ///< m, largest displacement of any box
	bool nonFinite = false;
	double msPerStep = 0;
};
/// The pushed stack of the truth suite (5 boxes of 1 kg, box-ground mu 0.5, box-box mu 1) pushed at
/// the bottom box with capacityFraction times mu W: 2 s when that exceeds 1 (it slides), else 3 s.
/// sceneOverrides go to the scene pushed_stack after the suite's own values (so they win), e.g.
/// {{"shape", 4}, {"ground", 2}} (tests/truth/PushedGridTest.cpp); mu is the scene's groundMu.
PushedStack measurePushedStack(const harness::SolverSpec& solver, double capacityFraction,
							   const std::vector<std::pair<std::string, double>>& sceneOverrides = {});

/// The pushed stack's physics statement as a verdict: at rest (within 1 cm) when capacityFraction
/// <= 1, else sliding as one at Coulomb's rate (within 10%, bodies within 1 cm of each other);
/// sceneOverrides as for measurePushedStack (the truth case and the shape grid share it).
Verdict pushedStackVerdict(const harness::SolverSpec& solver, double capacityFraction,
						   const std::vector<std::pair<std::string, double>>& sceneOverrides = {});

/// Cases defined in src/StaticsCases.cpp and src/DynamicsCases.cpp.
void addStaticsCases(std::vector<TruthCase>& cases);
void addDynamicsCases(std::vector<TruthCase>& cases);
}  // namespace truth
