// A DXF drawing into the CAM's Drawing, on dxflib (a thin adaptor): LINE, ARC, CIRCLE, LWPOLYLINE and POLYLINE
// (with bulges) of the ENTITIES section, in mm after the header's $INSUNITS, with their layer and colour.
#pragma once
#include <string>

#include "cam/drawing.hpp"

namespace cnc::cam {

struct DxfOptions {
    // Entity types the CAM does not read (SPLINE, TEXT, INSERT, ...): false refuses the drawing, listing them with
    // their counts; true leaves them out and lists them in Drawing::unread.
    bool skip_unread = false;
};

// Throws cnc::BadInput naming the file (and line) for a file that is not a DXF, an $INSUNITS the CAM does not
// convert, entity types it does not read (unless skipped), or a drawing with nothing to cut.
Drawing read_dxf(const std::string& path, const DxfOptions& options);

// mm per drawing unit for a DXF $INSUNITS code (0, unitless, is taken as mm); 0 for a code without a length.
double mm_per_insunit(int insunits);

}  // namespace cnc::cam
