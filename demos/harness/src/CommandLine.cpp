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

const char* const kFixationNames[] = {"keep", "zero", "linear", "twist"};  // by btShockPropagationFixationMode

/// The table: a plugin setting's flag is one entry here.
const std::vector<PluginFlag>& pluginFlags()
{
	static const std::vector<PluginFlag> table = {
		numberFlag("--f", "F,G,...", "plugin weighting values f in [0,1] (default 0.5; D2)", field(&btShockPropagationSettings::m_weighting), "f",
				   [](double f) { return f >= 0 && f <= 1; }, "in [0, 1]", true),
		{"--fixation", "MODE,...", "plugin fixation: twist (default), linear, keep, zero (D1)", false,
		 [](btShockPropagationSettings& s, const std::string& text) {
			 for (int m = 0; m < 4; ++m)
				 if (text == kFixationNames[m])
				 {
					 s.m_fixationMode = btShockPropagationFixationMode(m);
					 return;
				 }
			 throw std::invalid_argument("unknown fixation mode '" + text + "'; valid: twist, linear, keep, zero");
		 },
		 [](const btShockPropagationSettings& s) { return std::string("fix=") + kFixationNames[s.m_fixationMode]; }},
		switchFlag("--global-correction", "plugin: the paper's un-layered second correction (D4)",
				   diagnostic(&btShockPropagationDiagnostics::m_layeredSecondCorrection), false, "globalcorr"),
		numberFlag("--slop", "M,N,...", "plugin: correction slop values in metres (default: 0.18 g dt^2; D6)",
				   field(&btShockPropagationSettings::m_correctionSlop), "slop", [](double m) { return m >= 0 || m == -1; }, ">= 0 metres"),
		switchFlag("--bfs-layers", "plugin: plain BFS layers, no support ordering (D12 off)", diagnostic(&btShockPropagationDiagnostics::m_supportOrdering),
				   false, "bfs"),
		numberFlag("--weight-sweeps", "N,...", "plugin: most sweeps per layer of the weight pass (default: 3 x the app's iterations; D16)",
				   field(&btShockPropagationSettings::m_weightIterations), "sweeps", [](double n) { return n >= 1; }, ">= 1"),
		switchFlag("--no-transfer", "plugin: no load transfer before the weight pass's sweeps (D16 off)",
				   diagnostic(&btShockPropagationDiagnostics::m_loadTransfer), false, "notransfer"),
		numberFlag("--warm-factor", "W,...", "plugin: warm-start factor of stacked groups, -1 = the app's (default 1; D16)",
				   diagnostic(&btShockPropagationDiagnostics::m_warmStartFactor), "warm", [](double w) { return (w >= 0 && w <= 1) || w == -1; }, "in [0, 1] or -1"),
		numberFlag("--tip-gain", "G,...", "plugin: weight-pass guard, steps of free fall a converged re-solve may add (default 3; D16)",
				   diagnostic(&btShockPropagationDiagnostics::m_weightGuardTipping), "tip", [](double g) { return g >= 0; }, ">= 0"),
		numberFlag("--guard-slack", "S,...", "plugin: weight-pass guard slack, share of |g| dt (default 0.1; D16)",
				   diagnostic(&btShockPropagationDiagnostics::m_weightGuardSlack), "slack", [](double g) { return g >= 0; }, ">= 0"),
		switchFlag("--app-friction", "plugin: stacked groups keep the app's friction rows (one per point by default) instead of two (D7)",
				   diagnostic(&btShockPropagationDiagnostics::m_twoFrictionDirections), false, "appfriction"),
		numberFlag("--weight-convergence", "C,...", "plugin: a weight-pass layer stops sweeping once no row's velocity changes by more than C |g| dt (default 0.006; D16)",
				   diagnostic(&btShockPropagationDiagnostics::m_weightConvergence), "wconv", [](double c) { return c >= 0; }, ">= 0"),
		numberFlag("--tip-margin", "M,...", "plugin: weight-pass guard, share of the support's size a load must act outside of to tip a body (default 0; D16)",
				   diagnostic(&btShockPropagationDiagnostics::m_weightGuardTipMargin), "tipmargin", [](double m) { return m >= 0; }, ">= 0"),
		switchFlag("--no-support-blocks", "plugin: no support block solve before a layer's sweeps (D19 off)",
				   diagnostic(&btShockPropagationDiagnostics::m_supportBlocks), false, "noblocks"),
		switchFlag("--no-weight-blocks", "plugin: a weight-pass re-solve ends after its sweeps, without its support blocks (D31 off)",
				   diagnostic(&btShockPropagationDiagnostics::m_weightPassBlocks), false, "noweightblocks"),
		switchFlag("--no-fixation-rest-speed", "plugin: a fixated support shows the layer above even motion slower than the convergence speed (D32 off)",
				   diagnostic(&btShockPropagationDiagnostics::m_fixationRestSpeed), false, "norestspeed"),
		switchFlag("--own-transfer-factor", "plugin: the load transfer factors its own normal equations instead of using the support block's (D24 off)",
				   diagnostic(&btShockPropagationDiagnostics::m_sharedBlockFactor), false, "ownfactor"),
		numberFlag("--layer-min-sweeps", "N,...", "plugin: fewest sweeps per layer before a converged layer ends, -1 = always the app's N (default 2; D19)",
				   field(&btShockPropagationSettings::m_layerMinIterations), "minsweeps", [](double n) { return n >= 1 || n == -1; }, ">= 1 or -1"),
		numberFlag("--layer-floor", "N,...", "plugin: a layer may sweep at most max(the app's N, N) times before it is cut off unconverged, 0 = the app's N (default 10; D22)",
				   field(&btShockPropagationSettings::m_layerIterationFloor), "floor", [](double n) { return n >= 0; }, ">= 0"),
		switchFlag("--resolve-small-loads", "plugin: re-solve every loaded weight-pass layer, even below the convergence speed (D20 off)",
				   diagnostic(&btShockPropagationDiagnostics::m_transferSmallLoads), false, "resolvesmall"),
		switchFlag("--full-global-pass", "plugin: the global pass always runs ceil(f N) sweeps, even once converged (D21 off)",
				   diagnostic(&btShockPropagationDiagnostics::m_convergedGlobalPass), false, "fullglobal"),
		switchFlag("--reject-whole-layer", "plugin: a rejected weight-pass re-solve restores every free body of its layer (D26 off)",
				   diagnostic(&btShockPropagationDiagnostics::m_rejectPerIsland), false, "wholelayer"),
		switchFlag("--no-tipping-composites", "plugin: a body statics says tips is judged alone by the weight-pass guard (D25 off)",
				   diagnostic(&btShockPropagationDiagnostics::m_tippingComposites), false, "notipping"),
		switchFlag("--no-impact-tipping", "plugin: an impact tips a composite only where its weight would too (D27 off)",
				   diagnostic(&btShockPropagationDiagnostics::m_impactTipping), false, "noimpact"),
		switchFlag("--guard-linear-only", "plugin: the weight-pass guard judges an unconverged re-solve by the centre-of-mass speed only, not its spin (D28 off)",
				   diagnostic(&btShockPropagationDiagnostics::m_guardSpin), false, "guardlinear"),
		switchFlag("--no-rigid-sliding", "plugin: a body that slides is re-solved alone, not with what rests on it as one rigid body (D29 off)",
				   diagnostic(&btShockPropagationDiagnostics::m_rigidSlidingComposites), false, "norigidslide"),
		switchFlag("--no-box-face-corners", "plugin: a box face resting on a box gets only the points Bullet's box-box test reports (D30 off)",
				   field(&btShockPropagationSettings::m_keepBoxFaceCorners), false, "nocorners"),
		switchFlag("--composites", "plugin: a sliding base carries the inertia of what rests on it (D23, opt-in)",
				   diagnostic(&btShockPropagationDiagnostics::m_slidingComposites), true, "composites"),
		switchFlag("--second-correction", "plugin: the world's second phase, detection at t + dt and correction (D4; the default since issue 38)",
				   field(&btShockPropagationSettings::m_secondCorrection), true, "secondcorr"),
		switchFlag("--no-second-phase", "plugin: no second phase after the positions advance (D4 off: the world steps as the solver-only mode)",
				   field(&btShockPropagationSettings::m_secondCorrection), false, "nosecond"),
		switchFlag("--second-all-pairs", "plugin: the second phase's detection dispatches every overlapping pair, not only those of stacked islands (D4)",
				   diagnostic(&btShockPropagationDiagnostics::m_secondDetectionAllPairs), true, "allpairs2"),
		switchFlag("--second-depth-refresh", "plugin: the second correction at the step's own points, depths refreshed, no detection at t + dt (before issue 38)",
				   diagnostic(&btShockPropagationDiagnostics::m_secondDetection), false, "refresh2"),
		switchFlag("--converging", "plugin: the converging step (predictor, corrector; opt-in, work in progress; docs/design.md section 4u)",
				   diagnostic(&btShockPropagationDiagnostics::m_convergingStep), true, "converging"),
		numberFlag("--predictor-convergence", "C,...", "plugin: the converging step's predictor ends a layer once a sweep moves no row by more than C |g| dt (default 6e-6; section 4u)",
				   diagnostic(&btShockPropagationDiagnostics::m_predictorConvergence), "pconv", [](double c) { return c >= 0; }, ">= 0"),
		numberFlag("--predictor-sweeps", "N,...", "plugin: most sweeps per layer and pass of the converging step's predictor (default 200; section 4u)",
				   diagnostic(&btShockPropagationDiagnostics::m_predictorIterations), "psweeps", [](double n) { return n >= 0; }, ">= 0"),
		numberFlag("--predictor-cycles", "N,...", "plugin: most up-and-down cycles of the converging step's predictor (default 3; section 4u)",
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
