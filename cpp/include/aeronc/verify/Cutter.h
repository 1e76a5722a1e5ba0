#pragma once
// The cutting end of a milling cutter, rotationally symmetric about the tool axis: flat end
// (cornerRadius 0), bull nose (0 < cornerRadius < radius) or ball (cornerRadius = radius), or a
// chamfer mill: a flat tip of radius tipRadius, then a cone rising coneSlope mm per mm of radius
// up to the cutter's radius (coneSlope > 0, cornerRadius 0).

namespace aeronc::verify {

struct Cutter {
    double radius = 0;
    double cornerRadius = 0;
    double tipRadius = 0;  // chamfer mill: radius of its flat tip
    double coneSlope = 0;  // chamfer mill: 1 / tan(half the included angle); 0: not a cone

    // Throws aeronc::Error (input) for a diameter that is not positive or a corner radius outside
    // [0, diameter / 2].
    static Cutter fromDiameter(double diameter, double cornerRadius);
    // A chamfer mill of largest diameter `diameter`, tip diameter `tipDiameter` and included
    // angle `includedAngle` degrees (90: a 45 degree chamfer). Throws aeronc::Error (input) for a
    // tip not below the diameter or an angle outside (0, 180).
    static Cutter cone(double diameter, double tipDiameter, double includedAngle);
    bool isCone() const { return coneSlope > 0; }

    // Height of the cutter's lower surface above its tip at radial distance r (0 <= r <= radius).
    double height(double r) const;
    // d height / dr: 0 on the flat part, growing without bound at the rim of a rounded corner.
    double slope(double r) const;
    // d slope / dr.
    double curvature(double r) const;
    // The profile of the cutter grown by an allowance a all round: radius + a, corner radius + a
    // (with its tip lowered by a, the Minkowski sum with a ball of radius a). Negative a shrinks it.
    // A cone moves out by a sideways: radius + a, tip radius + a, the same slope.
    Cutter grownBy(double a) const;
};

}  // namespace aeronc::verify
