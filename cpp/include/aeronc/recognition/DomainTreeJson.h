#pragma once
// The machining-domain tree as JSON text. Recognition writes it (the CLI's --json, the Python
// binding's result, the Machining Features group's stored Result); tool selection reads it
// back, so it plans the tree the user saw rather than recognising the part again.
#include <aeronc/recognition/DomainTree.h>

#include <string>

namespace aeronc::recognition {

// JSON text of the tree. A minCornerRadius < 0 (no concave corner) is written as null.
std::string toJson(const DomainTree& tree, int indent = 1);

// The tree toJson wrote: toJson(fromJson(toJson(t))) == toJson(t). Keys toJson does not write
// are ignored. Throws inputError naming the field at fault ("elements[3].contour[2]: ...") for
// text that is not JSON, a missing field or one of the wrong type, an unknown element type or
// face role, an id, setup, parent, child or face number out of range, and a parent/children
// link that the other side does not repeat.
DomainTree fromJson(const std::string& text);

}  // namespace aeronc::recognition
