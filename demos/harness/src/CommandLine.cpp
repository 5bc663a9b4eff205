#include "harness/CommandLine.h"

#include <scenes/Registry.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <functional>
#include <iostream>
#include <ostream>
#include <sstream>
#include <stdexcept>
#include <type_traits>

namespace harness
{
double parseNumber(const std::string& text)
{
	char* end = nullptr;
	const double v = std::strtod(text.c_str(), &end);
	if (text.empty() || *end != '\0' || !std::isfinite(v)) throw std::invalid_argument("not a number: '" + text + "'");
	return v;
}

int parseInteger(const std::string& text)
{
	const double v = parseNumber(text);
	if (v != std::floor(v) || std::fabs(v) > 1e9) throw std::invalid_argument("not an integer: '" + text + "'");
	return int(v);
}

std::vector<std::string> splitList(const std::string& text, const std::string& what)
{
	std::vector<std::string> out;
	std::stringstream in(text);
	std::string item;
	while (std::getline(in, item, ','))
	{
		if (item.empty()) throw std::invalid_argument("empty entry in " + what + " list '" + text + "'");
		out.push_back(item);
	}
	if (out.empty()) throw std::invalid_argument("empty " + what + " list");
	return out;
}

std::vector<double> parseNumberList(const std::string& text, const std::string& what)
{
	std::vector<double> out;
	for (const std::string& item : splitList(text, what)) out.push_back(parseNumber(item));
	return out;
}

std::vector<int> parseIntegerList(const std::string& text, const std::string& what)
{
	std::vector<int> out;
	for (const std::string& item : splitList(text, what)) out.push_back(parseInteger(item));
	return out;
}

std::pair<std::string, double> parseSceneParam(const std::string& text)
{
	const auto eq = text.find('=');
	if (eq == std::string::npos || eq == 0) throw std::invalid_argument("--param wants NAME=VALUE, got '" + text + "'");
	return {text.substr(0, eq), parseNumber(text.substr(eq + 1))};
}

namespace
{
/// One plugin setting on the command line. `set` applies one value (text; "" for a switch) and
/// throws std::invalid_argument on a bad one; `show` gives the label text for the setting's value.
struct PluginFlag
{
	const char* flag;
	const char* value;  ///< value placeholder in the help, nullptr for a switch
	const char* help;
	bool alwaysInLabel;  ///< shown in labels even at the default (f)
	std::function<void(btShockPropagationSettings&, const std::string&)> set;
	std::function<std::string(const btShockPropagationSettings&)> show;
};

/// Where a flag's field is: a member of the settings, or of their diagnostics (m_diagnostics).
template <class T>
using FieldOf = std::function<T&(btShockPropagationSettings&)>;
template <class T>
FieldOf<T> field(T btShockPropagationSettings::*member)
{
	return [member](btShockPropagationSettings& s) -> T& { return s.*member; };
}
template <class T>
FieldOf<T> diagnostic(T btShockPropagationDiagnostics::*member)
{
	return [member](btShockPropagationSettings& s) -> T& { return s.m_diagnostics.*member; };
}

/// A switch that sets a bool field to `value`; labelled `label` when it does.
PluginFlag switchFlag(const char* flag, const char* help, FieldOf<bool> at, bool value, const char* label)
{
	return {flag, nullptr, help, false, [=](btShockPropagationSettings& s, const std::string&) { at(s) = value; },
			[=](const btShockPropagationSettings& s) {
				btShockPropagationSettings copy = s;
				return std::string(at(copy) == value ? label : "");
			}};
}

/// A numeric field (whole numbers for an int field) whose values pass `valid` (described by
/// `range`); labelled "key=value".
template <class T>
PluginFlag numberFlag(const char* flag, const char* value, const char* help, FieldOf<T> at, const char* key, bool (*valid)(double),
					  const char* range, bool alwaysInLabel = false)
{
	const std::string name = flag;
	return {flag, value, help, alwaysInLabel,
			[=](btShockPropagationSettings& s, const std::string& text) {
				const double v = std::is_integral<T>::value ? double(parseInteger(text)) : parseNumber(text);
				if (!valid(v)) throw std::invalid_argument(name + " values must be " + range + ", got '" + text + "'");
				at(s) = T(v);
			},
			[=](const btShockPropagationSettings& s) {
				btShockPropagationSettings copy = s;
				std::ostringstream out;
				out << key << "=" << at(copy);
				return out.str();
			}};
}

/// The table: a plugin setting's flag is one entry here.
const std::vector<PluginFlag>& pluginFlags()
{
	static const std::vector<PluginFlag> table = {
		numberFlag("--f", "F,G,...", "plugin weighting values f in [0,1]: the corrector runs ceil(f N) sweeps (default 0.5)", field(&btShockPropagationSettings::m_weighting), "f",
				   [](double f) { return f >= 0 && f <= 1; }, "in [0, 1]", true),
		switchFlag("--global-correction", "plugin: the paper's un-layered second correction (D4)",
				   diagnostic(&btShockPropagationDiagnostics::m_layeredSecondCorrection), false, "globalcorr"),
		numberFlag("--slop", "M,N,...", "plugin: correction slop values in metres (default: 0.18 g dt^2; D6)",
				   field(&btShockPropagationSettings::m_correctionSlop), "slop", [](double m) { return m >= 0 || m == -1; }, ">= 0 metres"),
		switchFlag("--bfs-layers", "plugin: plain BFS layers, no support ordering (D12 off)", diagnostic(&btShockPropagationDiagnostics::m_supportOrdering),
				   false, "bfs"),
		switchFlag("--app-friction", "plugin: stacked groups keep the app's friction rows (one per point by default) instead of two (D7)",
				   diagnostic(&btShockPropagationDiagnostics::m_twoFrictionDirections), false, "appfriction"),
		numberFlag("--weight-convergence", "C,...", "plugin: the corrector's sweeps end once none changes a row's velocity by more than C |g| dt (default 0.006)",
				   diagnostic(&btShockPropagationDiagnostics::m_weightConvergence), "wconv", [](double c) { return c >= 0; }, ">= 0"),
		switchFlag("--no-box-face-corners", "plugin: a box face resting on a box gets only the points Bullet's box-box test reports (D30 off)",
				   field(&btShockPropagationSettings::m_keepBoxFaceCorners), false, "nocorners"),
		switchFlag("--second-correction", "plugin: the world's second phase, detection at t + dt and correction (D4; the default since issue 38)",
				   field(&btShockPropagationSettings::m_secondCorrection), true, "secondcorr"),
		switchFlag("--no-second-phase", "plugin: no second phase after the positions advance (D4 off: the world steps as the solver-only mode)",
				   field(&btShockPropagationSettings::m_secondCorrection), false, "nosecond"),
		switchFlag("--second-all-pairs", "plugin: the second phase's detection dispatches every overlapping pair, not only those of stacked islands (D4)",
				   diagnostic(&btShockPropagationDiagnostics::m_secondDetectionAllPairs), true, "allpairs2"),
		switchFlag("--second-depth-refresh", "plugin: the second correction at the step's own points, depths refreshed, no detection at t + dt (before issue 38)",
				   diagnostic(&btShockPropagationDiagnostics::m_secondDetection), false, "refresh2"),
		numberFlag("--predictor-convergence", "C,...", "plugin: the predictor ends a layer visit once a sweep moves no row by more than C |g| dt (default 6e-6)",
				   diagnostic(&btShockPropagationDiagnostics::m_predictorConvergence), "pconv", [](double c) { return c >= 0; }, ">= 0"),
		numberFlag("--predictor-sweeps", "N,...", "plugin: most sweeps per layer visit of the predictor (default 200)",
				   diagnostic(&btShockPropagationDiagnostics::m_predictorIterations), "psweeps", [](double n) { return n >= 0; }, ">= 0"),
		numberFlag("--predictor-cycles", "N,...", "plugin: most up-and-down cycles of the predictor (default 4)",
				   diagnostic(&btShockPropagationDiagnostics::m_predictorCycles), "pcycles", [](double n) { return n >= 1; }, ">= 1"),
	};
	return table;
}
}  // namespace

bool PluginFlags::parse(int argc, char** argv, int& i)
{
	const std::string a = argv[i];
	const std::vector<PluginFlag>& flags = pluginFlags();
	for (int k = 0; k < int(flags.size()); ++k)
	{
		const PluginFlag& f = flags[k];
		if (a != f.flag) continue;
		Given given{k, {""}};
		if (f.value)
		{
			if (i + 1 >= argc) throw std::invalid_argument("missing value after " + a);
			given.values = splitList(argv[++i], a.substr(2));
			btShockPropagationSettings probe;
			for (const std::string& v : given.values) f.set(probe, v);  // reject bad values now
		}
		const auto same = std::find_if(m_given.begin(), m_given.end(), [k](const Given& g) { return g.flag == k; });
		if (same != m_given.end())
			*same = given;  // the last one given counts
		else
			m_given.push_back(given);
		return true;
	}
	return false;
}

std::vector<btShockPropagationSettings> PluginFlags::expand(const btShockPropagationSettings& base) const
{
	std::vector<btShockPropagationSettings> out{base};
	for (const Given& g : m_given)
	{
		std::vector<btShockPropagationSettings> next;
		for (const btShockPropagationSettings& s : out)
			for (const std::string& v : g.values)
			{
				next.push_back(s);
				pluginFlags()[g.flag].set(next.back(), v);
			}
		out.swap(next);
	}
	return out;
}

void PluginFlags::printUsage(std::ostream& out)
{
	for (const PluginFlag& f : pluginFlags())
	{
		std::string head = std::string("  ") + f.flag + (f.value ? std::string(" ") + f.value : std::string());
		head.resize(std::max<size_t>(head.size() + 1, 24), ' ');
		out << head << f.help << "\n";
	}
}

std::string optionValue(int argc, char** argv, int& i)
{
	if (i + 1 >= argc) throw std::invalid_argument(std::string("missing value after ") + argv[i]);
	return argv[++i];
}

bool parseSharedOption(int argc, char** argv, int& i, PluginFlags& plugin, void (*usage)())
{
	const std::string a = argv[i];
	if (a == "--help" || a == "-h")
	{
		usage();
		std::exit(0);
	}
	if (a == "--list")
	{
		scenes::printRegistry(std::cout);
		std::exit(0);
	}
	return plugin.parse(argc, argv, i);
}

std::string pluginSettingsLabel(const btShockPropagationSettings& settings)
{
	const btShockPropagationSettings defaults;
	std::string out;
	for (const PluginFlag& f : pluginFlags())
	{
		const std::string text = f.show(settings);
		if (!text.empty() && (f.alwaysInLabel || text != f.show(defaults))) out += " " + text;
	}
	return out;
}
}  // namespace harness
