#include "architectures/grbl/grbl_settings.hpp"

namespace cnc::sim {

void read_grbl_settings(KeyReader& r, GrblSettings& s, const std::filesystem::path& base) {
    read_serial_host_settings(r, s.serial);
    read_avr_board_settings(r, s.board, base);
    s.firmware_where = r.where("avr.firmware");
    s.protocol = r.get_choice("grbl.protocol", "character-counting", {"character-counting", "send-response"},
                              "grbl: how the sender streams: character-counting (lines in flight up to grbl's "
                              "receive buffer, as grbl's stream.py) or send-response (each line after the answer "
                              "of the one before)") == "character-counting"
                     ? host::grbl::Protocol::CharacterCounting
                     : host::grbl::Protocol::SendResponse;
    s.rx_buffer_bytes = static_cast<std::size_t>(
        r.get_int("grbl.rx_buffer_bytes", 128, 2, 65536,
                  "grbl: the firmware's serial receive buffer, bytes (grbl 1.1 RX_BUFFER_SIZE on the 328P: 128; a "
                  "ring, so it holds one less)"));
    s.status_interval_ps = s_to_ps(
        1e-3 *
        r.get_float("grbl.status_interval_ms", 200.0, 0.0, 60'000.0,
                    "grbl: status queries ('?') while the job streams, every this many ms (Universal G-code Sender: "
                    "200); 0: none until the last line is answered"));
    s.settings = r.get_string_list("grbl.settings",
                                   "grbl: settings sent after the start-up message, \"$N=value\", after and over "
                                   "those derived from the machine ($100/$101 steps per mm, $110/$111 maximum rate, "
                                   "$120/$121 acceleration, $32 laser mode)");
    s.settings_where = r.where("grbl.settings");
}

}  // namespace cnc::sim
