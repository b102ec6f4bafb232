// read_link_bytes: the PC program's writes and the CP2102's logs, read and dropped slice by slice as an atmega
// run does, hold at most a byte in flight, and the bytes handed over are the ones the other end of the line got.
// The MCU is a second CP2102 whose host confirms every byte it receives (0x06, the seed 003 protocol), so the
// test needs no firmware.
#define SC_INCLUDE_DYNAMIC_PROCESSES  // sc_spawn
#include <gtest/gtest.h>

#include <cstdint>
#include <systemc>
#include <vector>

#include "architectures/atmega/link_bytes.hpp"
#include "host/pc_program.hpp"
#include "uart/cp2102.hpp"

using cnc::TimePs;
namespace cad2g = cnc::host::cad2g;

namespace {

constexpr TimePs kMs = cnc::kPsPerMs;
constexpr TimePs kDecisionPs = 1'000;  // any offset: it is added to every byte's start bit
constexpr TimePs kSliceMs = 2;         // shorter than one byte's round trip (about 3 ms): a slice sees few bytes

sc_core::sc_time at(TimePs t) {
    return sc_core::sc_time::from_value(static_cast<sc_dt::uint64>(t));
}

struct Handed {
    std::size_t transfer;
    TimePs t_ps;
};

}  // namespace

TEST(AtmegaLinkBytes, DroppedAsReadHoldAByteInFlightAndKeepTheCounts) {
    const std::vector<cad2g::Transfer> transfers{{0, 0, {0x01, 0x10, 0x20, 0x30, 0x40, 0x50}},
                                                 {1, 0, {0x02, 0x11, 0x21, 0x31}},
                                                 {1, 1, {0x12, 0x22, 0x32, 0x42}}};
    const cnc::uart::Cp2102Config link;
    const cnc::host::SenderConfig sender;
    sc_core::sc_signal<bool> to_mcu("to_mcu", true), to_pc("to_pc", true);
    cnc::uart::Cp2102 cp2102("cp2102", link);
    cnc::uart::Cp2102 mcu("mcu", link);
    cp2102.txd(to_mcu);
    cp2102.rxd(to_pc);
    mcu.txd(to_pc);
    mcu.rxd(to_mcu);
    cnc::host::PcProgram pc("host", sender, cp2102, transfers, {cnc::host::byte_round_trip_ps(sender, link), {}});
    sc_core::sc_spawn([&] {  // the first confirm once the port has settled, then one per byte received
        sc_core::wait(at(sender.settle_ps + kMs));
        const std::uint8_t confirm = cad2g::kConfirmByte;
        mcu.usb_write(&confirm, 1);
        for (;;) {
            sc_core::wait(mcu.data_event());
            while (mcu.read_byte()) mcu.usb_write(&confirm, 1);
        }
    });

    std::vector<Handed> handed;
    for (TimePs t = 0; !pc.finished() && t < 1'000 * kMs; t += kSliceMs * kMs) {
        sc_core::sc_start(at(kSliceMs * kMs));
        cnc::sim::read_link_bytes(pc, cp2102, kDecisionPs, [&](std::size_t transfer, TimePs t_ps) {
            handed.push_back({transfer, t_ps});
        });
        EXPECT_LE(pc.writes().size() - pc.writes().first(), 1U);  // written, its start bit not out yet
        EXPECT_EQ(cp2102.tx_log().size(), cp2102.tx_log().first());
        EXPECT_EQ(cp2102.rx_log().size(), cp2102.rx_log().first());
    }
    ASSERT_TRUE(pc.finished());
    sc_core::sc_start(at(10 * kMs));  // the last confirm crosses back
    cnc::sim::read_link_bytes(pc, cp2102, kDecisionPs, [&](std::size_t transfer, TimePs t_ps) {
        handed.push_back({transfer, t_ps});
    });

    // 14 bytes written and sent, 15 confirms (one before the first byte), none of them held any more.
    EXPECT_EQ(pc.writes().size(), 14U);
    EXPECT_EQ(pc.writes().first(), 14U);
    EXPECT_EQ(cp2102.tx_log().size(), 14U);
    EXPECT_EQ(cp2102.rx_log().size(), 15U);
    EXPECT_EQ(cp2102.rx_log().first(), 15U);
    // Every byte handed over once, in the order written, at the start bit the other end received.
    ASSERT_EQ(handed.size(), 14U);
    ASSERT_EQ(mcu.rx_log().size(), 14U);
    std::size_t j = 0;
    for (std::size_t k = 0; k < transfers.size(); ++k) {
        for (const std::uint8_t byte : transfers[k].bytes) {
            EXPECT_EQ(handed[j].transfer, k) << j;
            EXPECT_EQ(mcu.rx_log()[j].byte, byte) << j;
            EXPECT_EQ(handed[j].t_ps, mcu.rx_log()[j].t_start_bit_ps + kDecisionPs) << j;
            ++j;
        }
    }
}
