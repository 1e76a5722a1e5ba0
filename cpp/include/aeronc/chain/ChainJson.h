#pragma once
// The machining chain as JSON text: what the FreeCAD side builds its Job from, and edits
// (order, tool, enabled) before checkChain() re-runs the rules. docs/machining-chain.md
// lists every field.
#include <aeronc/chain/MachiningChain.h>

#include <string>

namespace aeronc::chain {

std::string toJson(const MachiningChain& chain, int indent = 1);

// The chain toJson wrote: toJson(fromJson(toJson(c))) == toJson(c). Throws aeronc::inputError
// naming the field at fault ("units[3].contour[2]: ...") for text that is not JSON, a missing
// field or one of the wrong type, an unknown step code, operation or rule, and a template that
// fails validateTemplate().
MachiningChain fromJson(const std::string& text);

}  // namespace aeronc::chain
