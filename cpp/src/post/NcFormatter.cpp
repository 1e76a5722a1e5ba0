// The dialect-independent part of the NC formatters (see NcFormatter.h).
#include "NcFormatter.h"

#include <aeronc/core/Error.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace aeronc::post {

using namespace kinematics;

namespace {

std::string num(double v) {
    char b[64];
    std::snprintf(b, sizeof b, "%g", v);
    return b;
}

// Whether a non-negative v is written as 0 with `decimals` decimals.
bool writtenAsZero(double v, int decimals) {
    static constexpr double kScale[16] = {1,    1e1,  1e2,  1e3,  1e4,  1e5,  1e6,  1e7,
                                          1e8,  1e9,  1e10, 1e11, 1e12, 1e13, 1e14, 1e15};
    return std::round(v * kScale[std::clamp(decimals, 0, 15)]) < 1;
}

// The S word is an integer; LinuxCNC and the 840D read it into 32 bits.
constexpr double kMaxSpindleWord = 2147483647.0;

}  // namespace

NcFormatter::NcFormatter(const Plan& plan, const NcOptions& o, bool semicolonComments, const char* dwellWord)
    : plan_(plan), prog_(*plan.program), m_(plan.machine), o_(o), w_(o.lineNumbers, semicolonComments),
      dwellWord_(dwellWord) {}

std::string NcFormatter::run() {
    header();
    for (const auto& s : plan_.steps) {
        const ClRecord& r = prog_.records[s.record];
        try {
            step(s, r);
        } catch (const Error& e) {
            throw inputError(prog_.where(r) + ": " + e.what());
        }
    }
    footer();
    return std::move(w_.text());
}

void NcFormatter::step(const PlannedStep& s, const ClRecord& r) {
    beforeStep(s);
    switch (s.kind) {
        case ClKind::Comment:
            if (o_.comments && !r.text.empty()) w_.comment(r.text);
            return;
        case ClKind::Operation:
            operation(r);
            return;
        case ClKind::WorkOffset:
            workOffset(r);
            return;
        case ClKind::LoadTool:
            if (r.tool.number < 0) throw inputError("tool number " + std::to_string(r.tool.number) + " is negative");
            loadTool(r);
            return;
        case ClKind::Spindle:
            spindle(r);
            return;
        case ClKind::Coolant:
            coolant_ = w_.coolant(r.text);
            return;
        case ClKind::Dwell:
            checkValue("dwell", r.seconds, "s", 3, false);
            w_.value(dwellWord_, r.seconds, 3);
            w_.end();
            return;
        case ClKind::Stop:
            w_.line(r.text);
            return;
        case ClKind::Move:
            if (s.motion != Motion::Rapid) checkFeed(s.feed, 3);
            move(s);
            if (o_.comments && s.origin == MoveOrigin::Reposition)
                w_.comment("branch change: retracted, repositioned, re-entering");
            return;
        case ClKind::Cycle:
            checkCycle(r);
            cycle(s, r);
            return;
    }
}

void NcFormatter::spindle(const ClRecord& r) {
    if (r.spindleDir == 0) {
        w_.line("M5");
        return;
    }
    // A speed the optimiser or the knowledge base capped at the limit may sit a rounding error
    // above it; the word written is the same.
    if (m_.maxSpindleSpeed && r.rpm > *m_.maxSpindleSpeed * (1 + 1e-9))
        throw inputError("spindle speed " + num(r.rpm) + " r/min exceeds the machine's maximum spindle speed " +
                         num(*m_.maxSpindleSpeed) + " r/min");
    checkValue("spindle speed", r.rpm, "r/min", 0, true);
    if (r.rpm > kMaxSpindleWord) throw inputError("spindle speed " + num(r.rpm) + " r/min does not fit the S word");
    w_.spindle(r.rpm, r.spindleDir);
}

void NcFormatter::checkCycle(const ClRecord& r) const {
    checkFeed(r.feed, 3);
    checkValue("the hole's feed depth (R level to bottom)", r.retract, "mm", o_.precision, true);
    checkValue("the hole's return level above the bottom", r.clearance, "mm", o_.precision, true);
    if (r.cycle == CycleKind::Peck || r.cycle == CycleKind::ChipBreak)
        checkValue("peck depth", r.peck, "mm", o_.precision, true);
    checkValue("dwell", r.seconds, "s", 3, false);
}

void NcFormatter::checkFeed(double f, int decimals) const {
    if (m_.maxFeed && f > *m_.maxFeed * (1 + 1e-9))
        throw inputError("feed " + num(f) + " mm/min exceeds the machine's maximum feed " + num(*m_.maxFeed) + " mm/min");
    checkValue("feed", f, "mm/min", decimals, true);
}

void NcFormatter::checkValue(const char* what, double v, const char* unit, int decimals, bool positive) const {
    const std::string named = std::string(what) + " " + num(v) + " " + unit;
    if (!std::isfinite(v)) throw inputError(std::string(what) + " is not a finite number");
    if (positive && (v <= 0 || writtenAsZero(v, decimals)))
        throw inputError(named + " must be positive" +
                         (v > 0 ? " (it is written as 0 with " + std::to_string(decimals) + " decimals)" : ""));
    if (!positive && v < 0) throw inputError(named + " must not be negative");
    if (std::abs(v) >= kMaxNcValue) throw inputError(named + " does not fit an NC word (below 1e9)");
}

void NcFormatter::operation(const ClRecord& r) {
    if (o_.comments) w_.comment("operation: " + r.text);
}

std::string NcFormatter::postedBy(const std::string& name, const std::string& controller) const {
    return name + ": posted by AeroNC for machine " + m_.name + " (" + m_.kinematicsName() + " " + m_.rotary[0].name +
           "/" + m_.rotary[1].name + ", " + controller + ")";
}

void NcFormatter::motionWord(Motion m) {
    static const char* words[] = {"G0", "G1", "G2", "G3"};
    const char* g = words[static_cast<int>(m)];
    if (!g_.valid || g_.last != g) w_.word(g);
    g_.last = g;
    g_.valid = true;
}

void NcFormatter::feedMode(const PlannedStep& s) {
    if (s.motion == Motion::Rapid) return;
    const bool inv = o_.inverseTime && s.rotaryMoved && s.minutes > 0;
    if (inv != inverse_) w_.word(inv ? "G93" : "G94"), f_.forget();
    inverse_ = inv;
}

void NcFormatter::unitsPerMinute() {
    if (inverse_) w_.word("G94"), f_.forget();
    inverse_ = false;
}

void NcFormatter::forgetModal() {
    for (auto* m : {&x_, &y_, &z_, &a_[0], &a_[1], &f_, &g_}) m->forget();
}

void NcFormatter::stopSpindleAndCoolant() {
    w_.line("M5");
    if (coolant_) w_.line("M9");
}

std::string formatNc(const Plan& plan, const NcOptions& o) {
    return o.dialect == Dialect::LinuxCnc ? formatLinuxCnc(plan, o) : formatSinumerik(plan, o);
}

}  // namespace aeronc::post
