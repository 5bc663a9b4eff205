// Command-line values shared by the demo programs (bsp_demo, bsp_viewer, bsp_sweep). Each function
// throws std::invalid_argument with a message that quotes the bad text; the programs print it and
// exit with code 2.
#pragma once

#include <BulletShockPropagation/btShockPropagationSettings.h>

#include <iosfwd>
#include <string>
#include <utility>
#include <vector>

namespace harness
{
/// A finite decimal number, the whole text ("1e-3" yes; "", "1x", "nan", "inf" no).
double parseNumber(const std::string& text);

/// A whole number of at most 1e9 in magnitude ("10", "1e3" yes; "1.5" no).
int parseInteger(const std::string& text);

/// Comma-separated entries, none empty; `what` names the list in the message ("iteration").
std::vector<std::string> splitList(const std::string& text, const std::string& what);
std::vector<double> parseNumberList(const std::string& text, const std::string& what);
std::vector<int> parseIntegerList(const std::string& text, const std::string& what);

/// A scene parameter NAME=VALUE.
std::pair<std::string, double> parseSceneParam(const std::string& text);

/// The plugin settings the programs vary from the command line (bsp_demo, bsp_viewer), one flag
/// per btShockPropagationSettings field, all in one table (pluginFlags() in CommandLine.cpp): a
/// new setting is one field there and one entry here. A flag with a value takes a comma list;
/// each value is one variant, and the programs run every combination (expand()).
class PluginFlags
{
public:
	/// If argv[i] is a plugin flag, takes it (and its value, advancing i) and returns true.
	/// Throws std::invalid_argument on a missing or bad value.
	bool parse(int argc, char** argv, int& i);
	/// `base` with every combination of the values given (just `base` when no flag was given).
	std::vector<btShockPropagationSettings> expand(const btShockPropagationSettings& base = btShockPropagationSettings()) const;
	/// One help line per flag.
	static void printUsage(std::ostream& out);

private:
	struct Given
	{
		int flag;                         ///< index in the table
		std::vector<std::string> values;  ///< one entry for a switch (empty text)
	};
	std::vector<Given> m_given;
};

/// The text after option argv[i], advancing i; throws std::invalid_argument ("missing value after
/// --x") when there is none.
std::string optionValue(int argc, char** argv, int& i);

/// The options bsp_demo and bsp_viewer share, read at argv[i]: --help / -h (calls `usage` and exits
/// with 0), --list (prints the scene registry and exits with 0) and the plugin flags (into
/// `plugin`, advancing i). True if argv[i] was one of them.
bool parseSharedOption(int argc, char** argv, int& i, PluginFlags& plugin, void (*usage)());

/// " f=0.5" plus " <flag label>" for every plugin flag whose value differs from the default,
/// e.g. " f=0.1 fix=keep bfs" (SolverSpec::label()).
std::string pluginSettingsLabel(const btShockPropagationSettings& settings);
}  // namespace harness
