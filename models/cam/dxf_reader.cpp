#include "cam/dxf_reader.hpp"

#include <cmath>
#include <map>
#include <set>
#include <utility>

#include <dl_creationadapter.h>
#include <dl_dxf.h>

#include "cam/dxf_scan.hpp"
#include "common/bad_input.hpp"

namespace cnc::cam {

namespace {

constexpr double kDegToRad = M_PI / 180.0;
constexpr int kByBlock = 0;
constexpr int kByLayer = 256;
constexpr int kDefaultColour = 7;   // white/black: what AutoCAD draws BYBLOCK outside a block in
constexpr int kClosedPolyline = 1;  // group 70 bit 0 of LWPOLYLINE and POLYLINE
// An extrusion direction this close to +-Z (unit vector components) is a flat entity: DXF writes it to 1e-15.
constexpr double kFlatTolerance = 1e-9;

const std::set<std::string>& read_types() {
    static const std::set<std::string> types = {"LINE", "ARC", "CIRCLE", "LWPOLYLINE", "POLYLINE"};
    return types;
}

// dxflib's callbacks, in file order. The n-th entity of a type the CAM reads is the n-th such entity of the scan,
// which gives its number and line; entities inside block definitions are drawn only through an INSERT.
class Adaptor : public DL_CreationAdapter {
public:
    Adaptor(std::string file, const DxfScan& scan, double mm_per_unit) : m_file(std::move(file)), m_mm(mm_per_unit) {
        for (std::size_t i = 0; i < scan.entities.size(); ++i) {
            if (read_types().count(scan.entities[i].type) != 0) {
                m_sources.push_back(static_cast<int>(i));
                m_lines.push_back(scan.entities[i].line);
                m_types.push_back(scan.entities[i].type);
            }
        }
    }

    void addLayer(const DL_LayerData& data) override {
        m_layer_colour[data.name] = std::abs(getAttributes().getColor());  // negative: the layer is off
    }
    void addBlock(const DL_BlockData&) override { m_in_block = true; }
    void endBlock() override { m_in_block = false; }

    void addLine(const DL_LineData& d) override {
        if (!start("LINE", false)) return;
        add(geom::Segment::line(point(d.x1, d.y1), point(d.x2, d.y2)));
    }
    void addArc(const DL_ArcData& d) override {
        if (!start("ARC", true)) return;
        const geom::Vec2 c = ocs_point(d.cx, d.cy);
        const double r = d.radius * m_mm;
        const geom::Vec2 from = c + ocs_direction(d.angle1) * r;
        const geom::Vec2 to = c + ocs_direction(d.angle2) * r;
        // Counter-clockwise from angle 50 to angle 51 about the extrusion direction: clockwise seen from +Z when
        // it is -Z.
        add(geom::Segment::arc(from, to, c, !m_mirrored));
    }
    void addCircle(const DL_CircleData& d) override {
        if (!start("CIRCLE", true)) return;
        const geom::Vec2 c = ocs_point(d.cx, d.cy);
        const geom::Vec2 from = c + geom::Vec2{d.radius * m_mm, 0.0};
        add(geom::Segment::arc(from, from, c, true));
    }
    void addPolyline(const DL_PolylineData& d) override {
        if (!start("POLYLINE", true)) return;
        m_polyline = true;
        m_closed = (d.flags & kClosedPolyline) != 0;
        m_vertices.clear();
    }
    void addVertex(const DL_VertexData& d) override {
        if (m_polyline) m_vertices.push_back({ocs_point(d.x, d.y), m_mirrored ? -d.bulge : d.bulge});
    }
    void endSequence() override { flush(); }

    // The polyline in progress ends where the next entity starts, or at the end of the file.
    void flush() {
        if (!m_polyline) return;
        m_polyline = false;
        const std::size_t n = m_vertices.size();
        const std::size_t segments = m_closed ? n : (n == 0 ? 0 : n - 1);
        for (std::size_t i = 0; i < segments; ++i) {
            const Vertex& a = m_vertices[i];
            const Vertex& b = m_vertices[(i + 1) % n];
            add(bulge_segment(a.at, b.at, a.bulge));
        }
    }

    Drawing take(const std::string& file) {
        flush();
        Drawing d;
        d.file = file;
        d.entities = std::move(m_entities);
        d.entities_read = m_read;
        return d;
    }

private:
    struct Vertex {
        geom::Vec2 at;
        double bulge = 0.0;
    };

    geom::Vec2 point(double x, double y) const { return {x * m_mm, y * m_mm}; }
    // ARC, CIRCLE and polyline coordinates are in the entity's object coordinate system (DXF reference, "Object
    // Coordinate Systems"): with the extrusion direction -Z (a mirrored entity) its x axis is the world's -x.
    geom::Vec2 ocs_point(double x, double y) const { return point(m_mirrored ? -x : x, y); }
    geom::Vec2 ocs_direction(double angle_deg) const {
        const double a = angle_deg * kDegToRad;
        return {m_mirrored ? -std::cos(a) : std::cos(a), std::sin(a)};
    }

    // A new entity of the ENTITIES section: false inside a block definition. `ocs`: its coordinates are in its
    // object coordinate system (a LINE's are in the world's).
    bool start(const char* type, bool ocs) {
        flush();
        if (m_in_block) return false;
        const bool scanned = m_read < static_cast<int>(m_sources.size());
        m_type = scanned ? m_types[m_read] : type;  // dxflib gives LWPOLYLINE and POLYLINE the same call
        m_source = scanned ? m_sources[m_read] : m_read;
        m_line = scanned ? m_lines[m_read] : 0;
        ++m_read;
        const DL_Attributes a = getAttributes();
        m_layer = a.getLayer();
        m_colour = a.getColor();
        if (m_colour == kByLayer) {
            const auto it = m_layer_colour.find(m_layer);
            m_colour = it == m_layer_colour.end() ? kDefaultColour : it->second;
        }
        if (m_colour == kByBlock) m_colour = kDefaultColour;
        const double* n = getExtrusion()->getDirection();
        if (ocs && (std::fabs(n[0]) > kFlatTolerance || std::fabs(n[1]) > kFlatTolerance)) {
            throw BadInput(m_file + ":" + std::to_string(m_line),
                           m_type + " is not in the XY plane (extrusion direction " + std::to_string(n[0]) + ", " +
                               std::to_string(n[1]) + ", " + std::to_string(n[2]) + "): the CAM cuts 2D drawings");
        }
        m_mirrored = ocs && n[2] < 0.0;
        return true;
    }

    // A zero-length line or arc would be a move that goes nowhere.
    void add(const geom::Segment& s) {
        if (s.length_mm() > 0.0) m_entities.push_back({s, m_type, m_source, m_line, m_layer, m_colour});
    }

    std::string m_file;
    double m_mm;
    bool m_mirrored = false;              // the entity's extrusion direction is -Z
    std::vector<int> m_sources, m_lines;  // the number, line and type of each entity of a type the CAM reads
    std::vector<std::string> m_types;
    std::map<std::string, int> m_layer_colour;
    bool m_in_block = false;
    std::vector<Entity> m_entities;
    int m_read = 0;
    std::string m_type, m_layer;
    int m_source = 0, m_line = 0, m_colour = kDefaultColour;
    bool m_polyline = false, m_closed = false;
    std::vector<Vertex> m_vertices;
};

std::string unread_text(const std::map<std::string, int>& unread) {
    std::string text;
    for (const auto& [type, count] : unread)
        text += (text.empty() ? "" : ", ") + type + " (" + std::to_string(count) + ")";
    return text;
}

}  // namespace

double mm_per_insunit(int insunits) {
    switch (insunits) {
        case 0:
            return 1.0;  // unitless: the CAM takes drawing units as mm, as seed 000's form does by default
        case 1:
            return 25.4;
        case 2:
            return 304.8;
        case 4:
            return 1.0;
        case 5:
            return 10.0;
        case 6:
            return 1000.0;
        case 8:
            return 25.4e-6;  // microinches
        case 9:
            return 25.4e-3;  // mils
        case 13:
            return 1e-3;  // microns
        case 14:
            return 100.0;  // decimetres
        default:
            return 0.0;
    }
}

Drawing read_dxf(const std::string& path, const DxfOptions& options) {
    const DxfScan scan = scan_dxf(path);
    const double mm = mm_per_insunit(scan.insunits);
    if (mm == 0.0) {
        throw BadInput(path + ":" + std::to_string(scan.insunits_line),
                       "$INSUNITS " + std::to_string(scan.insunits) +
                           " is not a length the CAM converts: 0 (unitless, read as mm), 1 in, 2 ft, 4 mm, 5 cm, 6 m, "
                           "8 microinch, 9 mil, 13 micron, 14 dm");
    }
    std::map<std::string, int> unread;
    int first_unread_line = 0;
    for (const ScannedEntity& e : scan.entities) {
        if (read_types().count(e.type) != 0) continue;
        if (unread.empty()) first_unread_line = e.line;
        ++unread[e.type];
    }
    if (!unread.empty() && !options.skip_unread) {
        throw BadInput(path + ":" + std::to_string(first_unread_line),
                       "entities the CAM does not read: " + unread_text(unread) +
                           "; it reads LINE, ARC, CIRCLE, LWPOLYLINE and POLYLINE (explode or convert the others, or "
                           "leave them out: cam.skip_unread = true, or cncsim cam --skip-unread)");
    }
    Adaptor adaptor(path, scan, mm);
    DL_Dxf dxf;
    if (!dxf.in(path, &adaptor)) throw BadInput(path, "cannot open the drawing");
    Drawing d = adaptor.take(path);
    d.unread = std::move(unread);
    if (d.entities.empty()) {
        throw BadInput(path,
                       "nothing to cut: the ENTITIES section has no LINE, ARC, CIRCLE, LWPOLYLINE or POLYLINE "
                       "of non-zero length");
    }
    return d;
}

}  // namespace cnc::cam
