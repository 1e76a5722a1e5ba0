#pragma once
// Checks of the holes shared by drilling and helical hole milling.
#include <aeronc/toolpath/Hole.h>

namespace aeronc::toolpath {

// Throws aeronc::inputError naming the hole (1-based) on non-finite or inverted values.
void checkHoles(const std::vector<Hole>& holes);

}  // namespace aeronc::toolpath
