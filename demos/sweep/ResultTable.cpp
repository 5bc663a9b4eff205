#include "ResultTable.h"

#include <cmath>
#include <cstdio>
#include <fstream>
#include <stdexcept>

namespace sweep
{
namespace
{
std::ofstream openOrThrow(const std::string& path)
{
	std::ofstream out(path);
	if (!out) throw std::runtime_error("cannot write '" + path + "'");
	return out;
}

std::string jsonString(const std::string& s)
{
	std::string out = "\"";
	for (char c : s)
	{
		if (c == '"' || c == '\\') out += '\\';
		out += c;
	}
	return out + "\"";
}
}  // namespace

void ResultTable::add(const std::string& key, double value)
{
	char text[64] = "";
	if (std::isfinite(value)) std::snprintf(text, sizeof text, "%.6g", value);
	m_rows.back().push_back({key, text, false});  // non-finite: empty in CSV, null in JSON
}

void ResultTable::add(const std::string& key, const std::string& text) { m_rows.back().push_back({key, text, true}); }

void ResultTable::writeCsv(const std::string& path) const
{
	std::ofstream out = openOrThrow(path);
	if (m_rows.empty()) return;
	for (size_t i = 0; i < m_rows.front().size(); ++i) out << (i ? "," : "") << m_rows.front()[i].key;
	out << "\n";
	for (const std::vector<Field>& row : m_rows)
	{
		for (size_t i = 0; i < row.size(); ++i) out << (i ? "," : "") << row[i].value;
		out << "\n";
	}
}

void ResultTable::writeJson(const std::string& path, const std::vector<std::pair<std::string, std::string>>& notes) const
{
	std::ofstream out = openOrThrow(path);
	out << "{\"notes\":{";
	for (size_t i = 0; i < notes.size(); ++i) out << (i ? "," : "") << jsonString(notes[i].first) << ":" << jsonString(notes[i].second);
	out << "},\n\"rows\":[\n";
	for (size_t r = 0; r < m_rows.size(); ++r)
	{
		out << (r ? ",\n" : "") << "{";
		for (size_t i = 0; i < m_rows[r].size(); ++i)
		{
			const Field& f = m_rows[r][i];
			out << (i ? "," : "") << jsonString(f.key) << ":" << (f.text ? jsonString(f.value) : (f.value.empty() ? "null" : f.value));
		}
		out << "}";
	}
	out << "\n]}\n";
}
}  // namespace sweep
