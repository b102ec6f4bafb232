// A cell of a table the CLI writes, escaped for its format: CSV (RFC 4180 quoting) and Markdown.
#pragma once
#include <string>

namespace cnc::sim {

// Always in double quotes, a quote doubled.
std::string csv_quoted(const std::string& s);
// Quoted only when it holds a comma, a quote or a line break.
std::string csv_field(const std::string& s);
// A '|' escaped, which would end the cell.
std::string md_cell(const std::string& s);

}  // namespace cnc::sim
