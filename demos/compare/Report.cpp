#include "Report.h"

#include <cstdio>
#include <ostream>
#include <unistd.h>

namespace compare
{
namespace
{
void drawBar(double fraction)
{
	const int width = 40;
	const int filled = int(fraction * width + 0.5);
	std::fprintf(stderr, "\r[%.*s%*s] %3d%%", filled, "========================================", width - filled, "", int(fraction * 100 + 0.5));
	std::fflush(stderr);
}
}  // namespace

void runLockstep(Trials& trials, int steps, bool progress, long done, long total)
{
	const bool show = progress && isatty(2);
	if (total <= 0) total = steps;
	for (int step = 0; step < steps; ++step)
	{
		for (std::unique_ptr<harness::Trial>& t : trials) t->step();
		if (show && (step % 10 == 0 || step == steps - 1)) drawBar(double(done + step + 1) / double(total));
	}
	if (show && done + steps >= total) std::fprintf(stderr, "\n");
}

void printTable(std::ostream& out, const Trials& trials)
{
	char line[256];
	std::snprintf(line, sizeof line, "%-30s %-12s %10s %10s %10s %12s %9s %9s %10s %7s\n", "solver", "standing", "maxdrift", "rmsdrift", "maxpen",
				  "KE(last 1s)", "ground/W", "ms/step", "ratio", "layers");
	out << line;
	const double baseMs = trials.empty() ? 1 : trials.front()->summary().msPerStep;
	for (const std::unique_ptr<harness::Trial>& t : trials)
	{
		const harness::TrialSummary s = t->summary();
		char standing[32];
		if (s.nonFinite) std::snprintf(standing, sizeof standing, "NaN");
		else if (s.standing) std::snprintf(standing, sizeof standing, "yes");
		else std::snprintf(standing, sizeof standing, "moved@%.2fs", s.collapseTime);
		std::snprintf(line, sizeof line, "%-30s %-12s %8.2fcm %8.2fcm %8.2fmm %10.3g J %9.3f %9.3f %9.2fx %7d\n",
					  t->simulation().spec().label().c_str(), standing, s.maxDrift * 100, s.rmsDrift * 100, s.maxPenetration * 1e3,
					  s.kineticEnergyLastSecond, s.groundOverWeightLastSecond, s.msPerStep, s.msPerStep / baseMs, s.layers);
		out << line;
	}
}

void writeCsv(std::ostream& out, const std::string& scene, const Trials& trials, bool header)
{
	if (header)
		out << "scene,solver,iterations,f,substeps,standing,collapse_s,max_drift_m,rms_drift_m,max_penetration_m,"
			   "ke_last_second_j,ground_over_weight,ms_per_step,layers\n";
	for (const std::unique_ptr<harness::Trial>& t : trials)
	{
		const harness::SolverSpec& spec = t->simulation().spec();
		const harness::TrialSummary s = t->summary();
		out << scene << "," << spec.name() << "," << spec.iterations << "," << spec.settings.m_weighting << "," << spec.substeps << ","
			<< s.standing << "," << s.collapseTime << "," << s.maxDrift << "," << s.rmsDrift << "," << s.maxPenetration << ","
			<< s.kineticEnergyLastSecond << "," << s.groundOverWeightLastSecond << "," << s.msPerStep << "," << s.layers << "\n";
	}
}

void writeJson(std::ostream& out, const std::string& scene, double timeStep, double duration, const Trials& trials)
{
	out << "{\"scene\":\"" << scene << "\",\"dt\":" << timeStep << ",\"duration\":" << duration << ",\"runs\":[";
	for (size_t i = 0; i < trials.size(); ++i)
	{
		const harness::Trial& t = *trials[i];
		const harness::SolverSpec& spec = t.simulation().spec();
		const harness::TrialSummary s = t.summary();
		auto series = [&](const char* name, const std::vector<double>& v) {
			out << ",\"" << name << "\":[";
			for (size_t k = 0; k < v.size(); ++k) out << (k ? "," : "") << v[k];
			out << "]";
		};
		out << (i ? "," : "") << "{\"solver\":\"" << spec.label() << "\",\"iterations\":" << spec.iterations << ",\"f\":" << spec.settings.m_weighting
			<< ",\"substeps\":" << spec.substeps << ",\"standing\":" << (s.standing ? "true" : "false") << ",\"collapse_s\":" << s.collapseTime
			<< ",\"max_drift_m\":" << s.maxDrift << ",\"rms_drift_m\":" << s.rmsDrift << ",\"max_penetration_m\":" << s.maxPenetration
			<< ",\"ke_last_second_j\":" << s.kineticEnergyLastSecond << ",\"ground_over_weight\":" << s.groundOverWeightLastSecond
			<< ",\"ms_per_step\":" << s.msPerStep << ",\"layers\":" << s.layers;
		series("drift_m", t.series().drift);
		series("penetration_m", t.series().penetration);
		series("kinetic_energy_j", t.series().kineticEnergy);
		series("ground_over_weight", t.series().groundOverWeight);
		out << "}";
	}
	out << "]}\n";
}
}  // namespace compare
