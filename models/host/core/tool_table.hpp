// The tool table of LinuxCNC's tool-table file format (`scenario.tool_table`): each tool's diameter, for cutter
// radius compensation (G41/G42), and Z length offset, for G43. Values in the machine's units, millimetres.
#pragma once
#include <istream>
#include <map>
#include <string>

namespace cnc::host {

struct ToolEntry {
    int tool = 0;              // T
    int pocket = 0;            // P (0 when the line has none)
    double diameter_mm = 0.0;  // D: G41/G42's radius is half of it
    double z_offset_mm = 0.0;  // Z: G43's tool length offset
    int line = 0;              // 1-based line of the table file
};

class ToolTable {
public:
    // nullptr for a tool the table does not hold. Tool 0 is "no tool": diameter and offset 0, always there.
    [[nodiscard]] const ToolEntry* find(int tool) const;
    [[nodiscard]] std::size_t size() const { return m_tools.size(); }
    [[nodiscard]] const std::string& file() const { return m_file; }

    // Throws cnc::BadInput("FILE:LINE", what is wrong and what is allowed).
    static ToolTable parse(std::istream& in, const std::string& filename);
    // BadInput if the file cannot be read.
    static ToolTable load(const std::string& path);

private:
    std::string m_file;
    std::map<int, ToolEntry> m_tools;
};

}  // namespace cnc::host
