#include "metrics/report/text_table.hpp"

#include <algorithm>
#include <cstdio>
#include <stdexcept>

namespace cnc::metrics {

TextTable::TextTable(std::vector<std::string> heads) : m_heads(std::move(heads)) {}

void TextTable::add_row(std::vector<std::string> cells) {
    if (cells.size() != m_heads.size()) throw std::invalid_argument("table row has the wrong number of cells");
    m_rows.push_back(std::move(cells));
}

namespace {

bool numeric(const std::string& cell) {
    return !cell.empty() && cell.find_first_not_of("+-0123456789.e") == std::string::npos;
}

}  // namespace

std::string TextTable::render(const std::string& title) const {
    std::vector<std::size_t> width(m_heads.size());
    std::vector<bool> left(m_heads.size(), false);
    for (std::size_t c = 0; c < m_heads.size(); ++c) {
        width[c] = m_heads[c].size();
        for (const auto& row : m_rows) {
            width[c] = std::max(width[c], row[c].size());
            if (!numeric(row[c])) left[c] = true;
        }
    }
    const auto line = [&](const std::vector<std::string>& cells) {
        std::string out;
        for (std::size_t c = 0; c < cells.size(); ++c) {
            const std::string pad(width[c] - cells[c].size(), ' ');
            if (c > 0) out += "  ";
            out += left[c] ? cells[c] + pad : pad + cells[c];
        }
        while (!out.empty() && out.back() == ' ') out.pop_back();
        return out + '\n';
    };
    std::size_t total = 0;
    for (const std::size_t w : width) total += w;
    total += 2 * (width.size() - 1);
    std::string out = title + '\n' + line(m_heads) + std::string(total, '-') + '\n';
    for (const auto& row : m_rows) out += line(row);
    return out;
}

std::string fixed(std::optional<double> v, int decimals) {
    if (!v) return "-";
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.*f", decimals, *v);
    std::string s = buf;
    // A tiny negative value rounds to "-0.000"; print it as zero.
    if (s[0] == '-' && s.find_first_not_of("-0.") == std::string::npos) s.erase(0, 1);
    return s;
}

}  // namespace cnc::metrics
