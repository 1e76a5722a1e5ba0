#pragma once
#include <stdexcept>
#include <string>

namespace aeronc {

// Every failure the core reports to a caller. The binding layer turns it into a
// Python exception and the CLI into a non-zero exit, both with this message.
class Error : public std::runtime_error {
public:
    enum class Kind { Input, Geometry, Internal };
    Error(Kind kind, const std::string& message) : std::runtime_error(message), kind_(kind) {}
    Kind kind() const { return kind_; }

private:
    Kind kind_;
};

inline Error inputError(const std::string& m) { return Error(Error::Kind::Input, m); }
inline Error geometryError(const std::string& m) { return Error(Error::Kind::Geometry, m); }

}  // namespace aeronc
