// One registry scene under one solver, stepped and measured: the unit the demo program, the
// seed studies, the sweep, the viewer, the behaviour and robustness specs and the benchmarks
// share (world + scene + teardown, written once). Not part of the shipped plugin.
#pragma once

#include <harness/Metrics.h>
#include <harness/Simulation.h>
#include <harness/Standing.h>
#include <scenes/Registry.h>

#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace harness
{
/// What a Trial measured after each step (index k = after step k + 1).
struct TrialSeries
{
	std::vector<double> drift;        ///< largest body displacement from the start (m)
	std::vector<double> penetration;  ///< deepest contact (m)
	std::vector<double> kineticEnergy;  ///< J
	std::vector<double> groundOverWeight;  ///< vertical ground reaction / total weight (-)
};

/// Summary over all steps so far.
struct TrialSummary
{
	bool standing = true;        ///< no body moved more than kStandingDriftMeters, nothing non-finite
	bool nonFinite = false;      ///< a NaN or Inf position or velocity appeared
	double collapseTime = -1;    ///< s, first time a body passed kStandingDriftMeters (-1: never)
	double maxDrift = 0;         ///< m, over all steps
	double rmsDrift = 0;         ///< m, at the last step
	double maxPenetration = 0;   ///< m, over all steps
	double kineticEnergyLastSecond = 0;  ///< J, mean over the last second
	double groundOverWeightLastSecond = 0;  ///< mean over the last second
	double msPerStep = 0;        ///< wall-clock milliseconds per step (stepSimulation only)
	int layers = 0;              ///< most stack layers in one step (plugin only)
};

class Trial
{
public:
	/// Builds `scene` (with `overrides`) into a fresh world with `solver`. Throws
	/// std::invalid_argument for an unknown scene or parameter (the message lists the valid ones).
	Trial(const SolverSpec& solver, const std::string& scene,
		  const std::vector<std::pair<std::string, double>>& overrides = {}, double timeStep = 1.0 / 60.0);
	~Trial();
	Trial(const Trial&) = delete;
	Trial& operator=(const Trial&) = delete;

	/// One frame: steps the world (timed) and records the metrics.
	void step();
	/// step() for `seconds` of simulated time (rounded to whole frames).
	void run(double seconds);

	Simulation& simulation() { return *m_sim; }
	const Simulation& simulation() const { return *m_sim; }
	scenes::SceneContent& scene() { return *m_scene; }
	const scenes::SceneContent& scene() const { return *m_scene; }
	const std::vector<btRigidBody*>& bodies() const { return m_bodies; }
	const DriftTracker& drift() const { return *m_drift; }
	const TrialSeries& series() const { return m_series; }
	int steps() const { return int(m_series.drift.size()); }
	/// Largest body displacement from the start after any step() so far (m).
	double maxDrift() const { return m_maxDrift; }
	/// The scene's body with this key (scenes::SceneContent::named).
	btRigidBody* named(const std::string& key) const { return m_scene->named(key); }
	TrialSummary summary() const;

private:
	std::unique_ptr<Simulation> m_sim;
	std::unique_ptr<scenes::SceneContent> m_scene;
	std::vector<btRigidBody*> m_bodies;
	std::unique_ptr<DriftTracker> m_drift;
	TrialSeries m_series;
	double m_seconds = 0;
	double m_maxDrift = 0;
	double m_collapseTime = -1;
	bool m_nonFinite = false;
	int m_layers = 0;
};
}  // namespace harness
