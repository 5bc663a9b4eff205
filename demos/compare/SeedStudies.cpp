#include "SeedStudies.h"

#include "Report.h"

#include <algorithm>
#include <cstdarg>
#include <cstdio>
#include <fstream>
#include <ostream>

namespace compare
{
namespace
{
const double kTimeStep = 1.0 / 60.0;

harness::SolverSpec solver(harness::SolverKind kind, int iterations)
{
	harness::SolverSpec s;
	s.kind = kind;
	s.iterations = iterations;
	return s;
}

const harness::SolverSpec kStock10 = solver(harness::SolverKind::StockSI, 10);
const harness::SolverSpec kStock100 = solver(harness::SolverKind::StockSI, 100);
const harness::SolverSpec kShock10 = solver(harness::SolverKind::ShockWorld, 10);

struct Group
{
	std::string scene;
	std::vector<std::pair<std::string, double>> params;
	std::vector<harness::SolverSpec> solvers;
	std::vector<double> checkpoints;  // seconds, ascending
};

/// What the studies read off a trial at a checkpoint.
struct Snapshot
{
	double time = 0;
	double drift = 0;        // m, largest body displacement now
	double penetration = 0;  // m, deepest contact now
	double maxSpeed = 0;     // m/s, fastest body now
	double topDrop = 0;      // m, how far the body named "top" sank (0 if none)
};

Snapshot snapshot(harness::Trial& t, double topStartY)
{
	Snapshot s;
	s.time = t.simulation().time();
	s.drift = t.series().drift.back();
	s.penetration = t.series().penetration.back();
	s.maxSpeed = harness::maxSpeed(t.bodies());
	if (const btRigidBody* top = t.scene().named("top")) s.topDrop = topStartY - top->getCenterOfMassPosition().y();
	return s;
}

int stepsUntil(double seconds) { return int(seconds / kTimeStep + 0.5); }

long totalSteps(const std::vector<Group>& groups)
{
	long total = 0;
	for (const Group& g : groups) total += stepsUntil(g.checkpoints.back());
	return total;
}

/// Runs one group in lockstep; returns [trial][checkpoint] snapshots and the trials.
std::vector<std::vector<Snapshot>> runGroup(const Group& g, Trials& trials, bool progress, long& done, long total)
{
	std::vector<double> topStart;
	for (const harness::SolverSpec& spec : g.solvers)
	{
		trials.emplace_back(new harness::Trial(spec, g.scene, g.params, kTimeStep));
		const btRigidBody* top = trials.back()->scene().named("top");
		topStart.push_back(top ? double(top->getCenterOfMassPosition().y()) : 0.0);
	}
	std::vector<std::vector<Snapshot>> snaps(trials.size());
	int stepped = 0;
	for (double checkpoint : g.checkpoints)
	{
		const int steps = stepsUntil(checkpoint) - stepped;
		runLockstep(trials, steps, progress, done, total);
		done += steps;
		stepped += steps;
		for (size_t i = 0; i < trials.size(); ++i) snaps[i].push_back(snapshot(*trials[i], topStart[i]));
	}
	return snaps;
}

void csvRows(std::ostream* csv, const char* study, const Group& g, const Trials& trials, const std::vector<std::vector<Snapshot>>& snaps)
{
	if (!csv) return;
	for (size_t i = 0; i < trials.size(); ++i)
	{
		const harness::SolverSpec& spec = trials[i]->simulation().spec();
		for (const Snapshot& s : snaps[i])
			*csv << study << "," << g.scene << "," << spec.label() << "," << spec.iterations << "," << s.time << "," << s.drift << ","
				 << s.penetration << "," << s.maxSpeed << "," << s.topDrop << "," << trials[i]->summary().msPerStep << "\n";
	}
}

std::string line(const char* format, ...) __attribute__((format(printf, 1, 2)));
std::string line(const char* format, ...)
{
	char buffer[512];
	va_list args;
	va_start(args, format);
	std::vsnprintf(buffer, sizeof buffer, format, args);
	va_end(args);
	return buffer;
}
}  // namespace

void runSeedStudies(std::ostream& out, const std::string& csvPath, bool progress)
{
	std::ofstream csvFile;
	std::ostream* csv = nullptr;
	if (!csvPath.empty())
	{
		csvFile.open(csvPath);
		csv = &csvFile;
		*csv << "study,scene,solver,iterations,time_s,max_drift_m,max_penetration_m,max_speed_m_s,top_drop_m,ms_per_step\n";
	}

	const std::vector<Group> convergence = {
		{"wall", {}, {kStock10, kStock100, kShock10}, {4.0}},
		{"round_tower", {}, {kStock10, kStock100, kShock10}, {4.0}},
	};
	const std::vector<Group> frame6 = {
		{"tower", {{"n", 20}}, {kStock10, kStock100, kShock10}, {6 * kTimeStep}},
	};
	const std::vector<Group> sequences = {
		{"sparse_stacking", {}, {kStock10, kShock10}, {2, 4, 6, 8}},
		{"dense_random", {}, {kStock10, kShock10}, {2, 4, 6, 8}},
		{"pyramid", {}, {kStock10, kShock10}, {2, 4, 6, 8}},
		{"wall", {}, {kStock10, kShock10}, {2, 4, 6, 8}},
		{"round_tower", {}, {kStock10, kShock10}, {2, 4, 6, 8}},
	};
	const long total = totalSteps(convergence) + totalSteps(frame6) + totalSteps(sequences);
	long done = 0;

	out << "Seed study 1: convergence of the iterative solver, after 4 s (dt 1/60 s; standing = every body within 1 cm)\n";
	out << line("%-12s %-10s %-9s %10s %10s %10s %9s %8s\n", "scene", "solver", "standing", "maxdrift", "maxpen", "max speed", "ms/step", "ratio");
	for (const Group& g : convergence)
	{
		Trials trials;
		const auto snaps = runGroup(g, trials, progress, done, total);
		csvRows(csv, "convergence", g, trials, snaps);
		const double base = trials.front()->summary().msPerStep;
		for (size_t i = 0; i < trials.size(); ++i)
		{
			const harness::TrialSummary s = trials[i]->summary();
			const harness::SolverSpec& spec = trials[i]->simulation().spec();
			const std::string name = spec.name() + "-" + std::to_string(spec.iterations);
			out << line("%-12s %-10s %-9s %8.2fcm %8.2fmm %8.3fm/s %9.3f %7.2fx\n", g.scene.c_str(), name.c_str(), s.standing ? "yes" : "no",
						snaps[i].back().drift * 100, s.maxPenetration * 1e3, snaps[i].back().maxSpeed, s.msPerStep, s.msPerStep / base);
		}
	}

	out << "\nSeed study 2: frame 6 of a 20-box tower (0.1 s), without (stock SI) and with shock propagation\n";
	out << line("%-10s %12s %12s %12s\n", "solver", "top drop", "maxpen", "max speed");
	for (const Group& g : frame6)
	{
		Trials trials;
		const auto snaps = runGroup(g, trials, progress, done, total);
		csvRows(csv, "frame6", g, trials, snaps);
		for (size_t i = 0; i < trials.size(); ++i)
		{
			const harness::SolverSpec& spec = trials[i]->simulation().spec();
			const std::string name = spec.name() + "-" + std::to_string(spec.iterations);
			const Snapshot& s = snaps[i].back();
			out << line("%-10s %10.3fmm %10.3fmm %8.4fm/s\n", name.c_str(), s.topDrop * 1e3, s.penetration * 1e3, s.maxSpeed);
		}
	}

	out << "\nSeed study 3: sequences, largest body displacement from the start (cm) / fastest body (m/s) at 2, 4, 6, 8 s\n";
	out << line("%-16s %-8s %16s %16s %16s %16s\n", "scene", "solver", "2 s", "4 s", "6 s", "8 s");
	for (const Group& g : sequences)
	{
		Trials trials;
		const auto snaps = runGroup(g, trials, progress, done, total);
		csvRows(csv, "sequence", g, trials, snaps);
		for (size_t i = 0; i < trials.size(); ++i)
		{
			const harness::SolverSpec& spec = trials[i]->simulation().spec();
			const std::string name = spec.name() + "-" + std::to_string(spec.iterations);
			std::string row = line("%-16s %-8s", g.scene.c_str(), name.c_str());
			for (const Snapshot& s : snaps[i]) row += line(" %8.2f / %5.2f", s.drift * 100, s.maxSpeed);
			out << row << "\n";
		}
	}
	out << "(dense_random starts as a falling grid: its displacement is the drop into the pit, compare the solvers' pile speeds)\n";
}
}  // namespace compare
