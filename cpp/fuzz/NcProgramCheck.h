#pragma once
// The oracle of the post harnesses: whatever the input, a program the posts return has only
// printable blocks, and its feed, spindle-speed and peck words are positive, its tool numbers
// not negative (the words that once came out as raw buffer bytes, F0, Q0, T-2147483648).
#include "FuzzCommon.h"

#include <cstdlib>
#include <sstream>
#include <string>

namespace aeronc::fuzz {

inline void checkNcProgram(const std::string& nc) {
    std::istringstream lines(nc);
    std::string line;
    while (std::getline(lines, line)) {
        if (line.empty()) finding("an empty line in the NC program");
        if (line[0] == ';' || line[0] == '(' || line[0] == '%') continue;  // comments, 840D header
        for (const char c : line)
            if (static_cast<unsigned char>(c) < 0x20 || static_cast<unsigned char>(c) > 0x7e)
                finding("a block that is not printable text: " + line);
        std::string unquoted;  // names in quotes (T="...", CYCLE800's record) hold no words
        bool quoted = false;
        for (const char c : line) {
            if (c == '"') quoted = !quoted;
            else if (!quoted) unquoted += c;
        }
        std::istringstream words(unquoted);
        std::string w, previous;
        while (words >> w) {
            const char a = w[0];
            const bool number = w.size() > 1 && (std::isdigit(static_cast<unsigned char>(w[1])) || w[1] == '-' || w[1] == '.');
            if (number && (a == 'F' || a == 'S' || a == 'Q' || a == 'T') && !(a == 'F' && (previous == "G4"))) {
                char* end = nullptr;
                const double v = std::strtod(w.c_str() + 1, &end);
                if (*end != '\0') finding("a word that is not one number: " + w + " in " + line);
                if (a == 'T' ? v < 0 : !(v > 0)) finding("word " + w + " out of range in " + line);
            }
            previous = w;
        }
    }
}

}  // namespace aeronc::fuzz
