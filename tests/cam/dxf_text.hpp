// Minimal ASCII DXF drawings written by the tests (group code and value lines), so that the CAM's tests read real
// files through dxflib. Angles in degrees, as DXF stores them.
#pragma once
#include <fstream>
#include <string>
#include <utility>
#include <vector>

#include <fmt/format.h>

namespace cnc::test {

class DxfText {
public:
    DxfText& insunits(int code) {
        m_header = fmt::format(FMT_STRING("0\nSECTION\n2\nHEADER\n9\n$INSUNITS\n70\n{}\n0\nENDSEC\n"), code);
        return *this;
    }
    DxfText& layer(const std::string& name, int colour) {
        m_layers += fmt::format(FMT_STRING("0\nLAYER\n2\n{}\n70\n0\n62\n{}\n6\nCONTINUOUS\n"), name, colour);
        return *this;
    }
    DxfText& line(double x1, double y1, double x2, double y2, int colour = 256, const std::string& layer = "0") {
        m_entities += "0\nLINE\n" + common(colour, layer) +
                      fmt::format(FMT_STRING("10\n{:.17g}\n20\n{:.17g}\n30\n0\n11\n{:.17g}\n21\n{:.17g}\n31\n0\n"), x1,
                                  y1, x2, y2);
        return *this;
    }
    // extrusion_z -1: the arc's object coordinate system is mirrored (DXF groups 210, 220, 230).
    DxfText& arc(double cx, double cy, double r, double a1_deg, double a2_deg, int colour = 256,
                 double extrusion_z = 1.0) {
        m_entities +=
            "0\nARC\n" + common(colour, "0") +
            fmt::format(FMT_STRING("10\n{:.17g}\n20\n{:.17g}\n30\n0\n40\n{:.17g}\n50\n{:.17g}\n51\n{:.17g}\n"), cx, cy,
                        r, a1_deg, a2_deg) +
            fmt::format(FMT_STRING("210\n0\n220\n0\n230\n{:g}\n"), extrusion_z);
        return *this;
    }
    DxfText& circle(double cx, double cy, double r) {
        m_entities += "0\nCIRCLE\n" + common(256, "0") +
                      fmt::format(FMT_STRING("10\n{:.17g}\n20\n{:.17g}\n30\n0\n40\n{:.17g}\n"), cx, cy, r);
        return *this;
    }
    // Vertices (x, y, bulge); closed: group 70 bit 0.
    DxfText& lwpolyline(const std::vector<std::vector<double>>& vertices, bool closed) {
        m_entities += "0\nLWPOLYLINE\n" + common(256, "0") +
                      fmt::format(FMT_STRING("90\n{}\n70\n{}\n"), vertices.size(), closed ? 1 : 0);
        for (const auto& v : vertices) {
            m_entities += fmt::format(FMT_STRING("10\n{:.17g}\n20\n{:.17g}\n42\n{:.17g}\n"), v[0], v[1], v[2]);
        }
        return *this;
    }
    // The same as an old-style POLYLINE: a VERTEX entity per vertex, then SEQEND.
    DxfText& polyline(const std::vector<std::vector<double>>& vertices, bool closed) {
        m_entities += "0\nPOLYLINE\n" + common(256, "0") + fmt::format(FMT_STRING("66\n1\n70\n{}\n"), closed ? 1 : 0);
        for (const auto& v : vertices) {
            m_entities += "0\nVERTEX\n" + common(256, "0") +
                          fmt::format(FMT_STRING("10\n{:.17g}\n20\n{:.17g}\n42\n{:.17g}\n"), v[0], v[1], v[2]);
        }
        m_entities += "0\nSEQEND\n" + common(256, "0");
        return *this;
    }
    // Any other entity, by its type name only (for the types the CAM does not read).
    DxfText& other(const std::string& type) {
        m_entities += "0\n" + type + "\n" + common(256, "0");
        return *this;
    }

    [[nodiscard]] std::string text() const {
        std::string tables;
        if (!m_layers.empty())
            tables = "0\nSECTION\n2\nTABLES\n0\nTABLE\n2\nLAYER\n" + m_layers + "0\nENDTAB\n0\nENDSEC\n";
        return m_header + tables + "0\nSECTION\n2\nENTITIES\n" + m_entities + "0\nENDSEC\n0\nEOF\n";
    }
    void write(const std::string& path) const { std::ofstream(path) << text(); }

private:
    static std::string common(int colour, const std::string& layer) {
        return fmt::format(FMT_STRING("8\n{}\n62\n{}\n"), layer, colour);
    }

    std::string m_header, m_layers, m_entities;
};

}  // namespace cnc::test
