// The grbl sender's core: the lines as sent, the receive-buffer window of character counting against send-response,
// the answers, the settings derived from the machine.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "common/bad_input.hpp"
#include "host/core/grbl/grbl_settings.hpp"
#include "host/core/grbl/grbl_stream.hpp"

namespace cnc::host::grbl {
namespace {

std::vector<SendLine> job_of(const std::vector<std::string>& texts) {
    std::vector<SendLine> out;
    for (std::size_t i = 0; i < texts.size(); ++i) out.push_back({texts[i], "job.nc:" + std::to_string(i + 1)});
    return out;
}

// Every line the stream lets out now.
std::vector<std::string> drain_writes(Stream& s) {
    std::vector<std::string> out;
    while (auto w = s.next_write()) out.push_back(*w);
    return out;
}

TEST(GrblLines, StripsCommentsBlanksAndCaseAsStreamPyDoes) {
    EXPECT_EQ(stripped_line("g1 x10.5 (to the edge) Y-2 ; and a note"), "G1X10.5Y-2");
    EXPECT_EQ(stripped_line("  (only a comment)  "), "");
    const std::vector<SendLine> lines = lines_to_send("G21\n\n(c)\nG0 X1\r\n", "a.nc");
    ASSERT_EQ(lines.size(), 2U);
    EXPECT_EQ(lines[1].text, "G0X1");
    EXPECT_EQ(lines[1].where, "a.nc:4");
}

TEST(GrblStream, NothingIsSentBeforeTheStartUpMessage) {
    Stream s({}, {}, job_of({"G0X1"}));
    EXPECT_FALSE(s.next_write());
    s.received("error:7");  // grbl 1.1 on a blank EEPROM, before its start-up message
    EXPECT_EQ(s.phase(), Phase::Banner);
    s.received("");
    s.received("Grbl 1.1h ['$' for help]");
    EXPECT_EQ(s.next_write(), std::optional<std::string>("G0X1\n"));
}

// Ten lines of 30 bytes with the newline: 4 fit in the 127 bytes of grbl's ring (120), the fifth after an ok.
TEST(GrblStream, CharacterCountingFillsTheReceiveBufferAndNoMore) {
    std::vector<std::string> texts(10, std::string(29, 'G'));
    Stream s({Protocol::CharacterCounting, 128, true}, {}, job_of(texts));
    s.received("Grbl 1.1h ['$' for help]");
    EXPECT_EQ(drain_writes(s).size(), 4U);
    EXPECT_EQ(s.in_flight_bytes(), 120U);
    s.received("ok");
    EXPECT_EQ(drain_writes(s).size(), 1U);
    EXPECT_EQ(s.in_flight_bytes(), 120U);
    // After 120 bytes a 7-byte line fits (127, what the ring holds), an 8-byte one does not.
    Stream over({Protocol::CharacterCounting, 128, true}, {}, job_of({std::string(119, 'X'), "G0X1234"}));
    over.received("Grbl 1.1h");
    EXPECT_EQ(drain_writes(over).size(), 1U);
    Stream fits({Protocol::CharacterCounting, 128, true}, {}, job_of({std::string(119, 'X'), "G0X123"}));
    fits.received("Grbl 1.1h");
    EXPECT_EQ(drain_writes(fits).size(), 2U);
    EXPECT_EQ(fits.in_flight_bytes(), 127U);
}

TEST(GrblStream, SendResponseWaitsForEachAnswer) {
    Stream s({Protocol::SendResponse, 128, true}, {}, job_of({"G0X1", "G0X2", "G0X3"}));
    s.received("Grbl 1.1h");
    EXPECT_EQ(drain_writes(s).size(), 1U);
    s.received("ok");
    EXPECT_EQ(drain_writes(s).size(), 1U);
    s.received("ok");
    EXPECT_EQ(drain_writes(s), std::vector<std::string>{"G0X3\n"});
    s.received("ok");
    EXPECT_TRUE(s.draining());
    s.received("<Run|MPos:1.000,0.000,0.000|FS:0,0>");
    EXPECT_EQ(s.phase(), Phase::Draining);
    s.received("<Idle|MPos:3.000,0.000,0.000|FS:0,0>");
    EXPECT_EQ(s.phase(), Phase::Done);
}

// A job with no line to send drains as soon as the start-up message (and any settings) are through.
TEST(GrblStream, AJobWithNoLineDrainsAtOnce) {
    Stream s({}, {}, {});
    s.received("Grbl 1.1h");
    EXPECT_TRUE(s.draining());
    Stream with_setting({}, job_of({"$0=10"}), {});
    with_setting.received("Grbl 1.1h");
    EXPECT_EQ(drain_writes(with_setting), std::vector<std::string>{"$0=10\n"});
    EXPECT_FALSE(with_setting.draining());
    with_setting.received("ok");
    EXPECT_TRUE(with_setting.draining());
}

TEST(GrblStream, SettingsGoOneAtATimeBeforeTheJob) {
    Stream s({}, job_of({"$100=160.000", "$101=160.000"}), job_of({"G0X1", "G0X2"}));
    s.received("Grbl 1.1h");
    EXPECT_EQ(drain_writes(s), std::vector<std::string>{"$100=160.000\n"});
    s.received("ok");
    EXPECT_EQ(drain_writes(s), std::vector<std::string>{"$101=160.000\n"});
    s.received("ok");
    EXPECT_EQ(drain_writes(s).size(), 2U);
}

TEST(GrblStream, ASettingGrblRefusesFailsNamingIt) {
    Stream s({}, {{"$999=1", "scenario.toml:7: grbl.settings"}}, job_of({"G0X1"}));
    s.received("Grbl 1.1h");
    (void)drain_writes(s);
    s.received("error:3");
    EXPECT_EQ(s.phase(), Phase::Failed);
    EXPECT_EQ(s.failure(), "grbl answered error:3 to the setting $999=1 (scenario.toml:7: grbl.settings)");
    ASSERT_TRUE(s.refused_setting());
    EXPECT_EQ(s.refused_setting()->line.text, "$999=1");
}

TEST(GrblStream, AnErrorNamesItsLineStrictStopsLenientGoesOn) {
    for (const bool strict : {true, false}) {
        Stream s({Protocol::CharacterCounting, 128, strict}, {}, job_of({"G0X1", "G2X1Y1I1", "G0X3"}));
        s.received("Grbl 1.1h");
        EXPECT_EQ(drain_writes(s).size(), 3U);
        s.received("ok");
        s.received("error:20");
        ASSERT_EQ(s.errors().size(), 1U);
        EXPECT_EQ(s.errors()[0].line.where, "job.nc:2");
        EXPECT_EQ(s.errors()[0].answer, "error:20");
        if (strict) {
            EXPECT_EQ(s.phase(), Phase::Failed);
            EXPECT_EQ(s.failure(), "grbl answered error:20 to job.nc:2: G2X1Y1I1");
        } else {
            s.received("ok");
            EXPECT_TRUE(s.draining());
        }
    }
}

TEST(GrblStream, AnAlarmStopsTheJob) {
    Stream s({}, {}, job_of({"G0X1", "G0X2"}));
    s.received("Grbl 1.1h");
    (void)drain_writes(s);
    s.received("ALARM:2");
    EXPECT_EQ(s.phase(), Phase::Failed);
    EXPECT_EQ(s.failure(), "grbl raised ALARM:2 at job.nc:1");
}

TEST(GrblSettings, TheMachineGivesStepsRatesAndAccelerations) {
    MachineModel m;
    m.x.microsteps = 32;  // 1.8 deg, GT2 20 teeth: 6400 / 40 = 160 steps/mm
    m.y.microsteps = 32;
    m.x.limits.max_velocity_mm_per_s = 50.0;
    m.y.limits.max_accel_mm_per_s2 = 800.0;
    const std::vector<SendLine> lines =
        machine_settings(m, true, {"$0=5", "$110=2000"}, "s.toml: grbl.settings", "s.toml");
    std::vector<std::string> texts;
    for (const SendLine& l : lines) texts.push_back(l.text);
    const std::vector<std::string> expected{"$0=5",      "$32=1",         "$100=160.000",  "$101=160.000",
                                            "$110=2000", "$111=6000.000", "$120=1000.000", "$121=800.000"};
    EXPECT_EQ(texts, expected);
    EXPECT_EQ(lines[2].where, "s.toml: machine.x steps per mm");
    EXPECT_EQ(lines[0].where, "s.toml: grbl.settings");
    EXPECT_THROW((void)machine_settings(m, false, {"$x=1"}, "s.toml: grbl.settings", "s.toml"), BadInput);
    EXPECT_THROW((void)machine_settings(m, false, {"$10"}, "s.toml: grbl.settings", "s.toml"), BadInput);
}

}  // namespace
}  // namespace cnc::host::grbl
