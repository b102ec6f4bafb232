// SystemC tests of seed 004's Verilog in the loop (fpga/spi/rtl_spi_top.hpp) on its own: frames from the SPI
// master, with the master's promise, are counted and their words applied as the event model records them, each
// record seen once the simulation reaches its edge though the model runs ahead; an input
// that changes before the time promised is a logic error (the edges run ahead would have sampled the wrong level).
#include <gtest/gtest.h>

#include <functional>
#include <string>
#include <systemc>
#include <vector>

#include "fpga/spi/rtl_spi_top.hpp"
#include "spi_bench.hpp"

namespace cnc::spi::test {
namespace {

// The FPGA's pins on signals, and a host thread that runs `host` once.
class RtlBench : public sc_core::sc_module {
public:
    RtlBench(const sc_core::sc_module_name& name, std::function<void(RtlBench&)> host)
        : sc_module(name), master("master", wires()), fpga("fpga", fpga::SpiFpgaConfig{}, {}), m_host(std::move(host)) {
        master.sclk(sclk);
        master.mosi(mosi);
        master.ss(ss);
        master.miso(miso);
        fpga.sclk(sclk);
        fpga.mosi(mosi);
        fpga.ss(ss);
        fpga.miso(miso);
        fpga.step_x(step_x);
        fpga.dir_x(dir_x);
        fpga.step_y(step_y);
        fpga.dir_y(dir_y);
        fpga.laser(laser);
        SC_HAS_PROCESS(RtlBench);
        SC_THREAD(host_thread);
    }

    sc_core::sc_signal<bool> sclk{"sclk", false}, mosi{"mosi", false}, ss{"ss", true}, miso{"miso", false};
    sc_core::sc_signal<bool> step_x{"step_x", false}, dir_x{"dir_x", false}, step_y{"step_y", false};
    sc_core::sc_signal<bool> dir_y{"dir_y", false}, laser{"laser", false};
    SpiMaster master;
    fpga::RtlSpiTop fpga;

private:
    static SpiConfig wires() {
        SpiConfig c;
        c.trace_wires = true;
        return c;
    }
    void host_thread() { m_host(*this); }
    std::function<void(RtlBench&)> m_host;
};

TEST(RtlSpiTop, FramesCountedAndTheirWordsAppliedAsTheEventModelRecordsThem) {
    RtlBench bench("bench", [](RtlBench& b) {
        std::vector<std::uint8_t> reply;
        b.master.no_transfer_before(10 * kUs);
        sc_core::wait(sc_core::sc_time::from_value(10 * kUs));
        b.master.transfer(rates({500, true}, {0, false}), reply);
        b.master.no_transfer_before(60 * kUs);
        sc_core::wait(sc_core::sc_time::from_value(60 * kUs) - sc_core::sc_time_stamp());
        b.master.transfer(rates({0, true}, {0, false}), reply);
        b.master.no_transfer_before(100 * kUs);
    });
    bench.fpga.inputs_quiet_until([&bench] { return bench.master.pins_quiet_until(); });

    // README of models/fpga/spi: a transfer from 10 us ends at edge 1320, is written at 1323 and read at 1324; the
    // forward word raises DIR there and the first STEP 50 clocks of setup later (1374), then one every 500 clocks,
    // each counted an edge later. At 30 us the model has run ahead to the next transfer (60 us, edge 3000), but
    // what it records after 30 us is not seen yet.
    sc_core::sc_start(sc_core::sc_time::from_value(30 * kUs));
    EXPECT_GE(bench.fpga.cycles(), 3000);
    fpga::SpiFpgaStats st = bench.fpga.stats();
    EXPECT_EQ(st.frames, 1U);
    EXPECT_EQ(st.frames_accepted, 1U);
    EXPECT_EQ(st.fifo_max_level, 1U);
    EXPECT_EQ(st.counts[0], 1);
    const std::vector<fpga::AppliedRate> first = bench.fpga.take_applied(0);
    ASSERT_EQ(first.size(), 1U);
    EXPECT_EQ(first[0].edge, 1324);
    EXPECT_EQ(first[0].seq, 0U);
    EXPECT_EQ(first[0].rate, (AxisRate{500, true}));
    EXPECT_FALSE(first[0].stretched);

    // The stop frame (60 us to edge 3820, readable from 3824) is read where the running period ends, at 3874: the
    // rise due there is cancelled, 5 steps in all.
    sc_core::sc_start(sc_core::sc_time::from_value(70 * kUs));
    st = bench.fpga.stats();
    EXPECT_EQ(st.frames, 2U);
    EXPECT_EQ(st.fifo_drops, 0U);
    EXPECT_EQ(st.stretched_words, 0U);
    EXPECT_EQ(st.words_applied[0], 2U);
    EXPECT_EQ(st.counts[0], 5);
    const std::vector<fpga::AppliedRate> stop = bench.fpga.take_applied(0);
    ASSERT_EQ(stop.size(), 1U);
    EXPECT_EQ(stop[0].edge, 3874);
    EXPECT_EQ(stop[0].seq, 1U);
    EXPECT_EQ(stop[0].rate.period_cycles, 0U);
}

TEST(RtlSpiTop, StopWordsReadAtConsecutiveEdgesAreEachRecorded) {
    // A 100000-clock period holds X's next read until edge 101374; by then two stop frames wait, identical at the
    // read port: the first is read there, the second at the next edge, when X has stopped. Y (200000 clocks) has read
    // neither, so the FIFO's level stays as it is too.
    RtlBench bench("bench", [](RtlBench& b) {
        std::vector<std::uint8_t> reply;
        for (const TimePs t : {10 * kUs, 40 * kUs, 70 * kUs}) {
            b.master.no_transfer_before(t);
            sc_core::wait(sc_core::sc_time::from_value(t) - sc_core::sc_time_stamp());
            const bool first = t == 10 * kUs;
            b.master.transfer(rates({first ? 100'000U : 0U, true}, {first ? 200'000U : 0U, true}), reply);
        }
        b.master.no_transfer_before(2100 * kUs);
    });
    bench.fpga.inputs_quiet_until([&bench] { return bench.master.pins_quiet_until(); });
    sc_core::sc_start(sc_core::sc_time::from_value(2100 * kUs));

    const std::vector<fpga::AppliedRate> x = bench.fpga.take_applied(0);
    ASSERT_EQ(x.size(), 3U);
    EXPECT_EQ(x[1].edge, 101'374);
    EXPECT_EQ(x[2].edge, 101'375);
    EXPECT_EQ(x[1].seq, 1U);
    EXPECT_EQ(x[2].seq, 2U);
    EXPECT_EQ(bench.fpga.stats().counts[0], 1);  // the rise due at 101374 is cancelled by the stop
    EXPECT_EQ(bench.fpga.stats().words_applied[1], 1U);
}

TEST(RtlSpiTop, InputChangeBeforeThePromiseIsALogicError) {
    RtlBench bench("bench", [](RtlBench& b) {
        sc_core::wait(sc_core::sc_time::from_value(kUs));
        b.ss.write(false);  // promised quiet until 1 ms
    });
    bench.fpga.inputs_quiet_until([] { return kMs; });
    try {
        sc_core::sc_start(sc_core::sc_time::from_value(2 * kMs));
        FAIL() << "no error";
    } catch (const std::exception& e) {
        EXPECT_NE(std::string(e.what()).find("ss changed at 1000000 ps, before the 1000000000 ps promised"),
                  std::string::npos)
            << e.what();
    }
}

}  // namespace
}  // namespace cnc::spi::test
