#pragma once
// The patent's construction rules on a machining chain, each failure naming the node at
// fault ("setup +Z / process 3 (EM-F10) / step fs / unit 41 (element 16)"):
//   priority   within a setup the steps follow the template's step order;
//   existence  each element has a unit of every must-step machining its feature type (unless
//              the chain lists why not), and no unit belongs to a must_not step;
//   validity   along the units machining one element, tool diameters, radial and axial
//              allowances do not grow;
//   removal    every unit removes material: no earlier unit on the element already cut as
//              far with a tool reaching as far, and a rest unit reaches what its predecessor
//              could not;
//   fit        each unit's tool suits its element (reach, corner and floor radii, drill size).
#include <aeronc/chain/MachiningChain.h>

#include <vector>

namespace aeronc::chain {

// One entry per failure, and one "ok" entry per rule that holds everywhere.
std::vector<RuleCheck> checkRules(const MachiningChain& chain);

// The seven-level tree from the order: in each setup a process is a run of units with one
// tool, a step a run of one step code within it (one program each). Numbers the tools in
// order of first use and sets each unit's order and tool number.
void arrange(MachiningChain& chain);

// After edits (order, tool, enabled): checks the order lists every unit once, takes each
// unit's cutter, cutting data, step-down and step-over from the chain's tool list (and a rest
// unit's previous cutter from the unit before it), rearranges the tree, recomputes the
// travel of the order, and re-runs the rules. Throws aeronc::inputError for an order that is
// not a permutation of the units.
MachiningChain checkChain(MachiningChain chain);

}  // namespace aeronc::chain
