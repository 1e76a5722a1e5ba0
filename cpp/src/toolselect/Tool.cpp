#include <aeronc/core/Error.h>
#include <aeronc/toolselect/Tool.h>

#include <cmath>
#include <sstream>

namespace aeronc::toolselect {

void Tool::validate() const {
    const std::string who = "tool '" + id + "': ";
    auto fail = [&](const std::string& what) { throw inputError(who + what); };
    if (!isEndMill() && type != "drill" && type != "face" && type != "other")
        fail("unknown type '" + type + "' (expected flat, bull, ball, drill, face or other)");
    const double dims[] = {diameter, cornerRadius, fluteLength, reach, neckDiameter};
    for (double d : dims)
        if (!std::isfinite(d)) fail("dimensions must be finite numbers");
    std::ostringstream m;
    if (diameter <= 0) m << "diameter " << diameter << " mm must be positive";
    else if (cornerRadius < 0) m << "corner radius " << cornerRadius << " mm must not be negative";
    // 1e-9 mm: a ball's corner radius is often stored as exactly half the diameter.
    else if (cornerRadius > radius() + 1e-9)
        m << "corner radius " << cornerRadius << " mm exceeds the radius " << radius() << " mm";
    else if (type == "ball" && cornerRadius < radius() - 1e-9)
        m << "a ball end mill's corner radius (" << cornerRadius << " mm) must equal its radius ("
          << radius() << " mm)";
    else if (fluteLength <= 0) m << "flute length " << fluteLength << " mm must be positive";
    else if (reach < fluteLength)
        m << "reach " << reach << " mm is shorter than the flute length " << fluteLength << " mm";
    else if (flutes < 1) m << "flute count " << flutes << " must be at least 1";
    else if (neckDiameter < 0 || (neckDiameter > 0 && neckDiameter >= diameter))
        m << "neck diameter " << neckDiameter << " mm must be positive and below the diameter " << diameter << " mm";
    if (!m.str().empty()) fail(m.str());
}

}  // namespace aeronc::toolselect
