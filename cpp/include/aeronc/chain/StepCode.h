#pragma once
// The vocabulary of process plans (DESIGN.md §3, the patent's construction rules): step codes,
// whether a step must exist, the tool a step takes, and the operation a machining unit is.
#include <optional>
#include <string>
#include <vector>

namespace aeronc::chain {

// WS_r, WS_w, WS_c, WS_ss, WS_sf, WS_fs, WS_ff, WS_t, plus drilling and hole milling, and the
// edges: chamfers and countersinks cut with a chamfer mill. A template need not name the edge
// step: absent from its step order it comes after every other step (ProcessTemplate::rank).
enum class StepCode { Rough, Web, Corner, SemiWall, SemiFlange, FinishWall, FinishFlange, CutOff, Drill, HoleMill, Edge };

const char* toString(StepCode c);  // "r", "w", "c", "ss", "sf", "fs", "ff", "t", "d", "h", "e"
const char* describe(StepCode c);  // "rough the inner and outer shape", ...
std::optional<StepCode> stepCodeFrom(const std::string& text);
const std::vector<StepCode>& allStepCodes();
// Throws aeronc::inputError "<where>: unknown step code 'x' (known: r, w, ...)".
StepCode parseStepCode(const std::string& text, const std::string& where);
// Space-separated codes, each checked; throws naming `where` for an unknown or repeated one.
std::vector<StepCode> parseStepCodes(const std::string& text, const std::string& where);
std::string joinCodes(const std::vector<StepCode>& codes);  // "r w c ss"

enum class Existence { Must, May, MustNot };
const char* toString(Existence e);  // "must", "may", "must_not"
Existence parseExistence(const std::string& text, const std::string& where);

// Which of the element's planned tools a step uses.
enum class ToolRole { None, Roughing, Finishing, Corner, Drilling };
const char* toString(ToolRole r);  // "", "roughing", "finishing", "corner", "drilling"
ToolRole parseToolRole(const std::string& text, const std::string& where);  // "" or NULL: None

// What a unit asks of the toolpath generator.
enum class Operation { Pocket, Profile, Drill, Helix, Rest, Chamfer };
const char* toString(Operation o);  // "pocket", "profile", "drill", "helix", "rest", "chamfer"
Operation parseOperation(const std::string& text, const std::string& where);

// Feature types a template step machines: the recognised element types, and "flange" for a
// pocket that carries a flange (its walls are the flange steps' work, not the wall steps').
const std::vector<std::string>& featureTypes();
bool isFeatureType(const std::string& name);

}  // namespace aeronc::chain
