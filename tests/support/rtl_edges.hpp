// The pin changes an Icarus testbench of our Verilog writes (tests/fpga/rtl/stream_tb.v, tests/spi/rtl/
// spi_stream_tb.v): "pin edge level" per line, edge n at n clock periods, the levels after reset as edge 0.
#pragma once
#include <cstdint>
#include <fstream>
#include <map>
#include <string>

#include "common/edge_log.hpp"
#include "common/units.hpp"

namespace cnc::test {

inline std::map<std::string, EdgeLog> read_rtl_edges(const std::string& path, TimePs clock_period_ps) {
    std::map<std::string, EdgeLog> logs;
    std::ifstream in(path);
    std::string pin;
    std::int64_t edge = 0;
    int level = 0;
    while (in >> pin >> edge >> level) {
        EdgeLog& log = logs[pin];
        log.name = pin;
        if (edge == 0) {
            log.initial = level != 0;
        } else {
            log.add(edge * clock_period_ps, level != 0);
        }
    }
    return logs;
}

}  // namespace cnc::test
