// Cutter radius compensation (G41/G42) as LinuxCNC 2.9's interpreter makes it: the tool centre's path beside the
// programmed one, one tool radius away. Pure geometry: the interpreter (gcode.cpp) holds the moves back and sends
// them out; this file says where each compensated move goes and what it does to the move before it.
//
// LinuxCNC's rules (G-code reference, "G41, G42 Cutter Compensation"; its interpreter's straight and arc
// compensation): the first move after G41/G42 (the entry) ends one radius beside its programmed end, square to
// the move; at a convex (outside) corner the tool goes round the programmed corner on an arc of the tool radius;
// at a concave (inside) corner the move before is cut short where the two offset paths meet, so the tool centre
// of the last move stays open until the next move is known. The messages are LinuxCNC's.
#pragma once
#include <optional>
#include <string>
#include <vector>

#include "common/geometry.hpp"

namespace cnc::host {

enum class CompSide { Left, Right };  // G41: the tool left of the path (seen along the motion), G42 right

// A compensated move that the next programmed move may still cut short.
struct OpenMove {
    geom::Segment path;              // the tool centre
    int turns = 0;                   // arcs: + counter-clockwise, - clockwise, the magnitude counts the turns (G2/G3 P)
    geom::Vec2 direction;            // lines: the way they were made; a corner must not turn them back
    double planned_sweep_rad = 0.0;  // arcs: the sweep when made; a corner may shorten it, not lengthen it
    bool rapid = false;              // a G0 (for the message of a corner that turns it back)
};

// What one programmed move makes.
struct CompStep {
    std::optional<geom::Vec2> cut_open_at;  // the open moves end here instead (a concave corner); then they go out
    bool release_open = false;              // the open moves go out as they are
    std::optional<OpenMove> corner;         // goes out before `move`: the arc round a convex corner (a G0: a line)
    OpenMove move;                          // the new open move
};

class CutterComp {
public:
    // G41/G42 (radius from the tool table) and G41.1/G42.1 (D diameter / 2). A negative radius puts the tool on
    // the other side, as LinuxCNC does for a tool smaller than the path's nominal tool. BadInput(where) when on.
    void turn_on(CompSide side, double radius_mm, const std::string& where);
    void turn_off() { m_on = false; }
    // G41/G42 in force (LinuxCNC refuses some codes then, whatever the radius).
    [[nodiscard]] bool on() const { return m_on; }
    // The moves are offset: on, with a radius above 0 (G41 with a radius of 0 is allowed and moves nothing).
    [[nodiscard]] bool offsets() const { return m_on && m_radius_mm > 0.0; }
    // No compensated move made yet since G41/G42: the next one is the entry.
    [[nodiscard]] bool entry() const { return m_entry; }

    // A G0/G1 from the programmed point `from` to `to`; `tool` is where the tool centre is, `open` the first open
    // move (none: nothing is open). Throws BadInput(where, LinuxCNC's message).
    CompStep line(geom::Vec2 from, geom::Vec2 tool, geom::Vec2 to, bool rapid, const OpenMove* open,
                  const std::string& where);
    // A G2/G3 from `from` to `to` about `center`, `turns` as OpenMove::turns.
    CompStep arc(geom::Vec2 from, geom::Vec2 tool, geom::Vec2 to, geom::Vec2 center, int turns, const OpenMove* open,
                 const std::string& where);

private:
    CompStep entry_line(geom::Vec2 from, geom::Vec2 tool, geom::Vec2 to, bool rapid, const std::string& where) const;
    CompStep entry_arc(geom::Vec2 from, geom::Vec2 tool, geom::Vec2 to, geom::Vec2 center, int turns,
                       const std::string& where) const;
    // The tool centre is inside the arc: G41 counter-clockwise, G42 clockwise.
    [[nodiscard]] bool inside(int turns) const { return (m_side == CompSide::Left) == (turns > 0); }
    [[nodiscard]] double side_sign() const { return m_side == CompSide::Left ? 1.0 : -1.0; }
    [[nodiscard]] OpenMove corner_arc(geom::Vec2 from, geom::Vec2 to, geom::Vec2 corner) const;

    bool m_on = false;
    bool m_entry = true;
    CompSide m_side = CompSide::Left;
    double m_radius_mm = 0.0;
};

// Moves the end of every open move to `to` (the first one's start stays): LinuxCNC's checks that this does not
// gouge, a line turned back or an arc made longer, then the change. BadInput(where, ...) and nothing changed.
void cut_open_moves(std::vector<OpenMove*>& open, geom::Vec2 to, const std::string& where);

// Signed sweep from `from` to `to` about `center`, as LinuxCNC counts it: `turns` > 0 counter-clockwise, the
// last turn ending at `to` (the same point: a whole turn).
double sweep_rad(geom::Vec2 from, geom::Vec2 center, int turns, geom::Vec2 to);

}  // namespace cnc::host
