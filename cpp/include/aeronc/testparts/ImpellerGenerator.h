#pragma once
// Generator of centrifugal-impeller test parts with the ground truth it knows by construction
// (impeller paper, DESIGN.md §3): a hub of revolution, main and splitter blades with ruled side
// walls, root fillets and a centre bore. The axis is +Z; the part turns counter-clockwise seen
// from +Z, so a blade's pressure side faces +θ and its suction side −θ.
#include <TopoDS_Shape.hxx>
#include <string>
#include <vector>

namespace aeronc::testparts {

struct ImpellerSpec {
    int bladeCount = 9;           // main blades; as many splitters when splitters is set
    bool splitters = true;
    double boreDiameter = 20;     // through bore on the axis
    double noseRadius = 20;       // hub nose: the flat top annulus ends here and the hub begins
    double noseHeight = 40;       // z of the nose top plane (the back face is z = 0)
    double outerRadius = 60;      // rim cylinder
    double rimHeight = 8;         // z where the hub meets the rim; the hub is tangent to radial there
    double bladeHeight = 12;      // the shroud is the hub profile raised by this along the axis
    double bladeThickness = 2;    // side walls are offsets of the camber line; round leading/trailing edges
    double leadingRadius = 26;    // camber-line start of the main blades (inlet)
    double trailingRadius = 54;   // camber-line end (outlet)
    double splitterStart = 0.45;  // splitter inlet, as a fraction of the main blade's radial span
    double wrapDeg = 10;          // camber turn from inlet to outlet (backsweep)
    double leanDeg = 4;           // rotation of the top section about the axis: ruled, non-developable walls
    double filletRadius = 2;      // root fillet; 0 leaves the roots sharp
    int omitSplitter = -1;        // a defective part: this splitter left out (unequal blade groups)
    // The wider families, as other CAD systems write impellers (the defaults keep the part above).
    // wrapDeg 0 makes straight radial blades: their side walls are ruled between straight lines
    // (planes when leanDeg is 0 too).
    bool hubSpline = false;       // the hub meridian is a B-spline: the hub is one revolved B-spline face
    bool seamAcrossBlade = false; // the hub's seam meridian runs under main blade 0 and splits its root
    bool pumpPlate = false;       // open pump impeller: the blades stand on a flat back plate (no nose
                                  // cone; the hub is the plate's top plane) and have a flat tip
    double plateThickness = 8;    // the back plate of a pump impeller (pumpPlate)
    // As an exporter writes a part, its blades not exact copies: main blade offPitchBlade (with
    // its splitter) turned offPitchDeg off its pitch, within the recogniser's tolerance.
    int offPitchBlade = -1;
    double offPitchDeg = 0;
};

// One blade's faces, numbered 1-based as TopExp::MapShapes(shape, TopAbs_FACE) numbers them
// (FreeCAD's FaceN). fillets: the root fillet faces, each once, following the root loop from the
// pressure side (trailing, suction, leading after it).
struct BladeTruth {
    bool splitter = false;
    int pressure = 0, suction = 0, leading = 0, trailing = 0, shroud = 0;
    std::vector<int> fillets;     // a blade that the hub's seam crosses has one or two more
    double angleDeg = 0;  // angle of the camber-line start about the axis
};

struct ImpellerTruth {
    int bladeCount = 0;
    int hub = 0, bore = 0, rim = 0;
    std::vector<int> planes;          // nose top and back face (a pump impeller: the back face only)
    std::vector<BladeTruth> blades;   // in angular order: main 0, splitter 0, main 1, ...
    int seamBlade = -1;               // the blade (index into blades) whose root the hub's seam splits
    double boreDiameter = 0, boreDepth = 0, filletRadius = 0, bladeHeight = 0;
    // The narrowest gap between the side and edge walls of two adjacent blades, by OCCT's
    // distance between the blades' wall faces.
    double minChannelWidth = 0;
};

struct Impeller {
    TopoDS_Shape shape;
    ImpellerTruth truth;
};

// Throws aeronc::inputError for inconsistent sizes (blades off the hub, bore through the blades...)
// and geometryError when OCCT fails to build it.
Impeller makeImpeller(const ImpellerSpec& spec);

std::string truthToJson(const ImpellerTruth& truth);

// A spec from JSON text whose keys are the field names above (missing keys keep their default);
// "" is the default spec. Throws aeronc::inputError for unknown keys and values of the wrong type.
ImpellerSpec impellerSpecFromJson(const std::string& text);

}  // namespace aeronc::testparts
