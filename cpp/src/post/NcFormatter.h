#pragma once
// What both NC dialects share: the walk over the planned steps (an error names the operation
// and move it came from), the dispatch of each step by its kind, the words both write alike
// (comments, spindle, coolant, dwell, stops, the branch-change note), the modal axis, feed and
// motion words, and the feed mode (G93 inverse time or G94). A dialect writes its header and
// footer, work offsets, tool changes, moves and drilling cycles.
#include "NcWriter.h"

#include <aeronc/kinematics/Planner.h>
#include <aeronc/post/NcFormat.h>

#include <string>

namespace aeronc::post {

class NcFormatter {
public:
    virtual ~NcFormatter() = default;

    // The whole program: header, every planned step, footer.
    std::string run();

protected:
    // dwellWord: the address that takes the dwell in seconds.
    NcFormatter(const kinematics::Plan& plan, const NcOptions& options, bool semicolonComments, const char* dwellWord);

    virtual void header() = 0;
    virtual void footer() = 0;
    // Before every step, whatever its kind.
    virtual void beforeStep(const kinematics::PlannedStep&) {}
    // Writes the operation's label as a comment.
    virtual void operation(const kinematics::ClRecord& r);
    virtual void workOffset(const kinematics::ClRecord& r) = 0;
    virtual void loadTool(const kinematics::ClRecord& r) = 0;
    virtual void move(const kinematics::PlannedStep& s) = 0;
    virtual void cycle(const kinematics::PlannedStep& s, const kinematics::ClRecord& r) = 0;

    // "<name>: posted by AeroNC for machine <machine> (<kinematics> <axes>, <controller>)"
    std::string postedBy(const std::string& name, const std::string& controller) const;
    // G0 G1 G2 G3, written when it changes.
    void motionWord(kinematics::Motion m);
    // G93 inverse time (F = 1/minutes) on feed moves that turn a rotary axis, when asked for,
    // else G94; the mode word goes first in the block, F last.
    void feedMode(const kinematics::PlannedStep& s);
    // The checks of the numbers that reach a word; each throws inputError saying what is wrong,
    // run() adds the line. `decimals`: as the word is written, so that nothing becomes 0 there.
    // A feed in mm/min: positive, within the machine's maxFeed and the word's range.
    void checkFeed(double mmPerMin, int decimals) const;
    // Any other value: finite, positive (or, with positive false, not negative) once written,
    // below kMaxNcValue.
    void checkValue(const char* what, double v, const char* unit, int decimals, bool positive) const;
    // Back to G94, as drilling cycles need.
    void unitsPerMinute();
    void forgetModal();
    void stopSpindleAndCoolant();

    const kinematics::Plan& plan_;
    const kinematics::ClProgram& prog_;
    const kinematics::MachineModel& m_;
    const NcOptions& o_;
    NcWriter w_;
    bool coolant_ = false;
    bool inverse_ = false;
    Modal x_, y_, z_, a_[2], f_, g_;

private:
    void step(const kinematics::PlannedStep& s, const kinematics::ClRecord& r);
    void spindle(const kinematics::ClRecord& r);
    void checkCycle(const kinematics::ClRecord& r) const;

    const char* dwellWord_;
};

std::string formatSinumerik(const kinematics::Plan& plan, const NcOptions& options);
std::string formatLinuxCnc(const kinematics::Plan& plan, const NcOptions& options);

}  // namespace aeronc::post
