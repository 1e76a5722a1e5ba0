#pragma once
// Sequencing (integral-panel paper §2.4) and rapid-travel optimisation within its constraints.
//
// Within a setup the units follow the template's step order. The template's sequencing rules
// then apply in priority order: a key rule (process_order, outer_before_inner,
// feature_type_order) splits the units into ordered groups; the relational rule
// (higher_z_first) makes a parent's unit precede its child's in the same step. A rule never
// overrides one of higher priority: a lower key rule raises a child's key to its parent's
// rather than send the child first. Within the groups, centre_out orders from the setup's
// centre outwards (the rules-only order); the optimiser then shortens the rapid travel with
// nearest neighbour, 2-opt and Or-opt, never breaking a precedence.
#include <aeronc/chain/MachiningChain.h>

#include <optional>
#include <vector>

namespace aeronc::chain {

// Sets chain.order (every unit once, setup by setup, disabled units last in their setup) and
// chain.travel (rules-only and optimised). Without `optimise` the rules-only order is kept.
void sequence(MachiningChain& chain, bool optimise = true);

// Rapid travel of an order: the distance between the reference points (MachiningUnit::at) of
// consecutive enabled units of the same setup, mm.
double travelOf(const MachiningChain& chain, const std::vector<int>& order);

// An open path through points, some of which must come after others.
struct PathProblem {
    std::vector<Point2> points;
    std::vector<std::vector<int>> predecessors;  // indices that must come before each point
    std::optional<Point2> start;                 // where the path comes from, if anywhere
};
double pathLength(const PathProblem& p, const std::vector<int>& path);
bool respectsPrecedence(const PathProblem& p, const std::vector<int>& path);
// The nearest ready point next, from the start (or from `first` when there is no start).
std::vector<int> nearestNeighbour(const PathProblem& p, int first = -1);
// 2-opt and Or-opt moves that shorten the path and keep every precedence, until none is left.
// Never lengthens the path. `path` must respect the precedences.
void improvePath(const PathProblem& p, std::vector<int>& path);

}  // namespace aeronc::chain
