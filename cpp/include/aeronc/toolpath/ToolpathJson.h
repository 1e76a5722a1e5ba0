#pragma once
// One machining unit as JSON text in, its toolpath as JSON text out (docs/toolpaths.md):
//   in:  {"operation": "pocket" | "profile" | "helix" | "drill" | "rest", "cutter": {...}, ...}
//   out: {"moves": [[kind, u, v, h] or [3, u, v, h, r, q, dwell], ...], "cutLength", "rapidLength"}
// with kind 0 rapid, 1 feed, 2 plunge, 3 drill cycle.
#include <aeronc/toolpath/Toolpath.h>

#include <string>

namespace aeronc::toolpath {

// Throws aeronc::inputError, naming the unit when it has a "name", on malformed JSON, unknown
// keys and everything the operations refuse.
std::string toolpathJson(const std::string& unitJson);

std::string toJson(const Toolpath& toolpath);

}  // namespace aeronc::toolpath
