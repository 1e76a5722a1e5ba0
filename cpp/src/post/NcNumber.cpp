// Numbers as NC words write them (see appendNumber in NcFormat.h).
#include <aeronc/core/Error.h>
#include <aeronc/post/NcFormat.h>

#include <charconv>
#include <cmath>
#include <cstdio>

namespace aeronc::post {

namespace {

[[noreturn]] void unwritable(double v) {
    char b[64];
    std::snprintf(b, sizeof b, "%g", v);
    throw inputError(std::string("the value ") + b + " cannot be written in an NC word (it must be finite and below " +
                     "1e9 in magnitude)");
}

}  // namespace

void appendNumber(std::string& out, double v, int decimals) {
    static constexpr double kScale[10] = {1, 1e1, 1e2, 1e3, 1e4, 1e5, 1e6, 1e7, 1e8, 1e9};
    if (!(std::abs(v) < kMaxNcValue)) unwritable(v);  // NaN fails the comparison too
    if (decimals < 0 || decimals > 15) throw inputError("internal: " + std::to_string(decimals) + " decimals for an NC word");
    if (decimals <= 9) {
        const long long q = std::llround(v * kScale[decimals]);  // |q| < 1e18: fits
        if (q == 0) {
            out += '0';
            return;
        }
        unsigned long long a = q < 0 ? static_cast<unsigned long long>(-q) : static_cast<unsigned long long>(q);
        char buf[32];
        char* end = buf + sizeof buf;
        char* p = end;
        int d = decimals;
        while (d > 0 && a % 10 == 0) a /= 10, --d;  // trailing zeros of the fraction
        for (int k = 0; k < d; ++k) *--p = static_cast<char>('0' + a % 10), a /= 10;
        if (d > 0) *--p = '.';
        do {
            *--p = static_cast<char>('0' + a % 10);
            a /= 10;
        } while (a);
        if (q < 0) *--p = '-';
        out.append(p, end);
        return;
    }
    // Sign, 9 integer digits, the point and 15 decimals: 26 characters at most.
    char buf[64];
    const auto res = std::to_chars(buf, buf + sizeof buf, v, std::chars_format::fixed, decimals);
    if (res.ec != std::errc()) unwritable(v);
    char* end = res.ptr;
    while (end[-1] == '0') --end;
    if (end[-1] == '.') --end;
    if (end - buf == 2 && buf[0] == '-' && buf[1] == '0') {
        out += '0';
        return;
    }
    out.append(buf, end);
}

}  // namespace aeronc::post
