#pragma once
// The message of the aeronc::Error that f throws; a test failure when it throws none, and with
// inputErrorOf() also when the error is not Error::Kind::Input.
#include <aeronc/core/Error.h>

#include <gtest/gtest.h>

#include <functional>
#include <string>

namespace aeronc::test {

inline std::string errorOf(const std::function<void()>& f, bool inputOnly = false) {
    try {
        f();
    } catch (const Error& e) {
        if (inputOnly) EXPECT_EQ(e.kind(), Error::Kind::Input) << e.what();
        return e.what();
    }
    ADD_FAILURE() << "expected an aeronc::Error";
    return {};
}

inline std::string inputErrorOf(const std::function<void()>& f) { return errorOf(f, true); }

}  // namespace aeronc::test
