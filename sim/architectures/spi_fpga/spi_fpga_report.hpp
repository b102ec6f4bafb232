// The spi-fpga section of the report: servo thread statistics (periods, wake-up latency, landing), the SPI link
// (frame bits, transfer time, share of the servo period), the FPGA's FIFO, and the warnings. With `detail` also
// the holds at rest points, the rate log (per servo period: wake-up time, trajectory time, mode, and per axis the
// commanded steps/s, the period word sent signed by its direction bit (0 = stop) and the count fed back: the
// velocity staircase) and the velocity log (per period: the commanded path speed, 0 while the host holds at a rest
// point).
#pragma once
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "common/warning.hpp"
#include "fpga/spi/spi_board.hpp"
#include "host/servo/servo_thread.hpp"
#include "spi/spi_master.hpp"

namespace cnc::sim {

struct SpiFpgaReport {
    nlohmann::json details;
    std::string text;
    std::vector<Warning> warnings;
};

SpiFpgaReport spi_fpga_report(const host::servo::ServoThread& host, const spi::SpiMaster& master,
                              const fpga::SpiBoard& fpga, TimePs t_job_end_ps, bool detail);

}  // namespace cnc::sim
