#include "fpga/spi/core/spi_rtl_design.hpp"

#include <string>

#include "rtl/design_sources.hpp"

namespace cnc::fpga {

rtl::PluginSpec spi_rtl_plugin_spec(const SpiFpgaConfig& cfg, const rtl::Design& design) {
    rtl::PluginSpec spec;
    rtl::set_design(spec, design, "spi_fpga_top", CNC_FPGA_RTL_DIR,
                    {"spi_fpga_top.v", "spi_slave.v", "spi_cmd_fifo.v", "spi_pulse_gen.v", "spi_step_counter.v",
                     "spi_laser_latch.v"},
                    {{"FIFO_DEPTH", std::to_string(cfg.fifo_depth)},
                     {"PULSE_CYCLES", std::to_string(cfg.pulse_cycles)},
                     {"DIR_SETUP", std::to_string(cfg.dir_setup_cycles)},
                     {"DIR_HOLD", std::to_string(cfg.dir_hold_cycles)},
                     {"IMMEDIATE", cfg.rate_apply == RateApply::Immediately ? "1" : "0"}});
    spec.clock = "clk";
    spec.inputs = {{"rst_n", 1}, {"sclk", 1}, {"mosi", 1}, {"ss", 1}};
    spec.outputs = {{"miso", 1},   {"step_x", 1}, {"dir_x", 1},    {"n_enbl_x", 1},
                    {"step_y", 1}, {"dir_y", 1},  {"n_enbl_y", 1}, {"laser", 1}};
    const std::string& top = spec.top_module;
    spec.observed = {{"spi_slave", "spi_slave.ss_fell", "ss_fell"},
                     {"spi_slave", "spi_slave.ss_rose", "ss_rose"},
                     {"spi_slave", "spi_slave.accepted", "accepted"},
                     {"spi_slave", "spi_slave.fifo_full", "fifo_full"},
                     {top, "fifo_level", "fifo_level"},
                     {top, "rd_x", "rd_x"},
                     {top, "rd_y", "rd_y"},
                     {top, "fifo_dir_x", "fifo_dir_x"},
                     {top, "period_x", "period_x"},
                     {top, "fifo_dir_y", "fifo_dir_y"},
                     {top, "period_y", "period_y"},
                     {"spi_pulse_gen", "pulse_gen_x.period", "period"},
                     {"spi_pulse_gen", "pulse_gen_y.period", "period"},
                     {top, "count_x", "count_x"},
                     {top, "count_y", "count_y"},
                     {"spi_cmd_fifo", "cmd_fifo.rix", "rix"},
                     {"spi_cmd_fifo", "cmd_fifo.riy", "riy"},
                     {"spi_cmd_fifo", "cmd_fifo.avail_x", "avail_x"},
                     {"spi_cmd_fifo", "cmd_fifo.avail_y", "avail_y"},
                     {"spi_pulse_gen", "pulse_gen_x.running", "running"},
                     {"spi_pulse_gen", "pulse_gen_y.running", "running"},
                     {"spi_pulse_gen", "pulse_gen_x.dir_pend", "dir_pend"},
                     {"spi_pulse_gen", "pulse_gen_y.dir_pend", "dir_pend"}};
    return spec;
}

}  // namespace cnc::fpga
