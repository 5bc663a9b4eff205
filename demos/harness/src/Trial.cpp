#include "harness/Trial.h"

#include <BulletShockPropagation/btShockPropagationConstraintSolver.h>

#include <algorithm>
#include <chrono>

namespace harness
{
Trial::Trial(const SolverSpec& solver, const std::string& scene,
			 const std::vector<std::pair<std::string, double>>& overrides, double timeStep)
	: m_sim(new Simulation(solver, timeStep))
{
	m_scene = scenes::createScene(m_sim->world(), scene, overrides);
	m_bodies = m_scene->dynamicBodies();
	m_drift.reset(new DriftTracker(m_bodies));
}

Trial::~Trial()
{
	m_scene.reset();  // the scene removes its bodies while the world still exists
	m_sim.reset();
}

void Trial::step()
{
	const auto start = std::chrono::steady_clock::now();
	m_sim->step();
	m_seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

	btDispatcher& dispatcher = *m_sim->world().getDispatcher();
	const double drift = m_drift->maxDrift();
	m_series.drift.push_back(drift);
	m_maxDrift = std::max(m_maxDrift, drift);
	m_series.penetration.push_back(maxPenetration(dispatcher));
	m_series.kineticEnergy.push_back(kineticEnergy(m_bodies));
	m_series.groundOverWeight.push_back(
		// The manifolds hold the impulses of the frame's last sub-step.
		groundReactionOverWeight(dispatcher, m_scene->ground(), m_bodies, m_sim->timeStep() / m_sim->spec().substeps, m_sim->gravity()));
	if (m_collapseTime < 0 && drift > kStandingDriftMeters) m_collapseTime = m_sim->time();
	m_nonFinite = m_nonFinite || anyNonFinite(m_bodies);
	if (m_sim->shockSolver()) m_layers = std::max(m_layers, m_sim->shockSolver()->getStatistics().m_numLayers);
}

void Trial::run(double seconds)
{
	const int frames = int(seconds / m_sim->timeStep() + 0.5);
	for (int i = 0; i < frames; ++i) step();
}

TrialSummary Trial::summary() const
{
	TrialSummary s;
	const int n = steps();
	s.nonFinite = m_nonFinite;
	s.collapseTime = m_collapseTime;
	s.standing = m_collapseTime < 0 && !m_nonFinite;
	s.rmsDrift = m_drift->rmsDrift();
	s.layers = m_layers;
	if (n == 0) return s;
	s.maxDrift = m_maxDrift;
	s.maxPenetration = *std::max_element(m_series.penetration.begin(), m_series.penetration.end());
	const int window = std::min(n, std::max(1, int(1.0 / m_sim->timeStep() + 0.5)));
	for (int k = n - window; k < n; ++k)
	{
		s.kineticEnergyLastSecond += m_series.kineticEnergy[k] / window;
		s.groundOverWeightLastSecond += m_series.groundOverWeight[k] / window;
	}
	s.msPerStep = m_seconds * 1e3 / n;
	return s;
}
}  // namespace harness
