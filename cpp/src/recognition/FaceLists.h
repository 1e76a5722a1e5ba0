#pragma once
// Lists of face numbers, kept in the order found and without repeats.
#include <algorithm>
#include <vector>

namespace aeronc::recognition {

// Appends x unless it is already there or negative (no face).
inline void pushUnique(std::vector<int>& v, int x) {
    if (x >= 0 && std::find(v.begin(), v.end(), x) == v.end()) v.push_back(x);
}

}  // namespace aeronc::recognition
