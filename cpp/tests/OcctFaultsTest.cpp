// Faults inside a guarded call become errors, and the process's own handlers are back after.
#include <aeronc/brep/OcctFaults.h>

#include "ErrorOf.h"

#include <gtest/gtest.h>

#include <csignal>
#include <cstring>

using aeronc::runCatchingOcctFaults;
using aeronc::test::inputErrorOf;

namespace {

int g_marker = 0;
void ownHandler(int) { g_marker = 1; }

// Recursion without end, as OCCT's approximation once did on a damaged curve.
int bottomless(volatile int depth) {
    volatile char frame[512];
    frame[0] = static_cast<char>(depth);
    return bottomless(depth + 1) + frame[0];
}

}  // namespace

TEST(OcctFaults, SignalsBecomeErrorsNamingTheInput) {
    for (const int sig : {SIGSEGV, SIGFPE, SIGBUS, SIGILL}) {
        const std::string e = inputErrorOf([&] { runCatchingOcctFaults([&] { std::raise(sig); }, "part.step"); });
        EXPECT_EQ(e.rfind("part.step: OpenCASCADE failed (", 0), 0u) << e;
        EXPECT_NE(e.find("damaged"), std::string::npos) << e;
    }
}

TEST(OcctFaults, ANullDereferenceBecomesAnError) {
    volatile int* nothing = nullptr;
    const std::string e = inputErrorOf([&] { runCatchingOcctFaults([&] { *nothing = 1; }, "shape"); });
    EXPECT_NE(e.find("OpenCASCADE failed"), std::string::npos) << e;
}

#if !defined(__SANITIZE_ADDRESS__)
TEST(OcctFaults, AStackOverflowBecomesAnError) {
    const std::string e = inputErrorOf([&] { runCatchingOcctFaults([&] { bottomless(0); }, "shape"); });
    EXPECT_NE(e.find("OpenCASCADE failed"), std::string::npos) << e;
}
#endif

TEST(OcctFaults, TheCallersHandlersAreRestored) {
    struct sigaction own{}, before{}, after{};
    own.sa_handler = ownHandler;
    sigemptyset(&own.sa_mask);
    sigaction(SIGSEGV, &own, &before);
    sigaction(SIGINT, &own, nullptr);
    EXPECT_THROW(runCatchingOcctFaults([] { std::raise(SIGSEGV); }, "x"), aeronc::Error);
    runCatchingOcctFaults([] {}, "x");
    for (const int sig : {SIGSEGV, SIGINT}) {
        sigaction(sig, nullptr, &after);
        EXPECT_EQ(after.sa_handler, &ownHandler) << sig;
    }
    // Ctrl-C is not taken over during the call either.
    runCatchingOcctFaults(
        [] {
            struct sigaction during{};
            sigaction(SIGINT, nullptr, &during);
            EXPECT_EQ(during.sa_handler, &ownHandler);
        },
        "x");
    sigaction(SIGSEGV, &before, nullptr);
    signal(SIGINT, SIG_DFL);
    // A normal result and an aeronc::Error pass through unchanged.
    int v = 0;
    runCatchingOcctFaults([&] { v = 7; }, "x");
    EXPECT_EQ(v, 7);
    EXPECT_EQ(inputErrorOf([] { runCatchingOcctFaults([] { throw aeronc::inputError("own"); }, "x"); }), "own");
}
