// One registry scene under several solvers, stepped in lockstep: what the viewer shows side by
// side. Each viewport is a harness::Trial (the demo program's world, solver and metrics).
#pragma once

#include <harness/Trial.h>

#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace viewer
{
struct ComparisonSetup
{
	std::string scene = "wall";
	std::vector<std::pair<std::string, double>> params;  ///< scene parameter overrides
	std::vector<harness::SolverSpec> solvers;            ///< one viewport each
	double timeStep = 1.0 / 60.0;                        ///< s per frame
};

class Comparison
{
public:
	/// Builds every trial; throws std::invalid_argument for an unknown scene or parameter (the
	/// message lists the valid ones) or an empty solver list.
	explicit Comparison(const ComparisonSetup& setup);

	/// Rebuilds every trial from the setup (time 0, no shot boxes).
	void reset();
	/// One frame of every trial, one after the other.
	void step();
	/// Steps until `steps` frames have been taken since the last reset.
	void stepTo(int steps);
	int steps() const;
	double time() const;

	const ComparisonSetup& setup() const { return m_setup; }
	int size() const { return int(m_trials.size()); }
	harness::Trial& trial(int i) { return *m_trials[size_t(i)]; }
	const harness::Trial& trial(int i) const { return *m_trials[size_t(i)]; }

	/// Adds the same box to every world, its centre at `origin`, moving along `direction` (any
	/// length) at `speed` m/s: a cube of edge `edge` m and `mass` kg, with the scene's friction.
	void shootBox(const btVector3& origin, const btVector3& direction, double speed, double edge, double mass);
	int shotBoxes() const { return m_shots; }

private:
	ComparisonSetup m_setup;
	std::vector<std::unique_ptr<harness::Trial>> m_trials;
	int m_shots = 0;
};
}  // namespace viewer
