#pragma once
// The simulation report as JSON (the contract of docs/verification.md).
#include <aeronc/verify/Simulation.h>

#include <nlohmann/json.hpp>

namespace aeronc::verify {

nlohmann::json toJson(const SimulationReport& report);

// Options from JSON ("gougeTolerance", "collisionTolerance", "floorTolerance",
// "wallTolerance", "wallSearch", "wallBand", "leftoverMap", "maxListed"; "deflection" and
// "angularDeflection" are the mesher's, left to the caller). Throws aeronc::Error (input) for an
// unknown key or a value of the wrong type or out of range.
SimulationOptions simulationOptionsFromJson(const nlohmann::json& j);

}  // namespace aeronc::verify
