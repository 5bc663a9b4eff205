// bsp_sweep's three studies. Each writes raw results (CSV + JSON) for demos/charts/plot_charts.py.
#pragma once

#include "ResultTable.h"
#include "Variants.h"

#include <string>
#include <vector>

namespace sweep
{
/// Speed against accuracy: every variant x iteration count on every scene, 10 s at 60 Hz, the
/// configurations of one scene stepped in lockstep (one frame of each, then the next), so that
/// load from other processes hits all of them alike and ms/step ratios stay fair.
/// Rules, also written into the JSON notes:
///  - a configuration whose largest body displacement passes collapseDriftMeters (or that turns
///    NaN) has clearly collapsed: it stops there; its ms/step is over the steps it ran, its max
///    drift is at least collapseDriftMeters, its stop time is recorded;
///  - MLCP (Dantzig, O(n^3)) stops as "did not finish" (dnf) once its solve time passes
///    mlcpBudgetSeconds, or at once if one step took longer than mlcpStepSeconds; the Dantzig
///    solve does not use the iteration count, so that verdict stops every MLCP run of the scene;
///    on scenes of more than mlcpMaxBodies bodies it is not started (one step of the 210-box pyramid
///    takes seconds, of the 465-box one about a minute);
///  - the first step is captured (harness::ContactRecorder) and measured against the Eigen
///    reference: every solver starts from the same state there, so one reference per scene and
///    time step serves every configuration (cold start for all: no warm-start history);
///  - the last step of every run that lasted the full duration is captured too and measured
///    against a reference solved for that run's own state: the warm-started accuracy a running
///    simulation has (from a cold start PGS needs about 1,000 sweeps to converge on a 5-box tower,
///    warm started 100). Only on scenes of at most endReferenceMaxBodies bodies: a settled state
///    is a harder problem than the first step (one reference of the 465-box pyramid takes 40-70 s
///    there against 5 s at the first step, and there is one per run).
struct ParetoOptions
{
	std::vector<SceneCase> scenes = sweepScenes();
	std::vector<Variant> variants = sweepVariants();
	std::vector<int> iterations = sweepIterations();
	double durationSeconds = 10;
	double timeStepSeconds = 1.0 / 60.0;
	double collapseDriftMeters = 0.1;  // 10x the 1 cm standard: past it a run has failed
	double mlcpBudgetSeconds = 20;
	double mlcpStepSeconds = 0.5;
	int mlcpMaxBodies = 100;
	int endReferenceMaxBodies = 100;
	bool reference = true;
};
void runPareto(const ParetoOptions& options, ResultTable& out, std::vector<std::pair<std::string, std::string>>& notes);

/// Iterations needed to keep a tower of N boxes within 1 cm for 10 s, per solver: the first count
/// of a ladder (1, 2, 3, 5, 7, 10, 15, 20, 30, 50, ..., maxIterations) whose run stands. A run
/// stops as soon as a body passes 1 cm (it failed), so only standing runs take the full 10 s.
struct TowerOptions
{
	std::vector<int> heights = {2, 4, 6, 8, 10, 12, 16, 20, 24, 30, 40};
	std::vector<std::string> variants = {"si", "nncg", "sp f=0.5"};
	int maxIterations = 1000;
	double durationSeconds = 10;
};
void runTowers(const TowerOptions& options, ResultTable& out, std::vector<std::pair<std::string, std::string>>& notes);

/// Cost against body count: pyramids of base 10 .. 140 (55 .. 9,870 boxes), stock SI and the
/// plugin at 10 iterations, stepped in lockstep: warmupSteps untimed frames, then measuredSteps
/// timed ones. The plugin's step is split by phase (its statistics, plus Bullet's collision
/// detection timed around performDiscreteCollisionDetection by the harness).
struct ScalingOptions
{
	std::vector<int> bases = {10, 20, 30, 40, 60, 80, 100, 120, 140};
	std::vector<std::string> variants = {"si", "sp f=0.5"};
	int iterations = 10;
	int warmupSteps = 5;
	int measuredSteps = 10;
};
void runScaling(const ScalingOptions& options, ResultTable& out, std::vector<std::pair<std::string, std::string>>& notes);
}  // namespace sweep
