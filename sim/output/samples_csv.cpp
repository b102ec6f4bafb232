#include "output/samples_csv.hpp"

#include <cinttypes>
#include <cstdio>

namespace cnc::sim {

void write_samples_csv(std::ostream& out, const std::vector<ToolSample>& samples) {
    out << kSamplesCsvHeader << '\n';
    char row[96];
    for (const ToolSample& s : samples) {
        // Seconds from the integer picoseconds (simulated time is never negative), digit for digit: a double would
        // round the 12th decimal of a long job.
        const int n = std::snprintf(row, sizeof row, "%" PRId64 ".%012" PRId64 ",%.9f,%.9f\n", s.t_ps / kPsPerSec,
                                    s.t_ps % kPsPerSec, s.pos.x_mm, s.pos.y_mm);
        out.write(row, n);
    }
}

}  // namespace cnc::sim
