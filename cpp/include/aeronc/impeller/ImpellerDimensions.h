#pragma once
// Dimension analysis of a recognised impeller: the sizes that drive the choice of the ball or
// tapered ball end mill (impeller paper §2).
#include <aeronc/impeller/ImpellerFeatures.h>

#include <TopoDS_Shape.hxx>

#include <vector>

namespace aeronc::impeller {

// One station along a channel (a band of radius about the axis): how deep the channel is there
// (the walls' extent along the axis) and its narrowest width there (wall to the next blade's).
struct ChannelStation {
    double radius = 0, depth = 0, width = 0;
};

struct ImpellerDimensions {
    double boreDiameter = 0, boreDepth = 0;   // 0 when there is no bore
    // Narrowest gap between the walls (pressure, suction and edge rounds) of two adjacent
    // blades, over both channel kinds (main to splitter, splitter to main), by OCCT's distance.
    double minChannelWidth = 0;
    int channelBlades[2] = {0, 0};            // the adjacent pair where it occurs (blade indices)
    double minChannelDepth = 0;               // how deep the channel is where that gap is
    // Stations along both channel kinds. Where blades run in to a nose they may stand a fraction
    // of a millimetre tall in a gap narrower than any tool: that gap does not limit a tool.
    std::vector<ChannelStation> channelProfile;
    double filletRadius = 0;                  // root fillet radius (0 when there are no fillets)
    double bladeHeight = 0;                   // shroud above the hub along the axis, main blade
    double splitterHeight = 0;                // the same for a splitter (0 without splitters)
    double outerRadius = 0;                   // largest radius of the part about the axis
    double axialLength = 0;                   // extent of the part along the axis

    // The narrowest width where the channel is at least `depth` deep (a ball of radius R needs
    // channelWidth(R)); a depth beyond the deepest station is taken as the deepest. Without a
    // profile, minChannelWidth.
    double channelWidth(double depth) const;
};

ImpellerDimensions measureImpeller(const TopoDS_Shape& shape, const ImpellerFeatures& features);

// Features and dimensions as one JSON document (docs/impeller.md describes it).
std::string impellerToJson(const ImpellerFeatures& features, const ImpellerDimensions& dimensions);

}  // namespace aeronc::impeller
