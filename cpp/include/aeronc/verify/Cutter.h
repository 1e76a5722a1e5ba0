#pragma once
// The cutting end of a milling cutter, rotationally symmetric about the tool axis: flat end
// (cornerRadius 0), bull nose (0 < cornerRadius < radius) or ball (cornerRadius = radius).

namespace aeronc::verify {

struct Cutter {
    double radius = 0;
    double cornerRadius = 0;

    // Throws aeronc::Error (input) for a diameter that is not positive or a corner radius outside
    // [0, diameter / 2].
    static Cutter fromDiameter(double diameter, double cornerRadius);

    // Height of the cutter's lower surface above its tip at radial distance r (0 <= r <= radius).
    double height(double r) const;
    // d height / dr: 0 on the flat part, growing without bound at the rim of a rounded corner.
    double slope(double r) const;
    // d slope / dr.
    double curvature(double r) const;
    // The profile of the cutter grown by an allowance a all round: radius + a, corner radius + a
    // (with its tip lowered by a, the Minkowski sum with a ball of radius a). Negative a shrinks it.
    Cutter grownBy(double a) const;
};

}  // namespace aeronc::verify
