// Our grbl-protocol test firmware on the ATmega328P model, streamed to by the grbl sender through the CP2102: the
// receive-buffer window read off the MCU's own USART log (not the sender's count), send-response's one line at a
// time, and an unsupported line answered with its error. (The square's steps: tests/grbl, through the architecture.)
#include <gtest/gtest.h>

#include <algorithm>
#include <iostream>
#include <string>
#include <vector>

#include "avr_test_support.hpp"
#include "host/core/grbl/grbl_lines.hpp"
#include "host/core/grbl/grbl_stream.hpp"
#include "host/grbl_sender.hpp"
#include "uart/cp2102.hpp"

namespace cnc::avr::test {
namespace {

using host::grbl::Protocol;
using host::grbl::SendLine;

// The settings of a machine at 160 steps/mm (1.8 deg, 1/32, GT2 20T), 50 mm/s, in laser mode.
std::vector<SendLine> machine_160_steps_per_mm() {
    std::vector<SendLine> out;
    for (const char* s : {"$32=1", "$100=160.000", "$101=160.000", "$110=3000.000", "$111=3000.000"}) {
        out.push_back({s, "test"});
    }
    return out;
}

struct GrblBench {
    GrblBench(std::vector<SendLine> job, Protocol protocol, bool strict, TimePs status_interval_ps)
        : bench(grbl_config()),
          cp("cp", uart::Cp2102Config{}),
          sender("sender", sender_config(status_interval_ps), cp,
                 host::grbl::Stream({protocol, 128, strict}, machine_160_steps_per_mm(), std::move(job))) {
        cp.txd(bench.rxd);
        cp.rxd(*bench.signals[kTxdLine]);
    }
    static AvrCoreConfig grbl_config() {
        AvrCoreConfig cfg = config_with_usart_logs(GRBL_PROTOCOL_ELF);
        cfg.pins = grbl_pin_map();
        cfg.quantum_cycles = 1600;
        return cfg;
    }
    static host::GrblSenderConfig sender_config(TimePs status_interval_ps) {
        host::GrblSenderConfig c;
        c.status_interval_ps = status_interval_ps;
        return c;
    }
    // Runs until the sender has finished or failed, at most `limit_ps`.
    void run(TimePs limit_ps) {
        while (now_ps() < limit_ps && !sender.finished() && !sender.failure()) {
            bench.run_until_ps(now_ps() + 50 * kPsPerMs);
        }
    }
    // STEP rising edges while the shared nENBL (PB0) is low: the pulses the DRV8825s take.
    [[nodiscard]] std::size_t driver_steps(const char* step) const {
        std::size_t n = 0;
        for (const TimePs t : bench.log(step).rising()) n += bench.log("en_x").level_at(t) ? 0 : 1;
        return n;
    }
    // The most line bytes the MCU had received and not yet answered, at any received byte: each answer ("ok",
    // "error:N") the MCU sends frees the bytes of the oldest line (the sender's lines, in order); '?' is real-time.
    [[nodiscard]] std::size_t max_unanswered_bytes() const {
        std::vector<std::size_t> line_bytes;
        for (const host::GrblLineRecord& r : sender.lines()) {
            if (r.written && r.text != "?") line_bytes.push_back(r.text.size() + 1);
        }
        std::vector<Cycle> answer_cycles;  // the start of each answer's first byte
        std::string text;
        Cycle first = 0;
        for (const UsartTxRecord& t : bench.avr.chip().usart().tx_log()) {
            if (text.empty()) first = t.start_cycle;
            if (t.byte != '\n') {
                if (t.byte != '\r') text.push_back(static_cast<char>(t.byte));
                continue;
            }
            if (text == "ok" || text.rfind("error:", 0) == 0) answer_cycles.push_back(first);
            text.clear();
        }
        std::size_t received = 0;
        std::size_t most = 0;
        for (const UsartRxRecord& r : bench.avr.chip().usart().rx_log()) {
            if (r.byte == '?') continue;
            ++received;
            std::size_t answered = 0;
            for (std::size_t i = 0; i < answer_cycles.size() && answer_cycles[i] < r.start_cycle; ++i) {
                answered += line_bytes.at(i);
            }
            most = std::max(most, received - answered);
        }
        return most;
    }

    AvrBench bench;
    uart::Cp2102 cp;
    host::GrblSender sender;
};

// A zigzag of short G1 lines: more bytes than grbl's receive buffer holds while the motion runs.
std::vector<SendLine> zigzag_job(int lines) {
    std::vector<SendLine> out{{"G21G90G94", "zigzag.nc:1"}, {"F3000", "zigzag.nc:2"}};
    for (int i = 0; i < lines; ++i) {
        out.push_back({"G1X" + std::to_string(i % 2 == 0 ? 1 : 0) + ".000Y" + std::to_string(i + 1) + ".000",
                       "zigzag.nc:" + std::to_string(i + 3)});
    }
    return out;
}

TEST(GrblProtocol, CharacterCountingKeepsTheReceiveBufferFullButNeverOver) {
    GrblBench g(zigzag_job(60), Protocol::CharacterCounting, true, 0);
    g.run(60 * kPsPerSec);
    ASSERT_TRUE(g.sender.finished()) << g.sender.failure().value_or("");
    const std::size_t most = g.max_unanswered_bytes();
    std::cout << "most line bytes received and not answered: " << most << "\n";
    EXPECT_LE(most, 127U);
    EXPECT_GE(most, 127U - 18U) << "the window was never near full: the test shows nothing";
    EXPECT_EQ(g.driver_steps("step_y"), 60U * 160U);
}

TEST(GrblProtocol, SendResponseHasOneLineInFlight) {
    GrblBench g(zigzag_job(10), Protocol::SendResponse, true, 0);
    g.run(60 * kPsPerSec);
    ASSERT_TRUE(g.sender.finished()) << g.sender.failure().value_or("");
    EXPECT_EQ(g.max_unanswered_bytes(), std::string("G1X0.000Y10.000\n").size());
}

TEST(GrblProtocol, AnUnsupportedLineIsAnsweredWithItsError) {
    std::vector<SendLine> job = zigzag_job(2);
    job.insert(job.begin() + 3, {"G2X1Y1I1J0", "zigzag.nc:4"});
    GrblBench g(job, Protocol::CharacterCounting, false, 0);
    g.run(30 * kPsPerSec);
    ASSERT_TRUE(g.sender.finished()) << g.sender.failure().value_or("");
    ASSERT_EQ(g.sender.stream().errors().size(), 1U);
    EXPECT_EQ(g.sender.stream().errors()[0].line.where, "zigzag.nc:4");
    EXPECT_EQ(g.sender.stream().errors()[0].answer, "error:20");  // grbl: unsupported command
}

}  // namespace
}  // namespace cnc::avr::test
