// Rows of named fields, written as CSV (one header) and as JSON (an array of objects plus notes).
#pragma once

#include <string>
#include <utility>
#include <vector>

namespace sweep
{
class ResultTable
{
public:
	/// Starts a new row; then add fields in the same order for every row.
	void newRow() { m_rows.emplace_back(); }
	void add(const std::string& key, double value);
	void add(const std::string& key, const std::string& text);
	size_t size() const { return m_rows.size(); }

	/// Throws std::runtime_error if the file cannot be written.
	void writeCsv(const std::string& path) const;
	/// {"notes": {...}, "rows": [...]}; notes are key -> text.
	void writeJson(const std::string& path, const std::vector<std::pair<std::string, std::string>>& notes) const;

private:
	struct Field
	{
		std::string key, value;
		bool text;
	};
	std::vector<std::vector<Field>> m_rows;
};
}  // namespace sweep
