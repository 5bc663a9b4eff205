#include "harness/CommandLine.h"

#include <cmath>
#include <cstdlib>
#include <sstream>
#include <stdexcept>

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
}  // namespace harness
