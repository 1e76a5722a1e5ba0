#pragma once
// A cutting tool as the selector sees it: dimensions only, no database, no FreeCAD.
#include <string>

namespace aeronc::toolselect {

struct Tool {
    std::string id;
    std::string type;  // "flat", "bull", "ball", "drill", "face"; "other": kept for FreeCAD, never chosen
    std::string material;
    double diameter = 0;
    double cornerRadius = 0;  // a ball's is its radius
    double fluteLength = 0;
    double reach = 0;  // length below the holder no wider than the cutter; at least the flute length
    double neckDiameter = 0;  // a necked (long-reach) tool's relieved neck, below the diameter; 0: no neck
    int flutes = 0;

    double radius() const { return 0.5 * diameter; }
    bool necked() const { return neckDiameter > 0; }
    // The depth a tool can cut. Without a neck the shank behind the flutes is as wide as the
    // cutter and would rub a wall it finished, so the flutes limit it too; a necked tool's neck
    // clears the wall, so it goes as deep as its reach, the flutes cutting one layer at a time.
    double usableLength() const { return necked() || fluteLength >= reach ? reach : fluteLength; }
    // The highest wall a tool cuts in one pass: the flutes' length.
    double passHeight() const { return fluteLength; }
    // Flat, bull and ball end mills cut pocket walls and floors; drills and face mills do not.
    bool isEndMill() const { return type == "flat" || type == "bull" || type == "ball"; }

    // Throws aeronc::inputError naming the tool when a dimension is impossible.
    void validate() const;
};

}  // namespace aeronc::toolselect
