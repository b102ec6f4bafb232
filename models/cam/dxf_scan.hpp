// A first pass over an ASCII DXF file's group codes, before dxflib reads its geometry: dxflib reads any text
// without complaint, so the checks that it is a DXF at all, the entity types it holds (with the line each starts
// on) and the units header ($INSUNITS) are ours.
#pragma once
#include <string>
#include <vector>

namespace cnc::cam {

struct ScannedEntity {
    std::string type;  // LINE, ARC, ... as the file spells it
    int line = 0;      // 1-based line of its "0" group code
};

struct DxfScan {
    std::vector<ScannedEntity> entities;  // the ENTITIES section's entities in file order (VERTEX, SEQEND not counted)
    int insunits = 0;                     // header $INSUNITS (0: not given, or "unitless")
    int insunits_line = 0;                // its line, 0 when absent
};

// Throws cnc::BadInput naming the file (and line) when it cannot be read, is a binary DXF, is not a sequence of
// group code and value lines, or has no ENTITIES section.
DxfScan scan_dxf(const std::string& path);

}  // namespace cnc::cam
