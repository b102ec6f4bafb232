#include "compare/html_report.hpp"

#include <algorithm>
#include <filesystem>
#include <map>
#include <optional>
#include <sstream>

#include <nlohmann/json.hpp>

namespace cnc::sim {

namespace {

std::string escape(const std::string& s) {
    std::string out;
    for (const char c : s) {
        switch (c) {
            case '&':
                out += "&amp;";
                break;
            case '<':
                out += "&lt;";
                break;
            case '>':
                out += "&gt;";
                break;
            case '"':
                out += "&quot;";
                break;
            default:
                out += c;
        }
    }
    return out;
}

constexpr const char* kStyle =
    "body{font-family:sans-serif;max-width:1000px;margin:1em auto;padding:0 1em;color:#222}"
    "table{border-collapse:collapse}td,th{border:1px solid #ccc;padding:2px 8px}td.n{text-align:right}"
    "td.best{font-weight:bold;background:#eaf6ea}pre{background:#f6f6f6;padding:6px;overflow:auto;max-height:20em}"
    "img{max-width:100%;border:1px solid #ddd}.arch{border-bottom:4px solid}";

void table_html(std::ostream& os, const Comparison& comparison) {
    os << "<table>\n<tr><th>metric</th>";
    const std::vector<std::string> colours = column_colours(comparison.columns);
    for (std::size_t k = 0; k < comparison.columns.size(); ++k) {
        os << "<th class=\"arch\" style=\"border-bottom-color:" << colours[k] << "\">"
           << escape(comparison.columns[k].label()) << "</th>";
    }
    os << "</tr>\n";
    for (const TableRow& r : table_rows(comparison)) {
        os << "<tr><td>" << escape(r.label) << "</td>";
        for (std::size_t i = 0; i < r.cells.size(); ++i) {
            os << "<td class=\"n" << (r.best[i] ? " best" : "") << "\">" << escape(r.cells[i]) << "</td>";
        }
        os << "</tr>\n";
    }
    os << "</table>\n<p>Bold: the best value of the row (the smallest magnitude). A <code>-</code> is a figure the run "
          "does not have; a failed run shows none. "
       << escape(not_compared_note()) << "</p>\n";
    for (const std::string& n : zero_notes(comparison)) os << "<p>" << escape(n) << "</p>\n";
}

void warnings_html(std::ostream& os, const std::vector<CompareColumn>& columns) {
    const std::vector<std::string> colours = column_colours(columns);
    for (std::size_t k = 0; k < columns.size(); ++k) {
        const CompareColumn& c = columns[k];
        os << "<h3 class=\"arch\" style=\"border-bottom-color:" << colours[k] << "\">" << escape(c.label()) << ": "
           << escape(status(c)) << "</h3>\n";
        if (!c.report.is_null() && c.report.contains("failure")) {
            os << "<p><b>The run failed:</b> " << escape(c.report["failure"].get<std::string>()) << "</p>\n";
        } else if (c.exit_code != 0) {
            os << "<p><b>The run wrote no report</b> (exit code " << c.exit_code
               << "): its error is in the command's output.</p>\n";
        }
        const nlohmann::json warnings =
            c.report.is_null() ? nlohmann::json::array() : c.report.value("warnings", nlohmann::json::array());
        if (warnings.empty()) {
            os << "<p>No warnings.</p>\n";
            continue;
        }
        os << "<ul>\n";
        // The first places (the G-code lines, an axis and a time) before the first one's text, as the summary has.
        for (const nlohmann::json& w : warnings) {
            std::string places;
            for (const nlohmann::json& p : w.value("first", nlohmann::json::array())) {
                places += (places.empty() ? "" : ", ") + p.get<std::string>();
            }
            if (!places.empty() && w.value("count", std::size_t{0}) > w["first"].size()) places += ", ...";
            os << "<li>" << (places.empty() ? std::string() : escape(places) + ": ")
               << escape(w.value("message", std::string())) << " (" << w.value("count", 0) << " x, "
               << escape(w.value("kind", std::string())) << ")</li>\n";
        }
        os << "</ul>\n";
    }
}

// Which columns run with the scenario's own architecture and keys, and which with a variant's.
void columns_html(std::ostream& os, const std::vector<CompareColumn>& columns) {
    if (std::all_of(columns.begin(), columns.end(), [](const CompareColumn& c) { return c.variant.empty(); })) {
        os << "; every architecture runs it with only <code>scenario.architecture</code> changed.</p>\n";
        return;
    }
    os << "; each column runs it on its architecture with its variant's keys set after those:</p>\n<ul>\n";
    for (const CompareColumn& c : columns) {
        os << "<li><b>" << escape(c.label()) << "</b>:";
        for (const std::string& s : c.variant_sets) os << " <code>--set " << escape(s) << "</code>";
        os << (c.variant_sets.empty() ? " the scenario as it is" : "") << "</li>\n";
    }
    os << "</ul>\n";
}

}  // namespace

std::vector<std::string> column_colours(const std::vector<CompareColumn>& columns) {
    std::map<std::string, std::size_t> per_arch;
    for (const CompareColumn& c : columns) ++per_arch[c.architecture];
    std::map<std::string, std::size_t> seen;
    std::vector<std::string> out;
    for (const CompareColumn& c : columns) {
        out.push_back(variant_colour(arch_colour(c.architecture), seen[c.architecture]++, per_arch[c.architecture]));
    }
    return out;
}

std::string html_report(const Comparison& comparison, const std::vector<Plot>& plots, const HtmlJob& job) {
    const std::vector<CompareColumn>& columns = comparison.columns;
    std::ostringstream os;
    os << "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<title>cncsim compare: "
       << escape(job.scenario_file) << "</title>\n<style>" << kStyle << "</style>\n</head>\n<body>\n"
       << "<h1>cncsim compare: " << escape(std::filesystem::path(job.scenario_file).filename().string())
       << "</h1>\n<h2>Machine and job</h2>\n"
       << "<p>Scenario <code>" << escape(job.scenario_file) << "</code>";
    for (const std::string& o : job.overrides) os << ", <code>--set " << escape(o) << "</code>";
    columns_html(os, columns);
    os << "<pre>" << escape(job.scenario_text) << "</pre>\n<p>Job <code>" << escape(job.job_file) << "</code>, "
       << job.job_lines << " lines:</p>\n<pre>" << escape(job.job_text) << "</pre>\n<h2>Comparison</h2>\n";
    table_html(os, comparison);
    os << "<p>The same table: <a href=\"table.md\">table.md</a>, <a href=\"table.csv\">table.csv</a>, "
          "<a href=\"table.json\">table.json</a>. Each column's report and trace:";
    for (const CompareColumn& c : columns) {
        const std::string stem = escape(c.file_stem());
        if (!c.report.is_null()) os << " <a href=\"" << stem << ".json\">" << stem << ".json</a>";
        if (c.exit_code != 2) {  // bad input: refused before a trace was opened
            os << " <a href=\"" << stem << ".vcd\">" << stem << ".vcd</a>";
        }
    }
    os << "</p>\n<h2>Plots</h2>\n";
    for (const Plot& p : plots) {
        os << "<h3>" << escape(p.title) << "</h3>\n<p><a href=\"" << p.name << ".svg\"><img src=\"" << p.name
           << ".svg\" alt=\"" << escape(p.title) << "\"></a><br><a href=\"" << p.name << ".png\">PNG</a></p>\n";
    }
    os << "<h2>Warnings</h2>\n";
    warnings_html(os, columns);
    os << "</body>\n</html>\n";
    return os.str();
}

}  // namespace cnc::sim
