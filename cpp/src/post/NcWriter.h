#pragma once
// Block-by-block NC text: optional N numbers, comments in the dialect's form, and modal words
// that are written only when their formatted value changes.
#include <aeronc/post/NcFormat.h>

#include <string>
#include <string_view>

namespace aeronc::post {

// The last value written for one address; `valid` is false after anything that may have
// changed the controller's idea of it (a new plane, TRAORI, a tool change).
struct Modal {
    std::string last;
    bool valid = false;
    void forget() { valid = false; }
};

class NcWriter {
public:
    NcWriter(bool lineNumbers, bool semicolonComments) : numbers_(lineNumbers), semicolon_(semicolonComments) {}

    std::string& text() { return out_; }

    void word(std::string_view w) {
        if (!block_.empty()) block_ += ' ';
        block_ += w;
    }
    // Writes address+value, or nothing when it equals the last value of `m` (modal words).
    void modal(std::string_view address, double v, int decimals, Modal& m) {
        num_.clear();
        appendNumber(num_, v, decimals);
        if (m.valid && m.last == num_) return;
        m.last = num_;
        m.valid = true;
        if (!block_.empty()) block_ += ' ';
        block_ += address;
        block_ += num_;
    }
    // Writes address+value always (non-modal words: I J, inverse-time F).
    void value(std::string_view address, double v, int decimals) {
        if (!block_.empty()) block_ += ' ';
        block_ += address;
        appendNumber(block_, v, decimals);
    }
    // Spindle and coolant words are the same M codes in both dialects (DIN 66025). The caller
    // checks the speed (NcFormatter::spindle).
    void spindle(double rpm, int direction) {
        if (direction == 0) {
            line("M5");
            return;
        }
        value("S", rpm, 0);
        word(direction > 0 ? "M3" : "M4");
        end();
    }
    // Returns whether coolant is now on.
    bool coolant(const std::string& mode) {
        line(mode == "flood" ? "M8" : mode == "mist" ? "M7" : "M9");
        return mode != "off";
    }
    bool empty() const { return block_.empty(); }
    void end() {
        if (block_.empty()) return;
        if (numbers_) {
            out_ += 'N';
            appendNumber(out_, n_, 0);
            out_ += ' ';
            n_ += 10;
        }
        out_ += block_;
        out_ += '\n';
        block_.clear();
    }
    void line(std::string_view block) {
        word(block);
        end();
    }
    // A line break inside a comment would start a block of its own: control characters become
    // spaces.
    void comment(std::string_view text) {
        end();
        out_ += semicolon_ ? "; " : "(";
        for (char c : text) {
            if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) c = ' ';
            else if (!semicolon_ && c == '(') c = '[';  // no nesting in LinuxCNC comments
            else if (!semicolon_ && c == ')') c = ']';
            out_ += c;
        }
        if (!semicolon_) out_ += ')';
        out_ += '\n';
    }
    void raw(std::string_view text) {
        end();
        out_ += text;
        out_ += '\n';
    }

private:
    bool numbers_;
    bool semicolon_;
    double n_ = 10;
    std::string out_, block_, num_;
};

}  // namespace aeronc::post
