// Printing for bsp_demo: the comparison table, CSV / JSON files and the progress bar.
#pragma once

#include <harness/Trial.h>

#include <iosfwd>
#include <memory>
#include <string>
#include <vector>

namespace compare
{
using Trials = std::vector<std::unique_ptr<harness::Trial>>;

/// Steps every trial `steps` times in lockstep (one frame of each, then the next frame), with a
/// progress bar on stderr if `progress` and stderr is a terminal. `done` and `total` place this
/// run's share on the bar when several runs share one (steps counted over all of them).
void runLockstep(Trials& trials, int steps, bool progress, long done = 0, long total = 0);

/// The comparison table; ratio = ms/step over the first trial's.
void printTable(std::ostream& out, const Trials& trials);

/// One CSV row per trial (header first if `header`).
void writeCsv(std::ostream& out, const std::string& scene, const Trials& trials, bool header = true);

/// Summary and per-step series of every trial.
void writeJson(std::ostream& out, const std::string& scene, double timeStep, double duration, const Trials& trials);
}  // namespace compare
