// Firmware ELF checks made before libsimavr loads a file.
#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>

#include "avr/core/elf_check.hpp"
#include "common/bad_input.hpp"
#include "support/test_path.hpp"

using namespace cnc::avr;

namespace {

std::string error_of(const std::string& path, std::uint32_t f_cpu_hz = 16'000'000) {
    try {
        (void)check_avr_elf(path, "atmega328p", f_cpu_hz, "s.toml: avr.firmware");
    } catch (const cnc::BadInput& e) {
        return e.what();
    }
    return "";
}

std::string temp_file(const std::string& name, const std::string& content) {
    const std::string path = cnc::test::test_path(name);
    std::ofstream(path, std::ios::binary) << content;
    return path;
}

}  // namespace

TEST(AvrElfCheck, ReadsTheMmcuSection) {
    const ElfInfo info = check_avr_elf(AVR_FW_USART_TX_ELF, "atmega328p", 16'000'000, "w");
    EXPECT_EQ(info.mmcu, "atmega328p");
    EXPECT_EQ(info.frequency_hz, 16'000'000U);
    EXPECT_EQ(info.avr_arch, 5);
}

TEST(AvrElfCheck, MissingFile) {
    const std::string e = error_of("/nonexistent/fw.elf");
    EXPECT_NE(e.find("s.toml: avr.firmware: firmware ELF '/nonexistent/fw.elf' not found"), std::string::npos) << e;
}

TEST(AvrElfCheck, TextFileIsNotAnElf) {
    const std::string path = temp_file("avr_not_elf.txt", "G01 X10 Y10\n");
    EXPECT_NE(error_of(path).find("is not an ELF file"), std::string::npos);
    EXPECT_NE(error_of(temp_file("avr_empty.elf", "")).find("is not an ELF file"), std::string::npos);
}

TEST(AvrElfCheck, HostElfIsNotForTheAvr) {
    const std::string e = error_of("/bin/true");
    EXPECT_NE(e.find("'/bin/true' is an ELF for x86-64, not for the AVR"), std::string::npos) << e;
}

TEST(AvrElfCheck, TruncatedElf) {
    EXPECT_NE(error_of(temp_file("avr_trunc.elf", std::string("\x7f"
                                                              "ELF\x01\x01\x01",
                                                              7)))
                  .find("truncated"),
              std::string::npos);
}

TEST(AvrElfCheck, ElfForAnotherMcu) {
    const std::string e = error_of(AVR_FW_OTHER_MCU_ELF);
    EXPECT_NE(e.find("was built for atmega88 (its .mmcu section), the model is an atmega328p"), std::string::npos) << e;
}

TEST(AvrElfCheck, ElfForAnotherClock) {
    const std::string e = error_of(AVR_FW_USART_TX_ELF, 8'000'000);
    EXPECT_NE(e.find("declares F_CPU 16000000 Hz (.mmcu section), the chip runs at 8000000 Hz"), std::string::npos)
        << e;
}

TEST(AvrElfCheck, ReadsAvrLibcsDeviceNoteWithoutAnMmcuSection) {
    // avr-libc 2.0's start-up code puts the -mmcu device name in .note.gnu.avr.deviceinfo; both MCUs are avr5, so
    // the architecture alone cannot tell them apart.
    const ElfInfo info = check_avr_elf(AVR_FW_NO_MMCU_M16_ELF, "atmega16", 16'000'000, "w");
    EXPECT_EQ(info.mmcu, "atmega16");
    EXPECT_EQ(info.frequency_hz, 0U);
    try {
        (void)check_avr_elf(AVR_FW_NO_MMCU_M16_ELF, "atmega328p", 16'000'000, "s.toml: avr.firmware", "avr.mcu");
        FAIL() << "an ATmega16 ELF passed as an ATmega328P's";
    } catch (const cnc::BadInput& e) {
        EXPECT_NE(std::string(e.what()).find("was built for atmega16 (its .note.gnu.avr.deviceinfo section), avr.mcu "
                                             "is atmega328p"),
                  std::string::npos)
            << e.what();
    }
}
