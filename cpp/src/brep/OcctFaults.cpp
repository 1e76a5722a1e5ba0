// OCC_CATCH_SIGNALS jumps only when this file is built with OCC_CONVERT_SIGNALS, as OCCT itself is.
#ifndef OCC_CONVERT_SIGNALS
#define OCC_CONVERT_SIGNALS
#endif
#include <aeronc/brep/OcctFaults.h>
#include <aeronc/core/Error.h>

#include <OSD.hxx>
#include <Standard_ErrorHandler.hxx>
#include <Standard_Failure.hxx>

#include <cfenv>
#include <csignal>
#include <memory>

namespace aeronc {

namespace {

constexpr int kFaults[] = {SIGSEGV, SIGBUS, SIGFPE, SIGILL, SIGSYS};
// OSD::SetSignal takes these as well; they keep the handlers they had (Ctrl-C stays Ctrl-C).
constexpr int kOthers[] = {SIGHUP, SIGINT, SIGQUIT};

// A damaged B-rep can send OCCT's approximation into endless recursion: the stack overflows,
// and a handler running on that stack would fault again. The handlers run on a stack of
// their own.
constexpr size_t kHandlerStack = 256 * 1024;

// The handlers, signal stack and floating-point environment in force before, put back on
// destruction.
class SavedHandlers {
public:
    SavedHandlers() : stack_(new char[kHandlerStack]) {
        for (size_t i = 0; i < std::size(kFaults); ++i) sigaction(kFaults[i], nullptr, &old_[i]);
        for (size_t i = 0; i < std::size(kOthers); ++i) sigaction(kOthers[i], nullptr, &others_[i]);
        fegetenv(&fenv_);
        stack_t own{};
        own.ss_sp = stack_.get();
        own.ss_size = kHandlerStack;
        hasStack_ = sigaltstack(&own, &oldStack_) == 0;
    }
    ~SavedHandlers() {
        for (size_t i = 0; i < std::size(kFaults); ++i) sigaction(kFaults[i], &old_[i], nullptr);
        keepOthers();
        if (hasStack_) sigaltstack(&oldStack_, nullptr);
        fesetenv(&fenv_);
    }
    SavedHandlers(const SavedHandlers&) = delete;
    SavedHandlers& operator=(const SavedHandlers&) = delete;

    void keepOthers() const {
        for (size_t i = 0; i < std::size(kOthers); ++i) sigaction(kOthers[i], &others_[i], nullptr);
    }
    // OSD::SetSignal's handlers, moved onto the signal stack.
    void useSignalStack() const {
        if (!hasStack_) return;
        for (const int sig : kFaults) {
            struct sigaction a;
            if (sigaction(sig, nullptr, &a) == 0) {
                a.sa_flags |= SA_ONSTACK;
                sigaction(sig, &a, nullptr);
            }
        }
    }

private:
    std::unique_ptr<char[]> stack_;
    struct sigaction old_[std::size(kFaults)];
    struct sigaction others_[std::size(kOthers)];
    stack_t oldStack_{};
    bool hasStack_ = false;
    fenv_t fenv_;
};

void runWithJumpPoint(const std::function<void()>& f) {
    OCC_CATCH_SIGNALS
    f();
}

}  // namespace

void runCatchingOcctFaults(const std::function<void()>& f, const std::string& what) {
    const SavedHandlers saved;
    OSD::SetSignal(OSD_SignalMode_Set, Standard_False);
    saved.keepOthers();
    saved.useSignalStack();
    try {
        runWithJumpPoint(f);
    } catch (const Standard_Failure& e) {
        // Signals arrive as OSD_Signal subclasses (OSD_SIGSEGV, ...), with the signal named in
        // the message; any other OCCT exception f let through is reported the same way.
        const char* message = e.GetMessageString();
        throw inputError(what + ": OpenCASCADE failed (" + e.DynamicType()->Name() +
                         (message && *message ? std::string(": ") + message : std::string()) +
                         "); the file or shape is probably damaged");
    }
}

}  // namespace aeronc
