#include "sweep/sweep_file.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <set>
#include <stdexcept>

#include <fmt/format.h>
#include <toml++/toml.h>

#include "common/bad_input.hpp"
#include "scenario/key_reader.hpp"
#include "scenario/scenario.hpp"

namespace cnc::sim {

namespace {

namespace fs = std::filesystem;

// More points than this from one range is a mistake in its step, not a study.
constexpr std::size_t kMaxRangeValues = 100000;
constexpr double kRangeSlack = 1e-9;  // of the step: where a range's last value may overshoot `to` by rounding

std::string trimmed(const std::string& s) {
    const auto b = s.find_first_not_of(" \t");
    return b == std::string::npos ? "" : s.substr(b, s.find_last_not_of(" \t") - b + 1);
}

int line_of(const toml::node& n) {
    return static_cast<int>(n.source().begin.line);
}

// Reads one table of the sweep file, naming each key by its dotted path and line in messages.
class Table {
public:
    Table(const SweepSpec& spec, const toml::table& t, std::string path)
        : m_spec(spec), m_t(t), m_path(std::move(path)) {}

    [[noreturn]] void fail(const toml::node* n, const std::string& key, const std::string& what) const {
        const int line = n != nullptr ? line_of(*n) : line_of(m_t);
        throw BadInput(m_spec.where(line, name(key)), what);
    }
    [[nodiscard]] std::string name(const std::string& key) const { return m_path.empty() ? key : m_path + "." + key; }
    [[nodiscard]] const toml::node* get(const std::string& key) const { return m_t.get(key); }
    [[nodiscard]] int line(const std::string& key) const {
        const toml::node* n = get(key);
        return n != nullptr ? line_of(*n) : line_of(m_t);
    }

    void only(const std::set<std::string>& allowed) const {
        for (auto&& [k, v] : m_t) {
            if (allowed.count(std::string(k.str())) != 0) continue;
            std::string list;
            for (const std::string& a : allowed) list += (list.empty() ? "" : ", ") + a;
            fail(&v, std::string(k.str()), "unknown key; allowed here: " + list);
        }
    }

    [[nodiscard]] std::string string(const std::string& key) const {
        const toml::node* n = get(key);
        if (n == nullptr) return "";
        if (!n->is_string()) fail(n, key, "expected a string");
        return n->as_string()->get();
    }
    [[nodiscard]] double number(const std::string& key) const {
        const toml::node* n = get(key);
        if (n == nullptr) fail(nullptr, key, "missing");
        if (!n->is_number()) fail(n, key, "expected a number");
        const double v = n->value<double>().value_or(0.0);
        if (!std::isfinite(v)) fail(n, key, "expected a finite number");
        return v;
    }
    [[nodiscard]] const toml::array* array(const std::string& key, bool non_empty) const {
        const toml::node* n = get(key);
        if (n == nullptr) return nullptr;
        if (!n->is_array()) fail(n, key, "expected an array");
        if (non_empty && n->as_array()->empty()) fail(n, key, "an empty list: give at least one value");
        return n->as_array();
    }
    [[nodiscard]] std::vector<std::string> strings(const std::string& key) const {
        std::vector<std::string> out;
        const toml::array* a = array(key, true);
        if (a == nullptr) return out;
        for (const toml::node& e : *a) {
            if (!e.is_string()) fail(&e, key, "expected a list of strings");
            out.push_back(e.as_string()->get());
        }
        return out;
    }
    [[nodiscard]] std::vector<SweepSet> sets(const std::string& key) const {
        std::vector<SweepSet> out;
        const toml::array* a = array(key, true);
        if (a == nullptr) return out;
        for (const toml::node& e : *a) {
            if (!e.is_string()) fail(&e, key, "expected a list of \"key=value\" strings");
            const std::string text = e.as_string()->get();
            const auto eq = text.find('=');
            if (eq == std::string::npos || eq == 0) fail(&e, key, "\"" + text + "\" is not key=value");
            // "key = value" as TOML writes it: the child's --set takes "key=value".
            const std::string key = trimmed(text.substr(0, eq));
            out.push_back({key + "=" + trimmed(text.substr(eq + 1)), key, line_of(e)});
        }
        return out;
    }

private:
    const SweepSpec& m_spec;
    const toml::table& m_t;
    std::string m_path;
};

SweepValue value_of(const toml::node& n) {
    SweepValue v;
    if (n.is_number()) {
        v.numeric = true;
        v.number = n.value<double>().value_or(0.0);
        v.toml = n.is_integer() ? std::to_string(n.as_integer()->get()) : number_text(v.number);
        v.shown = v.toml;
    } else if (n.is_string()) {
        v.shown = n.as_string()->get();
        v.toml = "\"";
        for (const char c : v.shown) v.toml += c == '"' || c == '\\' ? std::string("\\") + c : std::string(1, c);
        v.toml += '"';
    } else if (n.is_boolean()) {
        v.toml = v.shown = n.as_boolean()->get() ? "true" : "false";
    }
    return v;
}

SweepAxis read_axis(const SweepSpec& spec, const toml::table& t, const std::string& path) {
    const Table r(spec, t, path);
    r.only({"key", "values", "from", "to", "step", "count", "scale"});
    SweepAxis axis{r.string("key"), line_of(t), {}};
    if (axis.key.empty()) r.fail(nullptr, "key", "missing: the scenario key to vary (cncsim keys lists them)");
    const toml::array* values = r.array("values", true);
    const bool range = r.get("from") != nullptr || r.get("to") != nullptr;
    if ((values != nullptr) == range) {
        r.fail(nullptr, "values",
               axis.key +
                   ": give either values = [...] or a range (from, to and step, or from, to, "
                   "count and scale = \"log\")");
    }
    if (values != nullptr) {
        for (const char* k : {"step", "count", "scale"}) {
            if (r.get(k) != nullptr) r.fail(r.get(k), k, axis.key + ": goes with a range (from, to), not values");
        }
        for (const toml::node& e : *values) {
            if (!e.is_number() && !e.is_string() && !e.is_boolean())
                r.fail(&e, "values", axis.key + ": a value is a number, a string or a boolean");
            axis.values.push_back(value_of(e));
        }
        return axis;
    }
    const double from = r.number("from");
    const double to = r.number("to");
    const std::string scale = r.get("scale") != nullptr ? r.string("scale") : "linear";
    if (scale != "linear" && scale != "log") r.fail(r.get("scale"), "scale", "\"" + scale + "\": linear | log");
    std::vector<double> numbers;
    try {
        if (scale == "log") {
            if (r.get("step") != nullptr) r.fail(r.get("step"), "step", axis.key + ": a log range takes count");
            const toml::node* count = r.get("count");
            if (count == nullptr || !count->is_integer()) r.fail(count, "count", axis.key + ": an integer >= 2");
            numbers = log_range(from, to, count->as_integer()->get());
        } else {
            if (r.get("count") != nullptr) r.fail(r.get("count"), "count", axis.key + ": a linear range takes step");
            numbers = linear_range(from, to, r.number("step"));
        }
    } catch (const std::invalid_argument& e) {
        r.fail(r.get(scale == "log" ? "count" : "step"), scale == "log" ? "count" : "step", axis.key + ": " + e.what());
    }
    for (const double x : numbers) axis.values.push_back({number_text(x), number_text(x), true, x});
    return axis;
}

SweepStudy read_study(const SweepSpec& spec, const toml::table& t, const std::string& path, std::string name) {
    const Table r(spec, t, path);
    SweepStudy study{std::move(name), line_of(t), false, r.sets("set"), {}};
    const std::string mode = r.get("mode") != nullptr ? r.string("mode") : "grid";
    if (mode != "grid" && mode != "zip") r.fail(r.get("mode"), "mode", "\"" + mode + "\": grid | zip");
    study.zip = mode == "zip";
    // No vary: the one point of each architecture, over the seeds.
    const toml::array* vary = r.array("vary", true);
    std::set<std::string> keys;
    for (std::size_t i = 0; vary != nullptr && i < vary->size(); ++i) {
        const toml::node& e = *vary->get(i);
        if (!e.is_table()) r.fail(&e, "vary", "expected a list of tables { key = ..., values = [...] }");
        study.axes.push_back(read_axis(spec, *e.as_table(), r.name("vary") + "[" + std::to_string(i) + "]"));
        if (!keys.insert(study.axes.back().key).second)
            r.fail(&e, "vary", study.axes.back().key + " is varied twice in one study");
    }
    if (study.zip) {
        for (const SweepAxis& a : study.axes) {
            if (a.values.size() != study.axes.front().values.size()) {
                throw BadInput(
                    spec.where(a.line, r.name("vary")),
                    fmt::format(FMT_STRING("mode = \"zip\" takes lists of one length: {} has {} values, "
                                           "{} has {}"),
                                study.axes.front().key, study.axes.front().values.size(), a.key, a.values.size()));
            }
        }
    }
    return study;
}

bool valid_name(const std::string& s) {
    if (s.empty()) return false;
    for (const char c : s) {
        if (!std::isalnum(static_cast<unsigned char>(c)) && c != '-' && c != '_' && c != '.') return false;
    }
    return true;
}

// [search]: its own study of `key` and `with` zipped, without values until the search adds them.
void read_search(SweepSpec& spec, const toml::table& t) {
    const Table r(spec, t, "search");
    r.only({"key", "with", "from", "to", "tolerance", "holds"});
    SweepSearch search{line_of(t), r.number("from"), r.number("to"), r.number("tolerance"), {}};
    if (search.tolerance <= 0.0) r.fail(r.get("tolerance"), "tolerance", "must be > 0");
    if (search.to <= search.from) r.fail(r.get("to"), "to", "must be above from");
    SweepStudy study{"search", line_of(t), true, {}, {}};
    const std::string key = r.string("key");
    if (key.empty()) r.fail(r.get("key"), "key", "missing: the scenario key whose largest value is searched");
    study.axes.push_back({key, r.line("key"), {}});
    for (const std::string& k : r.strings("with")) study.axes.push_back({k, r.line("with"), {}});
    const toml::array* holds = r.array("holds", true);
    if (holds == nullptr) r.fail(nullptr, "holds", "missing: [{ metric = \"/...\", max = ... }, ...]");
    for (std::size_t i = 0; i < holds->size(); ++i) {
        const toml::node& e = *holds->get(i);
        if (!e.is_table()) r.fail(&e, "holds", "expected a list of tables { metric = \"/...\", max = ..., min = ... }");
        const Table c(spec, *e.as_table(), "search.holds[" + std::to_string(i) + "]");
        c.only({"metric", "max", "min"});
        SweepCondition cond{{c.string("metric"), line_of(e)}, {}, {}};
        if (cond.metric.pointer.empty() || cond.metric.pointer.front() != '/')
            c.fail(c.get("metric"), "metric", "a JSON pointer into the report, \"/metrics/path/following_max_um\"");
        if (c.get("max") != nullptr) cond.max = c.number("max");
        if (c.get("min") != nullptr) cond.min = c.number("min");
        if (!cond.max && !cond.min) c.fail(nullptr, "max", "give max, min or both: what the metric must stay within");
        search.holds.push_back(cond);
        // Collected too, in results.csv and the summary.
        const auto same = [&](const SweepMetric& m) { return m.pointer == cond.metric.pointer; };
        if (std::none_of(spec.metrics.begin(), spec.metrics.end(), same)) spec.metrics.push_back(cond.metric);
    }
    spec.studies.push_back(std::move(study));
    spec.search = std::move(search);
}

}  // namespace

std::string SweepSpec::where(int line, const std::string& what) const {
    return file + ":" + std::to_string(line) + ": " + what;
}

std::string number_text(double v) {
    return fmt::format(FMT_STRING("{}"), v);
}

namespace {

double rounded(double v) {
    return std::stod(fmt::format(FMT_STRING("{:.12g}"), v));
}

}  // namespace

std::vector<double> linear_range(double from, double to, double step) {
    if (step == 0.0) throw std::invalid_argument("step 0 never reaches the end of the range");
    if ((to - from) * step < 0.0) {
        throw std::invalid_argument(fmt::format(FMT_STRING("step {} goes away from {} to {}"), number_text(step),
                                                number_text(from), number_text(to)));
    }
    const double n = std::floor((to - from) / step + kRangeSlack);
    if (n + 1 > static_cast<double>(kMaxRangeValues))
        throw std::invalid_argument(fmt::format(FMT_STRING("more than {} values"), kMaxRangeValues));
    std::vector<double> out;
    for (std::size_t i = 0; i <= static_cast<std::size_t>(n); ++i) out.push_back(rounded(from + step * i));
    return out;
}

std::vector<double> log_range(double from, double to, std::int64_t count) {
    if (count < 2 || static_cast<std::size_t>(count) > kMaxRangeValues)
        throw std::invalid_argument(fmt::format(FMT_STRING("count {}: 2 .. {}"), count, kMaxRangeValues));
    if (!(from > 0.0 && to > 0.0)) {
        throw std::invalid_argument(fmt::format(FMT_STRING("a log range runs between two values > 0, not {} and {}"),
                                                number_text(from), number_text(to)));
    }
    std::vector<double> out;
    for (std::int64_t i = 0; i < count; ++i) {
        out.push_back(rounded(from * std::pow(to / from, static_cast<double>(i) / static_cast<double>(count - 1))));
    }
    return out;
}

SweepSpec read_sweep_file(const std::string& path) {
    SweepSpec spec;
    spec.file = path;
    const toml::table root = parse_toml(path, "sweep file");
    const fs::path base = fs::path(path).parent_path();
    const Table r(spec, root, "");
    r.only(
        {"scenario", "job", "machine", "architectures", "seeds", "set", "metrics", "vary", "mode", "study", "search"});
    const std::string scenario = r.string("scenario");
    const std::string job = r.string("job");
    if (scenario.empty() == job.empty())
        r.fail(nullptr, "scenario", "give either scenario = \"FILE.toml\" or job = \"FILE.nc\" (paths relative to it)");
    spec.job = !job.empty();
    spec.input = (base / (spec.job ? job : scenario)).lexically_normal().string();
    spec.input_line = r.line(spec.job ? "job" : "scenario");
    if (const std::string machine = r.string("machine"); !machine.empty()) {
        if (!spec.job) r.fail(r.get("machine"), "machine", "goes with job = ...; a scenario names its own machine");
        spec.machine = (base / machine).lexically_normal().string();
    }
    spec.architectures = r.strings("architectures");
    spec.architectures_line = r.line("architectures");
    if (const toml::node* seeds = r.get("seeds")) {
        spec.seeds_line = line_of(*seeds);
        if (seeds->is_integer()) {
            const std::int64_t n = seeds->as_integer()->get();
            if (n < 1 || n > static_cast<std::int64_t>(kMaxRangeValues))
                r.fail(seeds, "seeds", fmt::format(FMT_STRING("{}: 1 .. {} (seeds 1 .. N)"), n, kMaxRangeValues));
            for (std::int64_t s = 1; s <= n; ++s) spec.seeds.push_back(s);
        } else {
            const toml::array* list = r.array("seeds", true);
            if (list == nullptr) r.fail(seeds, "seeds", "a count N (seeds 1 .. N) or a list of seeds");
            for (const toml::node& e : *list) {
                if (!e.is_integer() || e.as_integer()->get() < 0) r.fail(&e, "seeds", "a seed is an integer >= 0");
                spec.seeds.push_back(e.as_integer()->get());
            }
        }
    }
    spec.sets = r.sets("set");
    spec.metrics_line = r.line("metrics");
    const toml::array* metrics = r.array("metrics", true);
    if (metrics == nullptr && r.get("search") == nullptr)
        r.fail(nullptr, "metrics", "missing: the JSON pointers of the report to collect");
    for (std::size_t i = 0; metrics != nullptr && i < metrics->size(); ++i) {
        const toml::node& e = *metrics->get(i);
        if (!e.is_string() || e.as_string()->get().empty() || e.as_string()->get().front() != '/')
            r.fail(&e, "metrics", "a metric is a JSON pointer into the report, \"/metrics/path/following_max_um\"");
        spec.metrics.push_back({e.as_string()->get(), line_of(e)});
    }
    if (const toml::node* search = r.get("search")) {
        if (!search->is_table()) r.fail(search, "search", "expected a [search] table");
        for (const char* k : {"vary", "mode", "study", "seeds"}) {
            if (r.get(k) != nullptr)
                r.fail(r.get(k), k, "goes with a grid; a sweep file with [search] runs the search");
        }
        read_search(spec, *search->as_table());
        return spec;
    }
    const toml::array* studies = r.array("study", true);
    if (studies != nullptr && (r.get("vary") != nullptr || r.get("mode") != nullptr))
        r.fail(r.get("vary"), "vary", "with [[study]] tables each study has its own vary and mode");
    if (studies == nullptr) {
        // One study, the file's own: its `set` is the file's, already read for every point.
        spec.studies.push_back(read_study(spec, root, "", fs::path(path).stem().string()));
        spec.studies.back().sets.clear();
        return spec;
    }
    std::set<std::string> names;
    for (std::size_t i = 0; i < studies->size(); ++i) {
        const toml::node& e = *studies->get(i);
        const std::string at = "study[" + std::to_string(i) + "]";
        if (!e.is_table()) r.fail(&e, "study", "expected [[study]] tables");
        const Table t(spec, *e.as_table(), at);
        t.only({"name", "set", "vary", "mode"});
        const std::string name = t.string("name");
        if (!valid_name(name)) t.fail(t.get("name"), "name", "\"" + name + "\": letters, digits and - _ .");
        if (!names.insert(name).second) t.fail(t.get("name"), "name", "\"" + name + "\" is the name of two studies");
        spec.studies.push_back(read_study(spec, *e.as_table(), at, name));
    }
    return spec;
}

}  // namespace cnc::sim
