// Progress of a long simulation for the person waiting on it: nothing during the first second of wall time
// (most runs take less), then on a terminal one line rewritten in place, in a log one line per 10 % of the
// job's estimate (job_estimate.hpp) and one per doubling past it. Text only: it never touches the model.
#pragma once
#include <ostream>
#include <string>

namespace cnc::sim {

enum class ProgressStyle {
    Off,
    Terminal,  // stderr is a terminal: one line, redrawn with '\r'
    Log,       // stderr is a file or a pipe: whole lines only
};

class Progress {
public:
    // `label` names the run in every line (its architecture), so that the lines of several runs can share a stream.
    Progress(std::ostream& out, ProgressStyle style, double expected_s, std::string label = "");

    // Between simulation slices: simulated seconds so far, wall seconds since the simulation started.
    void update(double sim_s, double wall_s);
    // The simulation ended: ends the terminal's line, or logs the end, if anything was shown.
    void finish(double sim_s, double wall_s);

private:
    [[nodiscard]] std::string prefix() const;
    [[nodiscard]] std::string text(double sim_s, double wall_s) const;
    void show(const std::string& text);

    std::ostream& m_out;
    ProgressStyle m_style;
    double m_expected_s;
    std::string m_label;
    bool m_shown = false;
    double m_last_draw_wall_s = 0.0;
    std::size_t m_last_width = 0;
    double m_next_tenths = 1.0;  // Log: the share of the estimate, in tenths, that gets the next line (whole)
};

}  // namespace cnc::sim
