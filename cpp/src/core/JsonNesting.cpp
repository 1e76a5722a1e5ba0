#include <aeronc/core/Error.h>
#include <aeronc/core/JsonNesting.h>

namespace aeronc {

int jsonNesting(std::string_view text, int limit) {
    int depth = 0, deepest = 0;
    bool inString = false;
    for (size_t i = 0; i < text.size(); ++i) {
        const char c = text[i];
        if (inString) {
            if (c == '\\') ++i;
            else if (c == '"') inString = false;
            continue;
        }
        if (c == '"') {
            inString = true;
        } else if (c == '[' || c == '{') {
            if (++depth > deepest && (deepest = depth) > limit) return deepest;
        } else if ((c == ']' || c == '}') && depth > 0) {
            --depth;
        }
    }
    return deepest;
}

void checkJsonNesting(std::string_view text, const std::string& what) {
    if (jsonNesting(text) > kMaxJsonNesting)
        throw inputError(what + ": JSON nested deeper than " + std::to_string(kMaxJsonNesting) + " levels");
}

}  // namespace aeronc
