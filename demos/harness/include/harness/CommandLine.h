// Command-line values shared by the demo programs (bsp_demo, bsp_viewer, bsp_sweep). Each function
// throws std::invalid_argument with a message that quotes the bad text; the programs print it and
// exit with code 2.
#pragma once

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
}  // namespace harness
