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
    double reach = 0;  // holder reach below the holder; at least the flute length
    int flutes = 0;

    double radius() const { return 0.5 * diameter; }
    // The depth a tool can cut: the flutes and the holder both limit it.
    double usableLength() const { return fluteLength < reach ? fluteLength : reach; }
    // Flat, bull and ball end mills cut pocket walls and floors; drills and face mills do not.
    bool isEndMill() const { return type == "flat" || type == "bull" || type == "ball"; }

    // Throws aeronc::inputError naming the tool when a dimension is impossible.
    void validate() const;
};

}  // namespace aeronc::toolselect
