// The dialect-independent part of the NC formatters (see NcFormatter.h).
#include "NcFormatter.h"

#include <aeronc/core/Error.h>

namespace aeronc::post {

using namespace kinematics;

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
            loadTool(r);
            return;
        case ClKind::Spindle:
            w_.spindle(r.rpm, r.spindleDir);
            return;
        case ClKind::Coolant:
            coolant_ = w_.coolant(r.text);
            return;
        case ClKind::Dwell:
            w_.value(dwellWord_, r.seconds, 3);
            w_.end();
            return;
        case ClKind::Stop:
            w_.line(r.text);
            return;
        case ClKind::Move:
            move(s);
            if (o_.comments && s.origin == MoveOrigin::Reposition)
                w_.comment("branch change: retracted, repositioned, re-entering");
            return;
        case ClKind::Cycle:
            cycle(s, r);
            return;
    }
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
