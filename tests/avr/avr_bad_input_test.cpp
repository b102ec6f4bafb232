// Bad input to the ATmega328P model: the module refuses to elaborate with a BadInput naming what is wrong
// (the CLI turns it into exit status 2).
#include "avr_test_support.hpp"
#include "common/bad_input.hpp"

using namespace cnc::avr;
using namespace cnc::avr::test;

namespace {

std::string error_of(const AvrCoreConfig& cfg) {
    try {
        AvrCore avr("avr", cfg);
    } catch (const cnc::BadInput& e) {
        return e.what();
    }
    return "";
}

}  // namespace

TEST(AvrBadInput, MissingElf) {
    AvrCoreConfig cfg = config_for("/nonexistent/firmware.elf");
    cfg.where = "run.toml: avr.firmware";
    EXPECT_EQ(error_of(cfg),
              "run.toml: avr.firmware: firmware ELF '/nonexistent/firmware.elf' not found or not readable");
}

TEST(AvrBadInput, TextFile) {
    const std::string e = error_of(config_for(CNC_SOURCE_DIR "/models/avr/firmware/tests/fw_test.h"));
    EXPECT_NE(e.find("fw_test.h' is not an ELF file"), std::string::npos) << e;
}

TEST(AvrBadInput, HostElf) {
    EXPECT_NE(error_of(config_for("/bin/true")).find("is an ELF for x86-64, not for the AVR"), std::string::npos);
}

TEST(AvrBadInput, ElfForAnotherMcu) {
    const std::string e = error_of(config_for(AVR_FW_OTHER_MCU_ELF));
    EXPECT_NE(e.find("was built for atmega88 (its .mmcu section), the model is an atmega328p"), std::string::npos) << e;
}

TEST(AvrBadInput, OtherMcuOrClockInTheConfig) {
    AvrCoreConfig cfg = config_for(AVR_FW_USART_TX_ELF);
    cfg.mcu = "atmega2560";
    EXPECT_NE(error_of(cfg).find("MCU 'atmega2560' is not modelled"), std::string::npos);
    cfg = config_for(AVR_FW_USART_TX_ELF);
    cfg.f_cpu_hz = 20'000'000;
    EXPECT_NE(error_of(cfg).find("declares F_CPU 16000000 Hz"), std::string::npos);
}

TEST(AvrBadInput, PinMapWithAPinThatDoesNotExist) {
    AvrCoreConfig cfg = config_for(AVR_FW_USART_TX_ELF);
    cfg.pins.pins["step_x"] = Pin{'B', 8};
    EXPECT_NE(error_of(cfg).find("pin 'PB8' does not exist"), std::string::npos);
    cfg.pins.pins["step_x"] = Pin{'E', 1};
    EXPECT_NE(error_of(cfg).find("pin 'PE1' names a port the ATmega328P does not have"), std::string::npos);
    cfg.pins = default_pin_map();
    cfg.pins.pins.erase("head");
    EXPECT_NE(error_of(cfg).find("the pin map has no 'head'"), std::string::npos);
}
