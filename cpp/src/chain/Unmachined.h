#pragma once
// What the chain leaves, with the reason (fusing, Fusing.cpp): an element a must-step could not
// machine, attached features no unit cuts (countersinks, chamfers), walls leaning too far for a
// flat end mill along the axis, island tops no floor unit faces. Each face is named once.
#include <aeronc/chain/MachiningChain.h>
#include <aeronc/chain/ProcessTemplate.h>
#include <aeronc/recognition/DomainTree.h>

#include <limits>
#include <map>
#include <set>
#include <string>
#include <vector>

namespace aeronc::chain::detail {

// Fusing state of one element, in template order.
struct ElementState {
    double floorAllowance = std::numeric_limits<double>::infinity();  // left on the floor so far; inf: untouched
    int roughUnit = -1;            // the last pocket unit (its cutter goes before a rest unit)
    bool holeMachined = false;
    bool countersunk = false;         // a chamfer mill cut its countersink
    std::string countersinkWhy;       // why not, when there is one and it was not cut
    bool chamfered = false;           // a chamfer mill cut the chamfer along its outer loop
    std::string chamferWhy;           // the chamfers along its edges: what they are and the mill that would fit
    std::string shortOfFloor;         // roughed only as deep as the crib reaches: why it goes no further
    std::map<StepCode, std::string> gaps;  // why an applicable step made no unit
    std::set<StepCode> steps;              // the steps that made a unit
    int units = 0;
};

// Lists what the units of element e leave, after every step of template t was fused with it.
void listUnmachined(const recognition::DomainElement& e, const ElementState& state, const ProcessTemplate& t,
                    std::vector<Unmachined>& out);

// Lists faces of element e the chain leaves, each face once: a chamfer between two elements is
// named by the first.
void listFaces(const recognition::DomainElement& e, const std::string& reason, const std::vector<int>& faces,
               std::vector<Unmachined>& out);

// Island tops below a pocket's top that no floor unit faces (`faced`: those one does); each named
// once, by the first element that has it.
void listIslandTops(const recognition::DomainTree& tree, const std::set<int>& faced, std::vector<Unmachined>& out);

}  // namespace aeronc::chain::detail
