#pragma once
// The extra radial offset that keeps a cutter on a pocket floor out of the floor fillet's
// allowance layer.
//
// In the plane normal to the wall (x from the wall, z up from the floor), the fillet of radius
// rf is the arc about (rf, rf). A cutter of corner radius rc with its axis at R + a + e from
// the wall and its tip at the floor plus the axial allowance holds its corner arc about
// (a + e + rc, axial + rc). Grown by the radial allowance a all round and lifted to the tip
// height (the allowance layer the verification checks), that arc is about (a + e + rc, a + rc)
// with radius rc + a, and it stays inside the fillet's circle when
//     sqrt((rf - a - rc - e)^2 + (rf - a - rc)^2) + rc + a <= rf,
// that is, with d = rf - (rc + a): sqrt((d - e)^2 + d^2) <= d, which holds for e = d only. So
//     e = max(0, rf - (rc + a)).
namespace aeronc::toolpath {

// e above; 0 for no fillet. Throws aeronc::inputError for a negative or non-finite radius.
double floorFilletOffset(double floorFilletRadius, double cornerRadius, double radialAllowance);

}  // namespace aeronc::toolpath
