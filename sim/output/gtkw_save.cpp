#include "output/gtkw_save.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <sstream>
#include <system_error>

namespace cnc::sim {

namespace {

namespace fs = std::filesystem;

// gtkwave 3.3's trace flags (src/analyzer.h, TraceEntFlagBits): the bit each name has there.
constexpr std::uint32_t kBin = 1U << 3;
constexpr std::uint32_t kRightJustify = 1U << 5;
constexpr std::uint32_t kBlank = 1U << 9;
constexpr std::uint32_t kAnalogStep = 1U << 15;
constexpr std::uint32_t kAnalogInterpolated = 1U << 16;
constexpr std::uint32_t kAnalogBlankStretch = 1U << 17;
constexpr std::uint32_t kGroupBegin = 1U << 23;
constexpr std::uint32_t kGroupEnd = 1U << 24;
// A 1-bit trace as gtkwave adds it (what its own save files give a wire: @28).
constexpr std::uint32_t kWire = kRightJustify | kBin;

// The window the save file asks for, and the part of it the waves get: gtkwave 3.3.118 under Xvfb leaves the
// wave pane the window's width less the signal pane and 64 px of borders and scroll bar (the tree pane closed).
constexpr int kWindowWidthPx = 1400;
constexpr int kWindowHeightPx = 900;
constexpr int kSignalsWidthPx = 240;
constexpr int kWavePaneWidthPx = kWindowWidthPx - kSignalsWidthPx - 64;
// gtkwave's zoom z shows 2^-z time units per 200 px (nsperframe = zoombase^-zoom with zoombase 2, over
// pixelsperframe = 200).
constexpr double kPixelsPerFrame = 200.0;
// Rows an analog trace takes below its own (blank traces that stretch it), so that a position reads as a curve.
constexpr int kAnalogExtraRows = 4;
constexpr int kNamedMarkers = 26;  // A..Z, none set

std::string hex(std::uint32_t flags) {
    char buf[16];
    std::snprintf(buf, sizeof buf, "@%x", flags);
    return buf;
}

// gtkwave counts time in the timescale's unit (s .. fs) with its factor 1, 10 or 100 folded in.
std::int64_t unit_fs(std::int64_t timescale_fs) {
    std::int64_t unit = 1;
    while (unit * 1000 <= timescale_fs) unit *= 1000;
    return unit;
}

std::int64_t in_units(TimePs t_ps, std::int64_t unit) {
    const long double fs = static_cast<long double>(t_ps) * 1000.0L;
    return static_cast<std::int64_t>(std::llround(fs / static_cast<long double>(unit)));
}

// The first move with a twentieth of its length either side, inside the file; the whole file when the move is not
// in it or takes no time.
TimeSpan view_of(const TraceLayout& layout, const std::optional<TimeSpan>& first_move) {
    const TimeSpan file{layout.from_ps, std::max(layout.to_ps, layout.from_ps)};
    if (!first_move || first_move->to_ps <= first_move->from_ps) return file;
    const TimePs pad_ps = (first_move->to_ps - first_move->from_ps) / 20;
    const TimeSpan view{std::max(file.from_ps, first_move->from_ps - pad_ps),
                        std::min(file.to_ps, first_move->to_ps + pad_ps)};
    return view.to_ps > view.from_ps ? view : file;
}

void write_trace(std::ostream& out, const std::string& path, const SavedSignal& s) {
    if (!s.real) {
        out << hex(kWire) << '\n' << path << '\n';
        return;
    }
    out << hex(kWire | (s.interpolated ? kAnalogInterpolated : kAnalogStep)) << '\n' << path << '\n';
    out << hex(kAnalogBlankStretch) << '\n';
    for (int i = 0; i < kAnalogExtraRows; ++i) out << "-\n";
}

}  // namespace

std::optional<std::string> gtkw_path(const std::string& vcd_path) {
    std::error_code ec;
    const fs::file_status st = fs::status(vcd_path, ec);
    if (fs::exists(st) && !fs::is_regular_file(st)) return std::nullopt;
    fs::path p(vcd_path);
    if (p.extension() == ".vcd") return p.replace_extension(".gtkw").string();
    return vcd_path + ".gtkw";
}

std::string gtkw_text(const std::string& vcd_path, const TraceLayout& layout,
                      const std::optional<TimeSpan>& first_move) {
    const std::int64_t unit = unit_fs(layout.timescale_fs);
    const TimeSpan view = view_of(layout, first_move);
    const double span_units = std::max<double>(1.0, static_cast<double>(in_units(view.to_ps - view.from_ps, unit)));
    const double zoom = -std::log2(span_units * kPixelsPerFrame / kWavePaneWidthPx);
    const bool marked = first_move && first_move->from_ps >= view.from_ps && first_move->from_ps <= view.to_ps;

    std::error_code ec;
    const fs::path vcd_abs = fs::absolute(vcd_path, ec);
    std::ostringstream out;
    out << "[*] written by cncsim with the VCD: open with gtkwave VCD SAVEFILE (docs/vcd.md)\n";
    out << "[dumpfile] \"" << (ec ? fs::path(vcd_path) : vcd_abs).string() << "\"\n";
    out << "[timestart] " << in_units(view.from_ps, unit) << '\n';
    out << "[size] " << kWindowWidthPx << ' ' << kWindowHeightPx << '\n';
    out << "[pos] -1 -1\n";
    char zoom_text[32];
    std::snprintf(zoom_text, sizeof zoom_text, "%.6f", zoom);
    out << '*' << zoom_text << ' ' << (marked ? in_units(first_move->from_ps, unit) : -1);
    for (int i = 0; i < kNamedMarkers; ++i) out << " -1";
    out << '\n';
    out << "[sst_expanded] 0\n";
    out << "[signals_width] " << kSignalsWidthPx << '\n';

    std::vector<std::string> blocks;
    for (const SavedSignal& s : layout.signals) {
        if (std::find(blocks.begin(), blocks.end(), s.block) == blocks.end()) blocks.push_back(s.block);
    }
    for (const std::string& block : blocks) {
        if (!block.empty()) out << hex(kGroupBegin | kBlank) << "\n-" << block << '\n';
        for (const SavedSignal& s : layout.signals) {
            if (s.block != block) continue;
            write_trace(out, layout.top_scope + "." + (block.empty() ? "" : block + ".") + s.name, s);
        }
        if (!block.empty()) out << hex(kGroupEnd | kBlank) << "\n-" << block << '\n';
    }
    return out.str();
}

}  // namespace cnc::sim
