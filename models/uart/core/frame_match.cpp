#include "uart/core/frame_match.hpp"

#include <cstdlib>

namespace cnc::uart {

FrameMatch match_frames(const std::vector<SentFrame>& sent, const std::vector<ReceivedFrame>& received,
                        TimePs start_tolerance_ps) {
    FrameMatch m;
    m.fate.assign(sent.size(), FrameFate::Lost);
    m.extra.assign(sent.size(), 0);
    std::vector<bool> framed(sent.size(), false);
    std::size_t k = 0;
    for (const ReceivedFrame& r : received) {
        if (r.framing_error) ++m.framing_flagged;
        while (k < sent.size() && r.t_start_ps >= sent[k].t_end_ps) ++k;
        if (k == sent.size() || r.t_start_ps < sent[k].t_start_ps - start_tolerance_ps) {
            ++m.extra_frames;
            continue;
        }
        if (framed[k]) {
            ++m.extra[k];
            ++m.extra_frames;
            continue;
        }
        framed[k] = true;
        const bool own_start = std::llabs(r.t_start_ps - sent[k].t_start_ps) <= start_tolerance_ps;
        m.fate[k] = own_start && r.byte == sent[k].byte ? FrameFate::AsSent : FrameFate::Wrong;
    }
    for (const FrameFate f : m.fate) {
        if (f == FrameFate::AsSent) ++m.as_sent;
        if (f == FrameFate::Wrong) ++m.wrong;
        if (f == FrameFate::Lost) ++m.lost;
    }
    return m;
}

}  // namespace cnc::uart
