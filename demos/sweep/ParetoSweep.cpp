#include "Studies.h"

#include <harness/ContactRecorder.h>
#include <harness/Trial.h>
#include <reference/ContactReference.h>

#include <chrono>
#include <map>
#include <cmath>
#include <cstdio>
#include <memory>
#include <sstream>

namespace sweep
{
namespace
{
using Clock = std::chrono::steady_clock;

double secondsSince(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

/// One configuration of a scene: a variant at an iteration count, and how its run ended.
struct Run
{
	Variant variant;
	int iterations = 0;
	std::unique_ptr<harness::Trial> trial;
	bool active = true;
	std::string status = "standing";
	double stopSeconds = -1;   // simulated time when it stopped early (-1: ran the full duration)
	double wallSeconds = 0;    // time spent stepping it (for the MLCP budget)
	int tilt = 0;              // scenes that must tip: the side of the first clear tilt (firstTilt)
	reference::Accuracy accuracy = notMeasured();     // first step: cold start, same state for every run
	reference::Accuracy endAccuracy = notMeasured();  // last step: warm started, the run's own state

	static reference::Accuracy notMeasured()
	{
		reference::Accuracy a;
		a.residual = a.distance = a.referenceResidual = a.referenceMs = NAN;
		return a;
	}
};

/// References already solved in this scene, by problem: configurations that start from the same
/// state (every one, at the first step) share one solve per time step.
class ReferenceCache
{
public:
	reference::Accuracy measure(const harness::ContactProblem& problem)
	{
		const std::vector<double> key = fingerprint(problem);
		for (const Entry& e : m_entries)
			if (e.key == key) return reference::measureAgainst(problem, e.solution);
		const Clock::time_point start = Clock::now();
		m_entries.push_back({key, reference::solve(problem)});
		reference::Accuracy a = reference::measureAgainst(problem, m_entries.back().solution);
		a.referenceMs = secondsSince(start) * 1e3;
		return a;
	}

private:
	struct Entry
	{
		std::vector<double> key;
		reference::Solution solution;
	};
	static std::vector<double> fingerprint(const harness::ContactProblem& p)
	{
		std::vector<double> key{p.timeStep, double(p.rows.size()), double(p.bodies.size())};
		for (const harness::ContactProblem::Row& r : p.rows)
		{
			key.push_back(r.b);
			key.push_back(r.mu);
			key.push_back(r.bodyA);
			key.push_back(r.bodyB);
			key.insert(key.end(), r.jacobianA, r.jacobianA + 6);
			key.insert(key.end(), r.jacobianB, r.jacobianB + 6);
		}
		for (const harness::ContactProblem::Body& b : p.bodies)
		{
			key.push_back(b.invMass);
			key.insert(key.end(), b.invInertia, b.invInertia + 9);
		}
		return key;
	}
	std::vector<Entry> m_entries;
};

void stop(Run& run, const char* status)
{
	run.active = false;
	run.status = status;
	run.stopSeconds = run.trial->simulation().time();
}

double fact(const harness::Trial& trial, const char* key, double otherwise)
{
	const std::map<std::string, double>& facts = trial.scene().facts;
	const auto it = facts.find(key);
	return it == facts.end() ? otherwise : it->second;
}

/// For a scene that must tip one way (fact "heavySide": -1 = the -x end goes down, on the body named
/// "plank"): the side of the plank's first clear tilt (3 degrees), as tests/behavior/HardCaseTest.cpp
/// judges it (afterwards the stack may slide off and the light end tip it back: physics too).
/// 0 while level; +1 towards the heavy side; -1 the wrong way.
int firstTilt(harness::Trial& trial)
{
	const double side = fact(trial, "heavySide", 0);
	const btRigidBody* plank = trial.scene().named("plank");
	if (side == 0 || !plank) return 0;
	// The plank's +x axis in world coordinates: its y component is sin(tilt), > 0 when the -x end is down.
	const double rise = plank->getWorldTransform().getBasis().getColumn(0).y();
	if (std::fabs(rise) < std::sin(3 * M_PI / 180)) return 0;
	return (-side * rise > 0) ? 1 : -1;
}

void runScene(const SceneCase& scene, const ParetoOptions& o, ResultTable& out)
{
	const Clock::time_point sceneStart = Clock::now();
	std::vector<Run> runs;
	for (const Variant& v : o.variants)
		for (int n : o.iterations)
		{
			if (n > v.maxIterations) continue;
			Run run;
			run.variant = v;
			run.iterations = n;
			harness::SolverSpec spec = v.spec;
			spec.iterations = n;
			run.trial.reset(new harness::Trial(spec, scene.scene, scene.params, o.timeStepSeconds));
			runs.push_back(std::move(run));
		}
	const int steps = int(o.durationSeconds / o.timeStepSeconds + 0.5);
	ReferenceCache cache;
	// Dantzig's pivoting is O(rows^3): on bigger scenes one step takes seconds to minutes.
	const int bodies = runs.empty() ? 0 : int(runs.front().trial->bodies().size());
	bool mlcpOverBudget = bodies > o.mlcpMaxBodies;
	// A warm-started state is a harder problem than the first step: 40-70 s per reference at 465 boxes.
	const bool measureEnd = o.reference && bodies <= o.endReferenceMaxBodies;
	// A scene meant to move (the seesaw tips) is not stopped for drift: drift is its motion, not an error.
	const bool expectStanding = runs.empty() || fact(*runs.front().trial, "expectStanding", 1) != 0;
	for (int step = 0; step < steps; ++step)
	{
		for (Run& run : runs)
		{
			if (run.active && run.variant.isMLCP() && mlcpOverBudget) stop(run, "dnf");
			if (!run.active) continue;
			harness::Simulation& sim = run.trial->simulation();
			const bool first = o.reference && step == 0;
			const bool last = measureEnd && step == steps - 1;
			if (first || last) sim.recorder().arm();
			const Clock::time_point start = Clock::now();
			run.trial->step();
			const double seconds = secondsSince(start);
			run.wallSeconds += seconds;
			if (first) run.accuracy = cache.measure(sim.recorder().take());
			else if (last) run.endAccuracy = reference::measure(sim.recorder().take());

			if (!expectStanding && run.tilt == 0) run.tilt = firstTilt(*run.trial);
			const harness::TrialSeries& s = run.trial->series();
			if (harness::anyNonFinite(run.trial->bodies()))
				stop(run, "nonfinite");
			else if (expectStanding && s.drift.back() > o.collapseDriftMeters)
				stop(run, "collapsed");
			else if (run.variant.isMLCP() && (run.wallSeconds > o.mlcpBudgetSeconds || seconds > o.mlcpStepSeconds))
			{
				stop(run, "dnf");
				mlcpOverBudget = true;
			}
		}
	}

	std::fprintf(stderr, "pareto: %-16s stepped, %6.1f s\n", scene.label.c_str(), secondsSince(sceneStart));
	for (Run& run : runs)
	{
		const harness::TrialSummary s = run.trial->summary();
		if (run.active && !expectStanding) run.status = run.tilt > 0 ? "tipped" : run.tilt < 0 ? "tipped the wrong way" : "did not tip";
		else if (run.active && !s.standing) run.status = "moved";
		const harness::SolverSpec& spec = run.trial->simulation().spec();
		const std::string family = run.variant.label.substr(0, run.variant.label.find(' '));
		out.newRow();
		out.add("scene", scene.label);
		out.add("bodies", double(run.trial->bodies().size()));
		out.add("solver", run.variant.label);
		out.add("family", family);
		out.add("iterations", run.iterations);
		out.add("f", spec.isPlugin() ? double(spec.settings.m_weighting) : NAN);
		out.add("substeps", spec.substeps);
		out.add("expect_standing", expectStanding ? 1 : 0);
		out.add("status", run.status);
		out.add("collapse_s", s.collapseTime);
		out.add("stop_s", run.active ? o.durationSeconds : run.stopSeconds);
		out.add("steps", run.trial->steps());
		const double ran = run.trial->steps() > 0 ? 1.0 : NAN;  // a run stopped before its first step measured nothing
		out.add("max_drift_m", ran * s.maxDrift);
		out.add("max_penetration_m", ran * s.maxPenetration);
		out.add("ground_over_weight", ran * s.groundOverWeightLastSecond);
		out.add("ground_error", ran * std::fabs(s.groundOverWeightLastSecond - 1));
		out.add("ms_per_step", run.trial->steps() > 0 ? s.msPerStep : NAN);
		out.add("residual", run.accuracy.residual);
		out.add("distance", run.accuracy.distance);
		out.add("reference_residual", run.accuracy.referenceResidual);
		out.add("reference_rows", run.accuracy.rows);
		out.add("reference_ms", run.accuracy.referenceMs);
		out.add("residual_end", run.endAccuracy.residual);
		out.add("distance_end", run.endAccuracy.distance);
		out.add("reference_residual_end", run.endAccuracy.referenceResidual);
		out.add("reference_ms_end", run.endAccuracy.referenceMs);
	}
	std::fprintf(stderr, "pareto: %-16s %3zu runs, %6.1f s\n", scene.label.c_str(), runs.size(), secondsSince(sceneStart));
}
}  // namespace

void runPareto(const ParetoOptions& o, ResultTable& out, std::vector<std::pair<std::string, std::string>>& notes)
{
	const Clock::time_point start = Clock::now();
	for (const SceneCase& scene : o.scenes) runScene(scene, o, out);
	std::ostringstream rules;
	rules << "every configuration of a scene stepped in lockstep; " << o.durationSeconds << " s at " << 1 / o.timeStepSeconds
		  << " Hz; a run stops once any body is more than " << o.collapseDriftMeters
		  << " m from its start (status collapsed, stop_s) or turns NaN; a scene meant to move (expect_standing 0: the seesaw) is not stopped "
			 "for drift and its status says which way it first tipped by 3 degrees (tipped, tipped the wrong way, did not tip); MLCP stops as dnf once its stepping passes "
		  << o.mlcpBudgetSeconds << " s or one step passes " << o.mlcpStepSeconds
		  << " s (then every MLCP run of the scene: Dantzig does not use the iteration count), and is not started on scenes of more than "
		  << o.mlcpMaxBodies << " bodies; ms_per_step over the steps run; "
			 "residual and distance: the first step against the Eigen reference (cold start, same state for every run); "
			 "residual_end and distance_end: the last step of a run that lasted the full duration, against a reference solved for that run's own state (warm started), on scenes of at most "
		  << o.endReferenceMaxBodies << " bodies";
	notes.push_back({"rules", rules.str()});
	notes.push_back({"pareto_seconds", std::to_string(secondsSince(start))});
}
}  // namespace sweep
