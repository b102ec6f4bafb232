#include "architectures/spi_fpga/spi_fpga_report.hpp"

#include <algorithm>
#include <cstdio>
#include <sstream>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "common/rounding.hpp"
#include "spi/core/spi_frame.hpp"
#include "spi/core/spi_timing.hpp"

namespace cnc::sim {

namespace {

using host::servo::AxisPeriod;
using host::servo::PeriodMode;
using host::servo::PeriodRecord;
using nlohmann::json;

constexpr const char* kAxisNames[] = {"x", "y"};
// Log values to the resolution they carry: times to the ns, rates to 1e-3 steps/s, speeds to 1e-6 mm/s.
double seconds_ns(TimePs t) {
    return rounded(ps_to_s(t), 1e9);
}

// The period word signed by the direction bit (0 = stopped), as the rate log and the text show it.
std::int64_t signed_period(const spi::AxisRate& w) {
    return w.forward ? static_cast<std::int64_t>(w.period_cycles) : -static_cast<std::int64_t>(w.period_cycles);
}

// Holds at rest points: from the first landing period to the period that found every axis landed.
struct Hold {
    std::size_t first = 0;    // log index of the first Land period
    std::size_t release = 0;  // log index of the period that saw every axis landed
    std::uint64_t pulses = 0;
};

std::vector<Hold> holds(const std::vector<PeriodRecord>& log) {
    std::vector<Hold> out;
    for (std::size_t i = 0; i < log.size(); ++i) {
        if (log[i].mode != PeriodMode::Land) continue;
        if (out.empty() || out.back().release != i) out.push_back({i, i, 0});
        for (const AxisPeriod& a : log[i].axes) out.back().pulses += a.word.period_cycles != 0 ? 1 : 0;
        out.back().release = i + 1;
    }
    return out;
}

json holds_json(const std::vector<PeriodRecord>& log, const std::vector<host::servo::Wakeup>& wakeups) {
    json out = json::array();
    for (const Hold& h : holds(log)) {
        const std::size_t rel = std::min(h.release, log.size() - 1);
        out.push_back({{"tau_s", log[h.first].tau_s},
                       {"t_first_s", ps_to_s(wakeups[h.first].t_ps)},
                       {"t_release_s", ps_to_s(wakeups[rel].t_ps)},
                       {"periods", h.release - h.first},
                       {"landing_pulses", h.pulses}});
    }
    return out;
}

json rate_log(const std::vector<PeriodRecord>& log, const std::vector<host::servo::Wakeup>& wakeups) {
    json t = json::array();
    json tau = json::array();
    json mode = json::array();
    json axes = json::object();
    for (const char* name : kAxisNames) {
        axes[name] = {
            {"commanded_steps_per_s", json::array()}, {"period_cycles", json::array()}, {"count", json::array()}};
    }
    for (std::size_t i = 0; i < log.size(); ++i) {
        t.push_back(seconds_ns(wakeups[i].t_ps));
        tau.push_back(rounded(log[i].tau_s, 1e9));
        mode.push_back(to_string(log[i].mode));
        for (std::size_t a = 0; a < host::servo::kAxes; ++a) {
            const AxisPeriod& ap = log[i].axes[a];
            json& j = axes[kAxisNames[a]];
            j["commanded_steps_per_s"].push_back(rounded(ap.requested_steps_per_s, 1e3));
            j["period_cycles"].push_back(signed_period(ap.word));
            j["count"].push_back(ap.count);
        }
    }
    return {{"t_s", t}, {"tau_s", tau}, {"mode", mode}, {"axes", axes}};
}

json velocity_log(const std::vector<PeriodRecord>& log, const std::vector<host::servo::Wakeup>& wakeups) {
    json t = json::array();
    json v = json::array();
    for (std::size_t i = 0; i < log.size(); ++i) {
        t.push_back(seconds_ns(wakeups[i].t_ps));
        v.push_back(rounded(log[i].path_speed_mm_per_s, 1e6));
    }
    return {{"t_s", t}, {"path_speed_mm_per_s", v}};
}

// The first periods with a running word: the start of the staircase.
std::string staircase_text(const host::servo::ServoSummary& summary) {
    std::ostringstream os;
    os << "  rate log from the first running word (t; x, y: steps/s -> period word in clocks, signed by DIR):\n";
    for (const host::servo::StaircaseRow& row : summary.staircase()) {
        os << fmt::format(FMT_STRING("    {:>9.6f} s"), ps_to_s(row.t_ps));
        for (std::size_t a = 0; a < host::servo::kAxes; ++a) {
            os << fmt::format(FMT_STRING("  {:>+10.1f} -> {:>+11}"), row.requested_steps_per_s[a],
                              signed_period(row.word[a]));
        }
        os << '\n';
    }
    return os.str();
}

}  // namespace

SpiFpgaReport spi_fpga_report(const host::servo::ServoThread& host, const spi::SpiMaster& master,
                              const fpga::SpiBoard& fpga, TimePs t_job_end_ps, bool detail) {
    const host::servo::ServoCore& core = host.core();
    const host::servo::ServoConfig& cfg = core.config();
    const host::servo::ServoStats& st = core.stats();
    const spi::SpiConfig& link = master.config();
    const fpga::SpiFpgaConfig& fcfg = fpga.config();
    const std::size_t bits = spi::frame_bits(host::servo::kAxes);
    const TimePs transfer = spi::transfer_time_ps(link, bits);
    const TimePs slot = spi::transfer_slot_ps(link, bits);
    const host::servo::ServoSummary& sum = host.summary();
    const double latency_min_us = ps_to_us(sum.latency_min_ps());
    const double latency_mean_us = sum.latency_mean_ps() / static_cast<double>(kPsPerUs);
    const double latency_max_us = ps_to_us(sum.latency_max_ps());
    const fpga::SpiFpgaStats fst = fpga.stats();
    const std::uint64_t rejected = fst.frames - fst.frames_accepted;
    const std::uint64_t drops = fst.fifo_drops;
    const std::uint64_t stretched = fst.stretched_words;
    const double job_s = ps_to_s(t_job_end_ps);
    const double busy_pct = t_job_end_ps > 0 ? 100.0 * ps_to_s(master.ss_low_total_ps()) / job_s : 0.0;
    const double share_pct = 100.0 * static_cast<double>(transfer) / static_cast<double>(cfg.period_ps);

    SpiFpgaReport out;
    out.details = {{"servo",
                    {{"period_us", ps_to_us(cfg.period_ps)},
                     {"periods", sum.periods()},
                     {"tracking_periods", sum.tracking_periods()},
                     {"landing_periods", sum.landing_periods()},
                     {"latency",
                      {{"distribution", to_string(cfg.latency.distribution)},
                       {"bound_us", ps_to_us(cfg.latency.max_ps)},
                       {"min_us", latency_min_us},
                       {"mean_us", latency_mean_us},
                       {"max_us", latency_max_us}}},
                     {"position_gain", cfg.position_gain},
                     {"deadband_steps", cfg.deadband_steps},
                     {"stepgen_margin", cfg.stepgen_margin},
                     {"landing_period_cycles", host::servo::landing_period_cycles(cfg)},
                     {"rest_points", st.rest_points},
                     {"rest_points_landed", st.rest_points_landed},
                     {"landing_pulses", st.landing_pulses},
                     {"finished", host.finished()},
                     {"t_done_s", host.t_done_ps() ? json(ps_to_s(*host.t_done_ps())) : json(nullptr)}}},
                   {"spi",
                    {{"sclk_hz", link.sclk_hz},
                     {"frame_bits", bits},
                     {"cs_setup_ns", ps_to_ns(link.cs_setup_ps)},
                     {"cs_hold_ns", ps_to_ns(link.cs_hold_ps)},
                     {"ss_idle_min_ns", ps_to_ns(link.ss_idle_min_ps)},
                     {"transfer_us", ps_to_us(transfer)},
                     {"slot_us", ps_to_us(slot)},
                     {"transfer_share_of_period_pct", share_pct},
                     {"transfers", master.transfer_count()},
                     {"link_busy_pct", busy_pct},
                     {"wires_traced", link.trace_wires}}},
                   {"fpga",
                    {{"clock_hz", fcfg.clk_hz},
                     {"rate_apply", fcfg.rate_apply == fpga::RateApply::AtNextPulse ? "at-next-pulse" : "immediately"},
                     {"fifo_depth", fcfg.fifo_depth},
                     {"frames", fst.frames},
                     {"frames_rejected", rejected},
                     {"fifo_max_level", fst.fifo_max_level},
                     {"fifo_drops", drops},
                     {"replies_with_drop_flag", st.replies_dropped_flag},
                     {"stretched_words", stretched},
                     {"words_applied", fst.words_applied},
                     {"final_counts", fst.counts}}}};
    if (detail) {  // one entry per servo period, or per rest point
        const std::vector<PeriodRecord>& log = core.log();
        out.details["servo"]["holds"] = holds_json(log, host.wakeups());
        out.details["rate_log"] = rate_log(log, host.wakeups());
        out.details["velocity_log"] = velocity_log(log, host.wakeups());
    }

    std::ostringstream text;
    text << "spi-fpga host, link and FPGA\n"
         << fmt::format(FMT_STRING("  servo: {:.0f} us period, {} periods ({} tracking, {} landing)\n"),
                        ps_to_us(cfg.period_ps), sum.periods(), sum.tracking_periods(), sum.landing_periods())
         << fmt::format(FMT_STRING("  wake-up latency {} <= {:.1f} us: min {:.3f}, mean {:.3f}, max {:.3f} us\n"),
                        to_string(cfg.latency.distribution), ps_to_us(cfg.latency.max_ps), latency_min_us,
                        latency_mean_us, latency_max_us)
         << fmt::format(FMT_STRING("  landing: {} of {} rest points, {} landing pulses"), st.rest_points_landed,
                        st.rest_points, st.landing_pulses);
    if (host.t_done_ps()) text << fmt::format(FMT_STRING(", job done at {:.6f} s"), ps_to_s(*host.t_done_ps()));
    text << '\n'
         << fmt::format(FMT_STRING("  SPI: {}-bit frames at {} Hz: {:.3f} us with SS low ({:.3f} us slot), {:.3f} % of "
                                   "the servo period; link busy {:.3f} %\n"),
                        bits, link.sclk_hz, ps_to_us(transfer), ps_to_us(slot), share_pct, busy_pct)
         << fmt::format(
                FMT_STRING("  FPGA: rate_apply {}, FIFO depth {}: max level {}, {} frames dropped, {} rejected, "
                           "{} stretched words\n"),
                out.details["fpga"]["rate_apply"].get<std::string>(), fcfg.fifo_depth, fst.fifo_max_level,
                drops, rejected, stretched)
         << staircase_text(sum);
    out.text = text.str();

    if (drops > 0) {
        out.warnings.push_back({"fifo_drops", "",
                                std::to_string(drops) +
                                    " rate frames dropped by the full FIFO: with rate_apply = at-next-pulse a "
                                    "generator reads one frame per STEP, so frames queue while an axis steps slower "
                                    "than once per servo period, and the axis runs on stale rates"});
    }
    if (rejected > 0) {
        out.warnings.push_back({"frames_rejected", "", std::to_string(rejected) + " SPI frames rejected by the FPGA"});
    }
    if (stretched > 0) {
        out.warnings.push_back(
            {"words_stretched", "", std::to_string(stretched) + " rate words stretched to the minimum period"});
    }
    return out;
}

}  // namespace cnc::sim
