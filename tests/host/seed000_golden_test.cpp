// Seed 000 numbers and bytes, exactly as the thesis prints them (§3.4.2-§3.4.7, §4.5-§4.9, §6.3.1).
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "host/core/packet_codec.hpp"
#include "host/core/steps_file.hpp"
#include "host_test_util.hpp"

namespace cnc::host {
namespace {

TEST(HostSeed000, ReferenceMachineIs160StepsPerMmAndNumerator18750000) {
    const MachineModel m;  // seed 000 T3.4
    EXPECT_DOUBLE_EQ(m.x.steps_per_mm(), 160.0);
    EXPECT_DOUBLE_EQ(m.x.mm_per_step(), 0.00625);
    EXPECT_EQ(numerator(m.x.steps_per_mm()), 18'750'000u);  // §3.4.5
}

TEST(HostSeed000, InitPacketBytes) {
    const std::uint32_t n = numerator(160.0);
    const InitBytes expected{0xFF, 0x01, 0x1E, 0x1A, 0x30, 0x01, 0x1E, 0x1A, 0x30};  // §4.9
    EXPECT_EQ(encode_init(n, n), expected);
}

TEST(HostSeed000, MotionPacketBytes) {
    const MotionBytes expected{0x01, 0x00, 0x00, 0x01, 0x40, 0xFF, 0xFF, 0xFF, 0x60, 0x04, 0xB0};  // §4.9
    EXPECT_EQ(encode_motion(1, 320, -160, 1200), expected);
    // The same packet from G-code: 2 mm = 320 steps, -1 mm = -160 steps; a single-axis-dominant feed of 1200
    // needs the path feed 1200 * hypot(2, 1) / 2.
    const auto segs = cam(test::run_gcode("G1 X2 Y-1 F1341.6407864998738\n"), {}, {});
    ASSERT_EQ(segs.size(), 1u);
    EXPECT_EQ(encode_motion(to_packet(segs[0])), expected);
}

TEST(HostSeed000, WorkedExampleOfSection347) {
    const auto segs = cam(test::run_gcode("G1 X10.000 Y5.000 F1000\nG1 X10 Y0 F1000\n"), {}, {});
    ASSERT_EQ(segs.size(), 2u);
    EXPECT_EQ(segs[0].steps_x, 1600);
    EXPECT_EQ(segs[0].steps_y, 800);
    EXPECT_EQ(segs[0].feed, 894);
    EXPECT_EQ(segs[1].steps_x, 0);
    EXPECT_EQ(segs[1].steps_y, -800);
    EXPECT_EQ(segs[1].feed, 1000);
    EXPECT_DOUBLE_EQ(segs[1].path_feed_mm_per_min, 1000.0);  // T3.7 "PathFeed=1000"
}

TEST(HostSeed000, SixSegmentTestLogStepsFile) {
    const std::string path = std::string(CNC_SOURCE_DIR) + "/scenarios/jobs/six_segment.steps";
    const auto segs = load_steps_file(path);
    struct Row {
        MotionKind motion;
        std::int64_t x, y, feed;
    };
    const Row log[] = {
        // §6.3.1, Fig 6.4/6.5 sender log
        {MotionKind::Rapid, 4257, 15889, 1200},  {MotionKind::Linear, 0, 8000, 800},
        {MotionKind::Rapid, 2317, -5034, 1200},  {MotionKind::Linear, 4132, 3864, 800},
        {MotionKind::Rapid, -3807, -6829, 1200}, {MotionKind::Linear, 6000, 0, 800},
    };
    ASSERT_EQ(segs.size(), 6u);
    for (std::size_t i = 0; i < 6; ++i) {
        EXPECT_EQ(segs[i].index, static_cast<int>(i) + 1);
        EXPECT_EQ(segs[i].motion, log[i].motion);
        EXPECT_EQ(segs[i].steps_x, log[i].x);
        EXPECT_EQ(segs[i].steps_y, log[i].y);
        EXPECT_EQ(segs[i].feed, log[i].feed);
        EXPECT_DOUBLE_EQ(segs[i].dx_mm, static_cast<double>(log[i].x) / 160.0);
        EXPECT_DOUBLE_EQ(segs[i].dy_mm, static_cast<double>(log[i].y) / 160.0);
    }
    // The file is in canonical form: writing what was read reproduces it byte for byte.
    std::ifstream in(path);
    std::stringstream file;
    file << in.rdbuf();
    std::ostringstream rewritten;
    write_steps_file(rewritten, segs);
    EXPECT_EQ(rewritten.str(), file.str());
}

}  // namespace
}  // namespace cnc::host
