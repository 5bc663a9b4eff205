// The solvers of the behaviour specs; each spec runs a registry scene in a harness::Trial.
// Conditions of every spec: 60 Hz, sleeping disabled (the scenes do it), 10 iterations per pass
// unless the test says otherwise; "standing" is harness::kStandingDriftMeters.
#pragma once

#include <BulletShockPropagation/btShockPropagationConstraintSolver.h>
#include <BulletShockPropagation/btShockPropagationSettings.h>
#include <harness/Metrics.h>
#include <harness/Trial.h>

namespace spec
{
constexpr double kTimeStepSeconds = 1.0 / 60.0;

inline harness::SolverSpec shock(int iterations = 10, double f = btShockPropagationSettings().m_weighting)
{
	harness::SolverSpec s;
	s.kind = harness::SolverKind::ShockWorld;
	s.iterations = iterations;
	s.settings.m_weighting = btScalar(f);
	return s;
}

inline harness::SolverSpec shockSolverOnly(int iterations = 10, double f = btShockPropagationSettings().m_weighting)
{
	harness::SolverSpec s = shock(iterations, f);
	s.kind = harness::SolverKind::ShockSolverOnly;
	return s;
}

/// Erleben's classic method: the plugin without weight feeling (lower bodies never feel the upper
/// ones), the world, default settings otherwise.
inline harness::SolverSpec classic(int iterations = 10, double f = btShockPropagationSettings().m_weighting)
{
	harness::SolverSpec s = shock(iterations, f);
	s.settings.m_weightFeeling = false;
	return s;
}

/// The plugin's defaults (weight feeling on since D16), world mode.
inline harness::SolverSpec weightFeeling(int iterations = 10, double f = btShockPropagationSettings().m_weighting)
{
	harness::SolverSpec s = shock(iterations, f);
	s.settings.m_weightFeeling = true;
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

/// Steps a plugin trial `steps` times and returns one of the solver's per-step statistics summed
/// over those steps (e.g. &btShockPropagationStatistics::m_numLayerSweeps).
inline long sumOverSteps(harness::Trial& trial, int steps, int btShockPropagationStatistics::*statistic)
{
	long sum = 0;
	for (int i = 0; i < steps; ++i)
	{
		trial.step();
		sum += trial.simulation().shockSolver()->getStatistics().*statistic;
	}
	return sum;
}

}  // namespace spec
