// Plain-text table with aligned columns: columns of numbers right-aligned, columns with any text
// left-aligned. Used by the summary that the CLI prints.
#pragma once
#include <optional>
#include <string>
#include <vector>

namespace cnc::metrics {

class TextTable {
public:
    explicit TextTable(std::vector<std::string> heads);
    void add_row(std::vector<std::string> cells);  // must have as many cells as there are heads
    // Title line, head row, a rule, the rows; each line ends with '\n'.
    [[nodiscard]] std::string render(const std::string& title) const;

private:
    std::vector<std::string> m_heads;
    std::vector<std::vector<std::string>> m_rows;
};

// Fixed-point text of a value, "-" when absent.
[[nodiscard]] std::string fixed(std::optional<double> v, int decimals);

}  // namespace cnc::metrics
