#pragma once
#include <aeronc/recognition/DomainTree.h>
#include <aeronc/recognition/DomainTreeJson.h>  // toJson / fromJson, for the callers of recognise()

#include <TopoDS_Shape.hxx>
#include <functional>
#include <optional>
#include <string>

namespace aeronc::recognition {

struct Blank {
    Vec3 min{0, 0, 0};
    Vec3 max{0, 0, 0};
};

struct RecogniseOptions {
    // Setup directions (tool axes). Empty: found from the part (largest planar face's
    // normal and its opposite, then directions of remaining unmachined features).
    std::vector<Vec3> directions;
    // Blank: explicit box in world coordinates, or the part's bounding box in each
    // setup frame grown by this allowance. Elements open to the blank start at its highest
    // corner along their axis (without a blank: the part's box square to its principal axes).
    std::optional<Blank> blank;
    double blankAllowance = 0.0;
    double linearTolerance = 1e-3;   // mm: heights equal, points coincide
    double angularTolerance = 1e-3;  // rad: normal parallel / perpendicular to the axis
    double chordTolerance = 0.01;    // mm: sagitta when curves become polylines
    // Called with a fraction 0..1 and a stage; returning false cancels (throws). Called from
    // the thread that called recognise().
    std::function<bool(double, const std::string&)> progress;
    // Threads the levels of a setup are sliced on; 0: one per core of the machine.
    int threads = 0;
};

// Layered-slicing recognition of generalised pockets, openings and holes.
DomainTree recognise(const TopoDS_Shape& solid, const RecogniseOptions& options = {});

// Recognises the one solid of `shape`, which may also hold free faces, shells, wires or
// edges (a STEP import often does), and numbers the faces by their FaceN in `shape`, so
// roles, selections and the face count are those of the object the user picked. Faces
// outside the solid get no element and the role stock; they are listed in leftOutFaces and
// named in a warning. Throws like validatedSolid for a shape without exactly one valid solid.
DomainTree recogniseShape(const TopoDS_Shape& shape, const std::string& origin, const RecogniseOptions& options = {});

}  // namespace aeronc::recognition
