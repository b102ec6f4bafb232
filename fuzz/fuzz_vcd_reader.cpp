// libFuzzer harness: the VCD reader of `cncsim analyze` (metrics/vcd/vcd_reader.hpp). Only cnc::BadInput may leave
// it, and every edge log it returns is in time order.
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <string>

#include "common/bad_input.hpp"
#include "metrics/vcd/vcd_reader.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    std::istringstream in(std::string(reinterpret_cast<const char*>(data), size));
    try {
        const cnc::metrics::VcdContents vcd = cnc::metrics::read_vcd(in, "fuzz.vcd");
        for (const auto& [name, log] : vcd.signals) {
            bool level = log.initial;
            cnc::TimePs t_ps = 0;
            for (const cnc::Edge& e : log.edges) {
                if (e.t_ps < t_ps || e.level == level) {
                    std::fprintf(stderr, "invariant broken: edges of '%s' out of order or not alternating\n",
                                 name.c_str());
                    std::abort();
                }
                t_ps = e.t_ps;
                level = e.level;
            }
        }
    } catch (const cnc::BadInput&) {
    }
    return 0;
}
