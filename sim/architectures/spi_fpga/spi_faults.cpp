#include "architectures/spi_fpga/spi_faults.hpp"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

namespace cnc::sim {

void report_spi_faults(const FaultSettings& f, const spi::SpiMaster& master, const fpga::SpiFpgaStats& fpga,
                       ArchRun& run) {
    const spi::SpiMaster::FaultStats& st = master.fault_stats();
    const std::uint64_t refused = fpga.frames - fpga.frames_accepted;
    const std::uint64_t ran_changed = st.mosi_frames_hit - st.mosi_header_hit;
    run.details["faults"] = {{"seed", f.seed},
                             {"spi_ber", f.spi_ber},
                             {"commands_run_changed", ran_changed},
                             {"to_fpga",
                              {{"frames", master.transfer_count()},
                               {"frames_hit", st.mosi_frames_hit},
                               {"bits_inverted", st.mosi_bits_inverted},
                               {"command_byte_hit", st.mosi_header_hit},
                               {"refused_by_the_command_check", refused},
                               {"ran_changed", ran_changed}}},
                             {"from_fpga",
                              {{"frames", master.transfer_count()},
                               {"frames_hit", st.miso_frames_hit},
                               {"bits_inverted", st.miso_bits_inverted}}}};
    run.details_text += fmt::format(
        FMT_STRING("faults (seed {}): SPI BER {:g}\n  to the FPGA: {} of {} frames hit ({} bits inverted): {} refused "
                   "by its command check, {} run with changed words\n  from the FPGA: {} replies hit ({} bits)\n"),
        f.seed, f.spi_ber, st.mosi_frames_hit, master.transfer_count(), st.mosi_bits_inverted, refused, ran_changed,
        st.miso_frames_hit, st.miso_bits_inverted);
}

}  // namespace cnc::sim
