#include "sweep/sweep_results.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <fstream>
#include <map>
#include <sstream>

#include <fmt/format.h>

#include "common/bad_input.hpp"
#include "compare/compare.hpp"
#include "output/table_cells.hpp"
#include "plots/gnuplot_script.hpp"
#include "plots/plot_render.hpp"
#include "sweep/sweep_run.hpp"
#include "sweep/sweep_stats.hpp"

namespace cnc::sim {

namespace {

namespace fs = std::filesystem;

std::string status_of(int exit_code) {
    return exit_code == 0 ? "ok" : exit_code == 2 ? "bad input" : "failed";
}

// Every swept key once, in the order the studies name them: the columns of results.csv.
std::vector<std::string> swept_keys(const SweepSpec& spec) {
    std::vector<std::string> keys;
    for (const SweepStudy& s : spec.studies) {
        for (const SweepAxis& a : s.axes) {
            if (std::find(keys.begin(), keys.end(), a.key) == keys.end()) keys.push_back(a.key);
        }
    }
    return keys;
}

const SweepValue* value_of(const SweepSpec& spec, const SweepPoint& p, const std::string& key) {
    const SweepStudy& study = spec.studies[p.study];
    for (std::size_t a = 0; a < study.axes.size(); ++a) {
        if (study.axes[a].key == key) return &study.axes[a].values[p.value_index[a]];
    }
    return nullptr;
}

std::string figure_text(double v) {
    return fmt::format(FMT_STRING("{:.6g}"), v);
}

// The rows of one point of every seed: same study, architecture and values.
struct Group {
    const SweepPoint* first;
    std::vector<const SweepRow*> rows;
};

std::vector<Group> groups_of(const std::vector<SweepRow>& rows, std::size_t study) {
    std::vector<Group> out;
    for (const SweepRow& r : rows) {
        const SweepPoint& p = *r.point;
        if (p.study != study) continue;
        if (!out.empty() && out.back().first->architecture == p.architecture &&
            out.back().first->value_index == p.value_index) {
            out.back().rows.push_back(&r);
        } else {
            out.push_back({&p, {&r}});
        }
    }
    return out;
}

std::vector<double> ok_values(const Group& g, std::size_t metric) {
    std::vector<double> v;
    for (const SweepRow* r : g.rows) {
        if (r->record.exit_code == 0 && r->metrics[metric]) v.push_back(*r->metrics[metric]);
    }
    return v;
}

std::string slug(const std::string& s) {
    std::string out;
    for (const char c : s) {
        const bool keep = std::isalnum(static_cast<unsigned char>(c)) != 0;
        if (keep) out += c;
        if (!keep && !out.empty() && out.back() != '_') out += '_';
    }
    while (!out.empty() && out.back() == '_') out.pop_back();
    return out;
}

}  // namespace

nlohmann::json::json_pointer metric_pointer(const SweepMetric& metric, const std::string& architecture) {
    std::string p = metric.pointer;
    for (std::size_t at = p.find("{arch}"); at != std::string::npos; at = p.find("{arch}", at + architecture.size()))
        p.replace(at, 6, architecture);
    return nlohmann::json::json_pointer(p);
}

void check_metrics(const SweepSpec& spec, const nlohmann::json& report, const std::string& architecture,
                   const std::string& report_file) {
    for (const SweepMetric& m : spec.metrics) {
        const nlohmann::json::json_pointer ptr = metric_pointer(m, architecture);
        if (report.contains(ptr)) continue;
        nlohmann::json::json_pointer parent = ptr;
        while (!parent.empty() && !report.contains(parent)) parent = parent.parent_pointer();
        std::string keys;
        if (report.at(parent).is_object()) {
            for (const auto& [k, v] : report.at(parent).items()) keys += (keys.empty() ? "" : ", ") + k;
        }
        throw BadInput(spec.where(m.line, "metrics"),
                       "\"" + m.pointer + "\" is not in the report of " + architecture + " (" + report_file + "); " +
                           (parent.empty() ? std::string("the report") : "\"" + parent.to_string() + "\"") +
                           " holds: " + keys);
    }
}

std::vector<SweepRow> collect_rows(const SweepSpec& spec, const std::vector<SweepPoint>& points,
                                   const fs::path& out_dir) {
    std::vector<SweepRow> rows;
    std::vector<std::string> checked;  // the architectures whose first complete report the metrics were checked on
    for (const SweepPoint& p : points) {
        SweepRow row{&p, read_point_record(out_dir, p).value_or(PointRecord{}), {}};
        row.metrics.assign(spec.metrics.size(), std::nullopt);
        std::ifstream in(point_report(out_dir, p));
        const nlohmann::json report = in ? nlohmann::json::parse(in, nullptr, false) : nlohmann::json();
        if (row.record.exit_code == 0 && report.is_object()) {
            if (std::find(checked.begin(), checked.end(), p.architecture) == checked.end()) {
                check_metrics(spec, report, p.architecture, point_report(out_dir, p).string());
                checked.push_back(p.architecture);
            }
            for (std::size_t m = 0; m < spec.metrics.size(); ++m)
                row.metrics[m] = report_number(report, metric_pointer(spec.metrics[m], p.architecture));
        }
        rows.push_back(std::move(row));
    }
    return rows;
}

std::string results_csv(const SweepSpec& spec, const std::vector<SweepRow>& rows) {
    const std::vector<std::string> keys = swept_keys(spec);
    std::ostringstream os;
    os << "point,study,architecture";
    for (const std::string& k : keys) os << ',' << csv_field(k);
    os << ",seed,status,exit_code";
    for (const SweepMetric& m : spec.metrics) os << ',' << csv_field(m.pointer);
    os << ",message\n";
    for (const SweepRow& r : rows) {
        const SweepPoint& p = *r.point;
        os << p.id() << ',' << csv_field(spec.studies[p.study].name) << ',' << csv_field(p.architecture);
        for (const std::string& k : keys) {
            const SweepValue* v = value_of(spec, p, k);
            os << ',' << (v != nullptr ? csv_field(v->shown) : "");
        }
        os << ',' << (p.seed ? std::to_string(*p.seed) : "") << ',' << status_of(r.record.exit_code) << ','
           << r.record.exit_code;
        for (const std::optional<double>& v : r.metrics) os << ',' << (v ? number_text(*v) : "");
        os << ',' << csv_field(r.record.message) << '\n';
    }
    return os.str();
}

nlohmann::json results_json(const SweepSpec& spec, const std::vector<SweepRow>& rows) {
    nlohmann::json points = nlohmann::json::array();
    for (const SweepRow& r : rows) {
        const SweepPoint& p = *r.point;
        const SweepStudy& study = spec.studies[p.study];
        nlohmann::json values = nlohmann::json::object();
        for (std::size_t a = 0; a < study.axes.size(); ++a) {
            const SweepValue& v = study.axes[a].values[p.value_index[a]];
            values[study.axes[a].key] = v.numeric ? nlohmann::json(v.number) : nlohmann::json(v.shown);
        }
        nlohmann::json metrics = nlohmann::json::object();
        for (std::size_t m = 0; m < spec.metrics.size(); ++m)
            metrics[spec.metrics[m].pointer] = r.metrics[m] ? nlohmann::json(*r.metrics[m]) : nlohmann::json();
        points.push_back({{"point", p.id()},
                          {"study", study.name},
                          {"architecture", p.architecture},
                          {"values", values},
                          {"seed", p.seed ? nlohmann::json(*p.seed) : nlohmann::json()},
                          {"status", status_of(r.record.exit_code)},
                          {"exit_code", r.record.exit_code},
                          {"message", r.record.message},
                          {"sets", p.sets},
                          {"report", "points/" + p.id() + ".json"},
                          {"metrics", metrics}});
    }
    nlohmann::json metrics = nlohmann::json::array();
    for (const SweepMetric& m : spec.metrics) metrics.push_back(m.pointer);
    return {{"sweep", spec.file}, {"input", spec.input}, {"metrics", metrics}, {"points", points}};
}

std::string summary_md(const SweepSpec& spec, const std::vector<SweepRow>& rows) {
    const auto failed = std::count_if(rows.begin(), rows.end(), [](const SweepRow& r) { return r.record.exit_code; });
    std::ostringstream os;
    os << "# Sweep " << spec.file << "\n\n"
       << fmt::format(FMT_STRING("{} points of {}, {} failed (results.csv lists each point). Per metric, "
                                 "architecture and value: the mean, min and max over the seeds of the points that "
                                 "ran, and the 95 % confidence interval of the mean (Student's t; docs/sweeps.md)."),
                      rows.size(), spec.input, failed)
       << "\n";
    for (std::size_t s = 0; s < spec.studies.size(); ++s) {
        const SweepStudy& study = spec.studies[s];
        const std::vector<Group> groups = groups_of(rows, s);
        os << "\n## " << study.name << "\n";
        for (std::size_t m = 0; m < spec.metrics.size(); ++m) {
            os << "\n### " << md_cell(spec.metrics[m].pointer) << "\n\n| architecture |";
            for (const SweepAxis& a : study.axes) os << ' ' << md_cell(a.key) << " |";
            os << " seeds | mean | min | max | 95 % interval |\n|---|";
            for (std::size_t a = 0; a < study.axes.size(); ++a) os << "---|";
            os << "---|---|---|---|---|\n";
            for (const Group& g : groups) {
                os << "| " << g.first->architecture << " |";
                for (std::size_t a = 0; a < study.axes.size(); ++a)
                    os << ' ' << md_cell(study.axes[a].values[g.first->value_index[a]].shown) << " |";
                const std::vector<double> v = ok_values(g, m);
                const std::string n = v.size() == g.rows.size()
                                          ? std::to_string(v.size())
                                          : fmt::format(FMT_STRING("{} of {}"), v.size(), g.rows.size());
                if (v.empty()) {
                    os << ' ' << n << " | - | - | - | - |\n";
                    continue;
                }
                const SeedStats st = seed_stats(v);
                const std::string interval = st.n < 2 ? "-"
                                                      : figure_text(st.mean - st.half_width_95) + " .. " +
                                                            figure_text(st.mean + st.half_width_95);
                os << ' ' << n << " | " << figure_text(st.mean) << " | " << figure_text(st.min) << " | "
                   << figure_text(st.max) << " | " << interval << " |\n";
            }
        }
    }
    return os.str();
}

std::size_t write_sweep_plots(const SweepSpec& spec, const std::vector<SweepRow>& rows, const fs::path& out_dir) {
    const fs::path dir = out_dir / "plots";
    std::vector<gp::Script> scripts;
    fs::create_directories(dir / "data");
    for (std::size_t s = 0; s < spec.studies.size(); ++s) {
        const SweepStudy& study = spec.studies[s];
        if (study.axes.empty()) continue;
        const SweepAxis& x = study.axes.front();
        if (!std::all_of(x.values.begin(), x.values.end(), [](const SweepValue& v) { return v.numeric; })) continue;
        // A line per architecture and values of the other axes, its points in the order of x's values.
        std::map<std::string, std::vector<const Group*>> lines;
        std::vector<std::string> order;
        std::map<std::string, std::string> arch_of;
        const std::vector<Group> groups = groups_of(rows, s);
        for (const Group& g : groups) {
            std::string label = g.first->architecture;
            for (std::size_t a = 1; a < study.axes.size(); ++a)
                label += ", " + study.axes[a].key + " = " + study.axes[a].values[g.first->value_index[a]].shown;
            if (lines.count(label) == 0) order.push_back(label);
            lines[label].push_back(&g);
            arch_of[label] = g.first->architecture;
        }
        // A search tries its values out of order.
        for (auto& [label, line] : lines) {
            std::stable_sort(line.begin(), line.end(), [&](const Group* a, const Group* b) {
                return x.values[a->first->value_index[0]].number < x.values[b->first->value_index[0]].number;
            });
        }
        std::map<std::string, std::size_t> per_arch;
        for (const std::string& l : order) ++per_arch[arch_of[l]];
        double lo = 1e300;
        double hi = -1e300;
        for (const SweepValue& v : x.values) {
            lo = std::min(lo, v.number);
            hi = std::max(hi, v.number);
        }
        const bool log_x = lo > 0.0 && hi / lo >= 100.0;
        for (std::size_t m = 0; m < spec.metrics.size(); ++m) {
            const std::string name = slug(study.name + "_" + spec.metrics[m].pointer);
            const std::string data = "data/" + name + ".dat";
            std::ofstream out(dir / data);
            out << "# " << x.key << ", mean, 95 % interval low, high of " << spec.metrics[m].pointer
                << "; a block per line of the plot\n";
            std::vector<std::string> clauses;
            std::map<std::string, std::size_t> seen;
            std::size_t block = 0;
            gp::ColumnRange xs, ys;  // a constant x or y opens to +-1, not gnuplot's warning
            for (const std::string& l : order) {
                const std::string arch = arch_of[l];
                const std::string colour = variant_colour(arch_colour(arch), seen[arch]++, per_arch[arch]);
                std::size_t written = 0;
                for (const Group* g : lines[l]) {
                    const std::vector<double> v = ok_values(*g, m);
                    if (v.empty()) continue;
                    const SeedStats st = seed_stats(v);
                    const double at = x.values[g->first->value_index[0]].number;
                    xs = gp::merge(xs, {1, at, at});
                    ys = gp::merge(ys, {1, st.mean - st.half_width_95, st.mean + st.half_width_95});
                    out << number_text(at) << ' ' << number_text(st.mean) << ' '
                        << number_text(st.mean - st.half_width_95) << ' ' << number_text(st.mean + st.half_width_95)
                        << '\n';
                    ++written;
                }
                if (written == 0) continue;
                out << "\n\n";
                clauses.push_back(gp::quoted(data) + " index " + std::to_string(block++) +
                                  " using 1:2:3:4 with yerrorlines lw 1.5 pt 7 ps 0.6 lc rgb " + gp::quoted(colour) +
                                  " title " + gp::quoted(l));
            }
            if (clauses.empty()) continue;
            gp::Script script(Plot{name, spec.metrics[m].pointer + " against " + x.key + " (" + study.name + ")", x.key,
                                   spec.metrics[m].pointer});
            const std::string x_range =
                xs.lo == xs.hi ? fmt::format(FMT_STRING("set xrange [{:g}:{:g}]\n"), xs.lo - 1.0, xs.hi + 1.0) : "";
            script.body = gp::header(script.plot) + (log_x ? "set logscale x\n" : "") + x_range + gp::yrange_for(ys) +
                          gp::plot_line(clauses);
            scripts.push_back(std::move(script));
        }
    }
    if (scripts.empty()) return 0;
    return gp::render_scripts(scripts, dir).size();
}

}  // namespace cnc::sim
