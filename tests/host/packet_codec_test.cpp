#include <gtest/gtest.h>

#include <limits>
#include <stdexcept>

#include "host/core/packet_codec.hpp"
#include "host_test_util.hpp"

namespace cnc::host {
namespace {

using test::expect_bad_input;

TEST(HostPacketCodec, MotionRoundTripIncludingExtremes) {
    constexpr std::int32_t kMin = std::numeric_limits<std::int32_t>::min();
    constexpr std::int32_t kMax = std::numeric_limits<std::int32_t>::max();
    const MotionPacket cases[] = {
        {0, 0, 0, 0}, {1, 320, -160, 1200}, {2, -1, 1, 65535}, {3, kMin, kMax, 1}, {3, kMax, kMin, 32768},
    };
    for (const MotionPacket& p : cases) {
        const MotionPacket back = decode_motion(encode_motion(p));
        EXPECT_EQ(back.motion, p.motion);
        EXPECT_EQ(back.steps_x, p.steps_x);
        EXPECT_EQ(back.steps_y, p.steps_y);
        EXPECT_EQ(back.feed, p.feed);
    }
}

TEST(HostPacketCodec, MotionBytesAreBigEndianTwosComplement) {
    const MotionBytes b = encode_motion(3, std::numeric_limits<std::int32_t>::min(), -1, 0x1234);
    const MotionBytes expected{0x03, 0x80, 0x00, 0x00, 0x00, 0xFF, 0xFF, 0xFF, 0xFF, 0x12, 0x34};
    EXPECT_EQ(b, expected);
    const MotionBytes c = encode_motion(0, 0x01020304, 0x7FFFFFFF, 0xFFFF);
    const MotionBytes expected_c{0x00, 0x01, 0x02, 0x03, 0x04, 0x7F, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF};
    EXPECT_EQ(c, expected_c);
}

TEST(HostPacketCodec, InitRoundTrip) {
    const InitBytes b = encode_init(0xDEADBEEF, 1);
    const InitBytes expected{0xFF, 0xDE, 0xAD, 0xBE, 0xEF, 0x00, 0x00, 0x00, 0x01};
    EXPECT_EQ(b, expected);
    const InitPacket p = decode_init(b);
    EXPECT_EQ(p.num_x, 0xDEADBEEFu);
    EXPECT_EQ(p.num_y, 1u);
}

TEST(HostPacketCodec, TheRampsInitPacketAppendsItsRegistersToTheSeeds) {
    const RampInitBytes b = encode_ramp_init(18'750'000, 1, 0x465E, 0x10C8F);
    const RampInitBytes expected{0xFF, 0x01, 0x1E, 0x1A, 0x30, 0x00, 0x00, 0x00, 0x01,
                                 0x00, 0x00, 0x46, 0x5E, 0x00, 0x01, 0x0C, 0x8F};
    EXPECT_EQ(b, expected);
}

TEST(HostPacketCodec, TheSCurvesInitPacketAppendsItsJerkToTheRamps) {
    const ScurveInitBytes b = encode_scurve_init(18'750'000, 1, 0x465E, 0x10C8F, 0x0939'27A9);
    const ScurveInitBytes expected{0xFF, 0x01, 0x1E, 0x1A, 0x30, 0x00, 0x00, 0x00, 0x01, 0x00, 0x00,
                                   0x46, 0x5E, 0x00, 0x01, 0x0C, 0x8F, 0x09, 0x39, 0x27, 0xA9};
    EXPECT_EQ(b, expected);
}

TEST(HostPacketCodec, MarkerConfusionIsRejected) {
    EXPECT_THROW(encode_motion(0xFF, 0, 0, 0), std::invalid_argument);
    EXPECT_THROW(decode_init(InitBytes{0x01}), std::invalid_argument);
    EXPECT_THROW(decode_motion(MotionBytes{0xFF}), std::invalid_argument);
    EXPECT_EQ(decode_motion(MotionBytes{0xFE}).motion, 0xFE);  // the FPGA takes any other first byte as motion
}

TEST(HostPacketCodec, ToPacketChecksRanges) {
    MotionSegment s;
    s.index = 12;
    s.motion = MotionKind::ArcCCW;
    s.steps_x = -2147483648LL;
    s.steps_y = 2147483647LL;
    s.feed = 65535;
    const MotionPacket p = to_packet(s);
    EXPECT_EQ(p.motion, 3);
    EXPECT_EQ(p.steps_x, std::numeric_limits<std::int32_t>::min());
    EXPECT_EQ(p.steps_y, std::numeric_limits<std::int32_t>::max());
    EXPECT_EQ(p.feed, 65535);

    MotionSegment bad = s;
    bad.steps_x = 2147483648LL;
    expect_bad_input([&] { to_packet(bad); }, {"segment 12: steps_x 2147483648 outside int32"});
    bad = s;
    bad.steps_y = -2147483649LL;
    expect_bad_input([&] { to_packet(bad); }, {"steps_y -2147483649 outside int32"});
    bad = s;
    bad.feed = 65536;
    expect_bad_input([&] { to_packet(bad); }, {"feed 65536 outside 0..65535"});
    bad = s;
    bad.feed = -1;
    expect_bad_input([&] { to_packet(bad); }, {"feed -1 outside 0..65535"});
    bad = s;
    bad.motion = static_cast<MotionKind>(7);
    expect_bad_input([&] { to_packet(bad); }, {"motion 7 outside 0..3"});
}

}  // namespace
}  // namespace cnc::host
