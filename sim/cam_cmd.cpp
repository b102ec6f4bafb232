#include "cam_cmd.hpp"

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <optional>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "architectures/catalog.hpp"
#include "common/bad_input.hpp"
#include "compare/spawn.hpp"
#include "output/output_file.hpp"
#include "scenario/scenario.hpp"

namespace cnc::sim {

namespace {

namespace fs = std::filesystem;

struct Ordered {
    cam::Order order;
    cam::CamOutput output;
    std::optional<double> job_time_s;  // on --arch
};

void print_one(const cam::Drawing& d, const Ordered& o, std::ostream& out) {
    const cam::RouteStats& st = o.output.stats;
    out << fmt::format(FMT_STRING("cam: {}, order {}\n"), d.file, cam::order_name(o.order));
    out << fmt::format(FMT_STRING("  entities read        {:>10d}\n"), d.entities_read);
    out << fmt::format(FMT_STRING("  lines and arcs       {:>10d}\n"), d.entities.size());
    for (const auto& [type, count] : d.unread) {
        out << fmt::format(FMT_STRING("  not read             {:>10d} {} (cam.skip_unread)\n"), count, type);
    }
    out << fmt::format(FMT_STRING("  routes (rapids)      {:>10d}\n"), st.routes);
    out << fmt::format(FMT_STRING("  laser on/off cycles  {:>10d}\n"), st.routes);
    out << fmt::format(FMT_STRING("  cutting moves        {:>10d}\n"), st.moves);
    out << fmt::format(FMT_STRING("  rapid length [mm]    {:>10.3f}\n"), st.rapid_mm);
    out << fmt::format(FMT_STRING("  cutting length [mm]  {:>10.3f}\n"), st.cut_mm);
}

void print_table(const cam::Drawing& d, const std::vector<Ordered>& rows, const std::string& arch, std::ostream& out) {
    out << fmt::format(FMT_STRING("cam: {}: {} entities read, {} lines and arcs\n"), d.file, d.entities_read,
                       d.entities.size());
    out << fmt::format(FMT_STRING("{:<10} {:>7} {:>6} {:>9} {:>13} {:>15}"), "order", "routes", "moves", "commands",
                       "rapid [mm]", "cutting [mm]");
    if (!arch.empty()) out << fmt::format(FMT_STRING(" {:>14}"), "job time [s]");
    out << "\n";
    for (const Ordered& o : rows) {
        const cam::RouteStats& st = o.output.stats;
        out << fmt::format(FMT_STRING("{:<10} {:>7d} {:>6d} {:>9d} {:>13.3f} {:>15.3f}"), cam::order_name(o.order),
                           st.routes, st.moves, st.commands(), st.rapid_mm, st.cut_mm);
        if (!arch.empty()) out << (o.job_time_s ? fmt::format(FMT_STRING(" {:>14.4f}"), *o.job_time_s) : " failed");
        out << "\n";
    }
    if (!arch.empty()) out << "job time: each ordering's G-code run on " << arch << " (`cncsim run`)\n";
}

// The job time of `gcode` on the architecture: a `cncsim run` of its own (SystemC elaborates once per process).
std::optional<double> job_time(const std::string& self, const CamCommand& c, const std::string& gcode,
                               const std::string& name) {
    const fs::path dir = fs::temp_directory_path();
    const std::string stem = "cncsim-cam-" + std::to_string(getpid()) + "-" + name;
    const std::string job = (dir / (stem + ".nc")).string(), report = (dir / (stem + ".json")).string();
    std::ofstream(job) << gcode;
    std::vector<std::string> args = {self, "run", job, "--arch", c.arch, "--report", report, "--progress", "off"};
    if (!c.machine.empty()) args.insert(args.end(), {"--machine", c.machine});
    for (const std::string& s : c.sets) {
        if (s.rfind("cam.", 0) != 0) args.insert(args.end(), {"--set", s});
    }
    std::optional<double> t;
    if (run_child(args) == 0) {
        std::ifstream in(report);
        const nlohmann::json j = nlohmann::json::parse(in, nullptr, false);
        const nlohmann::json::json_pointer p("/metrics/job/job_time_s");
        if (!j.is_discarded() && j.contains(p)) t = j[p].get<double>();
    }
    std::error_code ec;
    fs::remove(job, ec);
    fs::remove(report, ec);
    return t;
}

}  // namespace

int cmd_cam(const CamCommand& c, const std::string& self, std::ostream& out) {
    std::vector<std::string> sets = c.sets;
    // The scenario gives the machine and the cam.* keys; --order and --skip-unread go first, so that a --set of
    // their keys still wins.
    if (c.skip_unread) sets.insert(sets.begin(), "cam.skip_unread=true");
    if (!c.order.empty()) {
        (void)cam::parse_order(c.order);
        sets.insert(sets.begin(), "cam.order=" + c.order);
    }
    if (!c.arch.empty()) {
        if (!c.compare_orders) throw BadInput("--arch " + c.arch, "goes with --compare-orders");
        if (!find_architecture(c.arch, "--arch " + c.arch).job_use().runs_job) {
            throw BadInput("--arch " + c.arch, c.arch + " runs no job");
        }
    }
    if (!c.out.empty()) check_output_path(c.out, "--out");
    const Scenario s = load_job_run({c.drawing, c.machine, c.arch}, sets);
    const cam::CamOptions& options = s.cam.options;
    const cam::Drawing drawing = cam::load_drawing(c.drawing, options, s.machine);

    std::vector<Ordered> rows;
    for (std::size_t i = 0; i < cam::order_names().size(); ++i) {
        const auto order = static_cast<cam::Order>(i);
        if (c.compare_orders || order == options.order) {
            rows.push_back({order, cam::cam_output(drawing, order, options), {}});
        }
    }
    if (!c.out.empty()) {
        for (const Ordered& o : rows) {
            if (o.order == options.order) write_output_file(c.out, "--out", o.output.gcode);
        }
    }
    if (!c.compare_orders) {
        print_one(drawing, rows.front(), out);
        return 0;
    }
    bool all_ran = true;
    if (!c.arch.empty()) {
        for (Ordered& o : rows) {
            o.job_time_s = job_time(self, c, o.output.gcode, cam::order_name(o.order));
            all_ran = all_ran && o.job_time_s.has_value();
        }
    }
    print_table(drawing, rows, c.arch, out);
    return all_ran ? 0 : 1;
}

}  // namespace cnc::sim
