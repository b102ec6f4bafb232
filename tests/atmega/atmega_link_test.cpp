// Links that do not work, on the atmega architecture: a firmware at another rate is refused before the run; one
// that does not speak the seed 003 protocol, says nothing or stops answering ends the run at once with the reason;
// a job that cannot finish is stopped by its own time limit. The firmwares are models/avr/firmware/tests.
#include <gtest/gtest.h>

#include <cmath>

#include "atmega_test_util.hpp"
#include "support/bad_input_message.hpp"

using cnc::test::bad_input_message;
using cnc::test::run_atmega;

namespace {

bool contains(const std::string& s, const std::string& part) {
    return s.find(part) != std::string::npos;
}

// One confirmed byte's trip at 57600 Bd with the defaults: 0.1 ms write latency, two 1 ms USB frames, 1 ms
// driver latency, the byte and its confirm (20 bits); the PC program allows 100 ms more (kConfirmMarginPs).
constexpr double kRoundTrip57600S = 0.1e-3 + 2 * 1e-3 + 1e-3 + 20.0 / 57600.0;  // 3.447 ms
constexpr double kSettleS = 0.3;  // host.settle_s default (seed 003's Sleep after opening the port)

}  // namespace

// grbl 1.1h at its own 115200 Bd (U2X0 = 1, UBRR0 = 16: 16 MHz / 136 = 117 647 Bd) on a link asked for 115200 (the
// CP2102's 24 MHz / 208 = 115 384.6 Bd, -1.92 %: within 8N1's 2.63 %). Its start-up message went out at boot and
// waits in the driver, so CAD2G reads its first byte as soon as the 0.3 s settle and its work on the first
// command (host.packet_processing_us, 0.2 ms) are over: a protocol mismatch at 0.3002 s, and the run stops at the
// next 10 ms check, 0.31 s.
TEST(AtmegaLinkFailure, GrblIsAProtocolMismatchWithinASecond) {
    const auto out =
        run_atmega("square_20mm", {std::string("avr.firmware=") + AVR_FW_GRBL_BANNER_ELF, "link.baud=115200"});
    EXPECT_FALSE(out.ok);
    EXPECT_EQ(out.failure.rfind("protocol mismatch: expected the confirm byte 0x06 of the seed 003 protocol before "
                                "the job's first byte (after the port settled), received ",
                                0),
              0U)
        << out.failure;
    // report.c report_init_message: "\r\nGrbl " GRBL_VERSION " ['$' for help]\r\n", in text and in ASCII hex
    EXPECT_TRUE(contains(out.failure, R"("\r\nGrbl 1.1h ['$' for help]\r\n" (hex 0D 0A 47 72 62 6C 20 31 2E 31 68 )"
                                      R"(20 5B 27 24 27 20 66 6F 72 20 68 65 6C 70 5D 0D 0A))"))
        << out.failure;
    EXPECT_TRUE(contains(out.failure, "avr_fw_grbl_banner.elf")) << out.failure;
    EXPECT_TRUE(contains(out.failure, "(run stopped at 0.310 s of simulated time)")) << out.failure;
    const auto& pc = out.report.at("atmega").at("pc");
    EXPECT_EQ(pc.at("bytes_written"), 0);
    EXPECT_NEAR(pc.at("t_stopped_s").get<double>(), kSettleS + 0.2e-3, 1e-12);
    EXPECT_EQ(out.metrics.axes.at(0).rising_edges, 0U);
}

// The same grbl on the atmega's default link, 57600 (57 553.96 Bd): 57 553.96 / 117 647.06 - 1 = -51.08 %, refused
// before anything runs, naming both ends.
TEST(AtmegaLinkFailure, AFirmwareAtAnotherRateIsRefusedBeforeTheRun) {
    const std::string err = bad_input_message(
        [] { (void)run_atmega("square_20mm", {std::string("avr.firmware=") + AVR_FW_GRBL_BANNER_ELF}); });
    EXPECT_TRUE(contains(err,
                         "square_20mm.toml: link.baud, avr.firmware: baud mismatch: link.baud = 57600 (the "
                         "CP2102 runs 57553.96 Bd) against the firmware "))
        << err;
    EXPECT_TRUE(contains(err, "'s USART0 at 117647.1 Bd (UBRR0 = 16, U2X0 = 1: 136 cycles a bit at 16 MHz)")) << err;
    EXPECT_TRUE(contains(err, "-51.08 % off the receiver's rate, and 8N1 works within +-2.63 %")) << err;
}

// seed 003's own firmware (UBRR0 = 16: 58 823.5 Bd) on a link asked for 51200 (AN205: 24 MHz / 469 = 51 172.7 Bd):
// 51 172.7 / 58 823.5 - 1 = -13.01 %.
TEST(AtmegaLinkFailure, TheBaudMismatchScenarioIsRefused) {
    const std::string err = bad_input_message([] { (void)run_atmega("baud_mismatch"); });
    EXPECT_TRUE(contains(err,
                         "link.baud = 51200 (the CP2102 runs 51172.71 Bd) against the seed 003 firmware's "
                         "USART0 at 58823.5 Bd (UBRR0 = 16, U2X0 = 0: 272 cycles a bit at 16 MHz)"))
        << err;
    EXPECT_TRUE(contains(err, "-13.01 %")) << err;
}

// A firmware that never sets its USART up (a timer ISR and a spin loop): nothing comes, and the first confirm is
// missed a round trip and the 100 ms margin after the settle.
TEST(AtmegaLinkFailure, ASilentFirmwareTimesOutAfterTheSettle) {
    const auto out = run_atmega("square_20mm", {std::string("avr.firmware=") + AVR_FW_BENCH_IDLE_ELF});
    EXPECT_FALSE(out.ok);
    EXPECT_EQ(out.failure.rfind("no confirm byte 0x06 within 103.4 ms before the job's first byte (after the port "
                                "settled): the firmware does not speak the seed 003 protocol",
                                0),
              0U)
        << out.failure;
    EXPECT_NEAR(out.report.at("atmega").at("pc").at("t_stopped_s").get<double>(), kSettleS + kRoundTrip57600S + 0.1,
                1e-9);
    EXPECT_TRUE(contains(out.failure, "(run stopped at 0.410 s of simulated time)")) << out.failure;
}

// A firmware that confirms the job's first 3 bytes and hangs: the third byte (a count of the first G00) is not the
// last of its transfer, so its confirm is due within a round trip and the margin of the write.
TEST(AtmegaLinkFailure, AFirmwareThatStopsAnsweringTimesOutInMidJob) {
    const auto out = run_atmega("square_20mm", {std::string("avr.firmware=") + AVR_FW_CONFIRM_THEN_HANG_ELF});
    EXPECT_FALSE(out.ok);
    EXPECT_EQ(out.failure.rfind("no confirm byte 0x06 within 103.4 ms after writing the job's byte 3 of 39: the "
                                "firmware stopped answering",
                                0),
              0U)
        << out.failure;
    const auto& pc = out.report.at("atmega").at("pc");
    EXPECT_EQ(pc.at("bytes_written"), 3);
}

// A firmware that confirms every byte and executes none: the PC program sends the whole job (G01 and M30, 7
// bytes), and the firmware never sleeps. Without scenario.max_sim_s the job's own limit stops the run and says so.
TEST(AtmegaLinkFailure, TheJobsOwnLimitStopsAJobThatCannotFinish) {
    const auto out = run_atmega("diagonal_45", {std::string("avr.firmware=") + AVR_FW_CONFIRM_ONLY_ELF});
    EXPECT_FALSE(out.ok);
    // G1 X20 Y20 F1000: 28.28 mm at 16.67 mm/s; the 0.3 s settle; 7 confirmed bytes; 0.2 ms per transfer (2).
    const double expected_s = std::sqrt(800.0) / (1000.0 / 60.0) + kSettleS + 7 * kRoundTrip57600S + 2 * 0.2e-3;
    const double limit_s = 2 * expected_s + 1 + 10;  // 2 x the estimate + 1 s per programmed move + 10 s
    EXPECT_NEAR(out.report.at("scenario").at("estimated_s").get<double>(), expected_s, 1e-9);
    EXPECT_NEAR(out.report.at("scenario").at("max_sim_s").get<double>(), limit_s, 1e-9);
    EXPECT_EQ(out.report.at("atmega").at("pc").at("bytes_written"), 7);
    EXPECT_EQ(out.metrics.axes.at(0).rising_edges, 0U);
    EXPECT_EQ(out.failure,
              "the firmware did not reach M30: stopped at 15.043 s of simulated time by this job's limit, 15.043 s = "
              "2 x 2.022 s + 1 s x 1 moves + 10 s from its 2.022 s estimate; set scenario.max_sim_s higher");
}
