#pragma once
// The spindle speed that gives a cutting speed on a cutter: n = 1000·v_c/(π·D). Tool planning,
// the machining chain's cutting data, the optimiser and the impeller program all take n from here.
namespace aeronc {

// r/min for a cutting speed v_c in m/min on a cutter of diameter D in mm.
inline double spindleSpeed(double cuttingSpeed, double diameter) {
    return 1000.0 * cuttingSpeed / (3.14159265358979323846 * diameter);
}

// The inverse: v_c in m/min of a cutter of diameter D in mm at n r/min.
inline double cuttingSpeed(double spindleRpm, double diameter) {
    return 3.14159265358979323846 * diameter * spindleRpm / 1000.0;
}

}  // namespace aeronc
