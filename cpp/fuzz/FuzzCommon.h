#pragma once
// What the fuzz harnesses share. Each harness defines LLVMFuzzerTestOneInput for one reader;
// it is linked with libFuzzer (target `fuzz`, clang, ASan + UBSan) to search, and with
// ReplayMain.cpp into a plain program that CI runs over the seeds and the inputs that once
// failed (tests/fuzz/<harness>/).
//
// Besides the sanitizers, a harness fails (abort) on what the project promises never to do:
// an exception that is not an aeronc::Error (a library's own, without the input's name), and
// for the posts, an NC program with a block that is not printable text or a feed, speed or
// peck word that is not positive.
#include <aeronc/core/Error.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <string>

namespace aeronc::fuzz {

inline std::string text(const uint8_t* data, size_t size) { return std::string(reinterpret_cast<const char*>(data), size); }

[[noreturn]] inline void finding(const std::string& what) {
    std::fprintf(stderr, "finding: %s\n", what.c_str());
    std::abort();
}

// Runs f: an aeronc::Error is the expected answer to bad input, anything else a finding.
template <class F>
bool expectingErrors(F f) {
    try {
        f();
        return true;
    } catch (const Error&) {
        return false;
    } catch (const std::exception& e) {
        finding(std::string("an exception that is not an aeronc::Error: ") + e.what());
    } catch (...) {
        finding("an exception that is not an aeronc::Error (not a std::exception)");
    }
}

}  // namespace aeronc::fuzz
