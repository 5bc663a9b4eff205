// A registry scene in a harness::Simulation, with drift tracking: the shared setup of the
// behaviour specs. Conditions of every spec: 60 Hz, sleeping disabled (the scenes do it),
// 10 iterations per pass unless the test says otherwise.
#pragma once

#include <BulletShockPropagation/btShockPropagationSettings.h>
#include <harness/Metrics.h>
#include <harness/Simulation.h>
#include <scenes/Registry.h>

#include <algorithm>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace spec
{
constexpr double kTimeStepSeconds = 1.0 / 60.0;
constexpr double kMaxDriftMeters = 0.01;

inline harness::SolverSpec shock(int iterations = 10, double f = btShockPropagationSettings().m_weighting)
{
	harness::SolverSpec s;
	s.kind = harness::SolverKind::ShockWorld;
	s.iterations = iterations;
	s.weighting = f;
	return s;
}

inline harness::SolverSpec shockSolverOnly(int iterations = 10, double f = btShockPropagationSettings().m_weighting)
{
	harness::SolverSpec s = shock(iterations, f);
	s.kind = harness::SolverKind::ShockSolverOnly;
	return s;
}

/// The plugin with weight feeling (D13): the world, default settings otherwise.
inline harness::SolverSpec weightFeeling(int iterations = 10, double f = btShockPropagationSettings().m_weighting)
{
	harness::SolverSpec s = shock(iterations, f);
	s.weightFeeling = true;
	return s;
}

/// The plugin in either mode (ShockWorld or ShockSolverOnly) with its default settings.
inline harness::SolverSpec plugin(harness::SolverKind kind)
{
	harness::SolverSpec s = shock();
	s.kind = kind;
	return s;
}

inline harness::SolverSpec stock(int iterations = 10)
{
	harness::SolverSpec s;
	s.kind = harness::SolverKind::StockSI;
	s.iterations = iterations;
	return s;
}

struct SceneRun
{
	std::unique_ptr<harness::Simulation> sim;
	std::unique_ptr<scenes::SceneContent> scene;
	std::vector<btRigidBody*> bodies;
	std::unique_ptr<harness::DriftTracker> drift;
	double worstDrift = 0;  // largest max-drift seen at any step

	SceneRun(const std::string& name, const harness::SolverSpec& solver,
			 const std::vector<std::pair<std::string, double>>& params = {})
		: sim(new harness::Simulation(solver, kTimeStepSeconds))
	{
		scene = scenes::createScene(sim->world(), name, params);
		bodies = scene->dynamicBodies();
		drift.reset(new harness::DriftTracker(bodies));
	}
	~SceneRun()
	{
		scene.reset();  // remove bodies before the world goes
		sim.reset();
	}

	void run(double seconds)
	{
		const int steps = int(seconds / kTimeStepSeconds + 0.5);
		for (int i = 0; i < steps; ++i)
		{
			sim->step();
			worstDrift = std::max(worstDrift, drift->maxDrift());
		}
	}
	btRigidBody* named(const std::string& key) const { return scene->named(key); }
};
}  // namespace spec
