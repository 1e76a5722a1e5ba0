#include <aeronc/compensation/MeasurementCsv.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <sstream>
#include <unordered_map>

namespace aeronc::compensation {

namespace {

const char* kColumns[] = {"u", "v", "height", "quality"};

std::string trim(const std::string& s) {
    size_t a = 0, b = s.size();
    while (a < b && std::isspace(static_cast<unsigned char>(s[a]))) ++a;
    while (b > a && std::isspace(static_cast<unsigned char>(s[b - 1]))) --b;
    return s.substr(a, b - a);
}

std::string lower(std::string s) {
    for (auto& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return s;
}

std::vector<std::string> fields(const std::string& line) {
    std::vector<std::string> out;
    size_t start = 0;
    for (;;) {
        const size_t comma = line.find(',', start);
        out.push_back(trim(line.substr(start, comma == std::string::npos ? std::string::npos : comma - start)));
        if (comma == std::string::npos) break;
        start = comma + 1;
    }
    return out;
}

std::string where(int line) { return "measurement file, line " + std::to_string(line) + ": "; }

double number(const std::string& text, const char* column, int line) {
    if (text.empty()) throw compensationError(where(line) + column + " is empty");
    errno = 0;
    char* end = nullptr;
    const double v = std::strtod(text.c_str(), &end);
    if (end != text.c_str() + text.size())
        throw compensationError(where(line) + column + " '" + text + "' is not a number");
    // An underflow (1e-320) is read as the tiny number it is; an overflow is no measurement.
    if (errno == ERANGE && std::abs(v) > 1.0)
        throw compensationError(where(line) + column + " '" + text + "' is out of range");
    if (std::isnan(v)) throw compensationError(where(line) + column + " is NaN (the camera found no hole?)");
    if (!std::isfinite(v)) throw compensationError(where(line) + column + " is not finite");
    return v;
}

bool isHeader(const std::vector<std::string>& f) {
    const std::string first = lower(f.front());
    return first == "hole" || first == "id" || first == "hole id" || first == "hole_id";
}

void checkHeader(const std::vector<std::string>& f, int line) {
    static const std::vector<std::vector<std::string>> names{{"u"}, {"v"}, {"height", "h"}, {"quality", "q"}};
    if (f.size() < 4 || f.size() > 5)
        throw compensationError(where(line) + "the header must be hole,u,v,height[,quality]");
    for (size_t i = 1; i < f.size(); ++i) {
        const auto& ok = names[i - 1];
        if (std::find(ok.begin(), ok.end(), lower(f[i])) == ok.end())
            throw compensationError(where(line) + "column " + std::to_string(i + 1) + " is '" + f[i] + "', expected '" +
                                    ok.front() + "' (the header must be hole,u,v,height[,quality])");
    }
}

std::string joined(const std::vector<std::string>& ids, size_t most = 12) {
    std::string s;
    for (size_t i = 0; i < ids.size() && i < most; ++i) s += (i ? ", " : "") + ids[i];
    if (ids.size() > most) s += ", ... (" + std::to_string(ids.size()) + " in all)";
    return s;
}

}  // namespace

std::vector<CameraReading> readMeasurementCsv(const std::string& textIn) {
    std::string_view text(textIn);
    if (text.substr(0, 3) == "\xEF\xBB\xBF") text.remove_prefix(3);
    std::vector<CameraReading> out;
    std::unordered_map<std::string, int> seen;
    bool headerAllowed = true;
    int line = 0;
    size_t pos = 0;
    while (pos <= text.size()) {
        size_t eol = text.find('\n', pos);
        if (eol == std::string_view::npos) eol = text.size();
        std::string raw(text.substr(pos, eol - pos));
        pos = eol + 1;
        ++line;
        if (!raw.empty() && raw.back() == '\r') raw.pop_back();
        const std::string s = trim(raw);
        if (s.empty() || s[0] == '#') continue;
        if (s.find(',') == std::string::npos) {
            const char* hint = s.find(';') != std::string::npos || s.find('\t') != std::string::npos
                                   ? " (fields must be separated by commas)"
                                   : "";
            throw compensationError(where(line) + "expected hole,u,v,height[,quality], got '" + s.substr(0, 60) + "'" + hint);
        }
        const auto f = fields(s);
        if (headerAllowed && isHeader(f)) {
            checkHeader(f, line);
            headerAllowed = false;
            continue;
        }
        headerAllowed = false;
        if (f.size() < 4 || f.size() > 5)
            throw compensationError(where(line) + std::to_string(f.size()) +
                                    " fields; expected 4 or 5: hole,u,v,height[,quality]");
        CameraReading r;
        r.line = line;
        r.id = f[0];
        if (r.id.empty()) throw compensationError(where(line) + "the hole id is empty");
        r.u = number(f[1], kColumns[0], line);
        r.v = number(f[2], kColumns[1], line);
        r.height = number(f[3], kColumns[2], line);
        if (!(r.height > 0.0)) throw compensationError(where(line) + "the height must be positive (camera above the hole)");
        if (f.size() == 5 && !f[4].empty()) r.quality = number(f[4], kColumns[3], line);
        const auto [it, fresh] = seen.emplace(r.id, line);
        if (!fresh)
            throw compensationError(where(line) + "hole " + r.id + " is measured twice (lines " +
                                    std::to_string(it->second) + " and " + std::to_string(line) + ")");
        out.push_back(std::move(r));
    }
    if (out.empty()) throw compensationError("measurement file: no measurements (expected lines hole,u,v,height[,quality])");
    return out;
}

std::vector<ImportedDatum> importMeasurements(const std::vector<CameraReading>& readings,
                                              const std::vector<DatumFrame>& datums, const ImportOptions& options) {
    if (datums.size() < 2)
        throw compensationError("fewer than two datum holes in the photo-hole set (" + std::to_string(datums.size()) +
                                "): define at least two");
    std::unordered_map<std::string, size_t> index;
    for (size_t i = 0; i < datums.size(); ++i)
        if (!index.emplace(datums[i].id, i).second)
            throw compensationError("the photo-hole set holds datum hole " + datums[i].id + " twice");
    std::vector<const CameraReading*> byDatum(datums.size(), nullptr);
    std::vector<std::string> unknown, missing;
    for (const auto& r : readings) {
        const auto it = index.find(r.id);
        if (it == index.end()) unknown.push_back(r.id + " (line " + std::to_string(r.line) + ")");
        else if (byDatum[it->second]) throw compensationError("hole " + r.id + " is measured twice");
        else byDatum[it->second] = &r;
    }
    if (!unknown.empty())
        throw compensationError("measurement file: unknown hole ids, not datum holes of the photo-hole set: " + joined(unknown));
    for (size_t i = 0; i < datums.size(); ++i)
        if (!byDatum[i]) missing.push_back(datums[i].id);
    if (!missing.empty())
        throw compensationError("measurement file: datum holes not measured: " + joined(missing) +
                                " (measure them, or remove them from the photo-hole set)");
    std::vector<ImportedDatum> out;
    std::vector<std::string> outliers, poor;
    out.reserve(datums.size());
    for (size_t i = 0; i < datums.size(); ++i) {
        const auto& d = datums[i];
        const auto& r = *byDatum[i];
        try {
            requireRigid(d.chain);
        } catch (const Error& e) {
            throw compensationError("datum hole " + d.id + ": " + e.what());
        }
        ImportedDatum m;
        m.reading = r;
        m.datum.id = d.id;
        m.datum.nominal = d.nominal;
        m.datum.measured = d.chain.toPart(Vec3(r.u, r.v, r.height));
        const double off = m.datum.deviation().norm();
        if (off > options.maxDeviation) {
            std::ostringstream os;
            os.precision(3);
            os << d.id << " " << std::fixed << off << " mm (line " << r.line << ")";
            outliers.push_back(os.str());
        }
        if (r.quality && *r.quality < options.minQuality) {
            std::ostringstream os;
            os << d.id << " quality " << *r.quality << " (line " << r.line << ")";
            poor.push_back(os.str());
        }
        out.push_back(std::move(m));
    }
    if (!outliers.empty()) {
        std::ostringstream os;
        os << "measurement file: outliers beyond " << options.maxDeviation
           << " mm from the nominal position: " << joined(outliers)
           << " (measure these holes again, or raise the outlier tolerance if the part really is that far off)";
        throw compensationError(os.str());
    }
    if (!poor.empty()) {
        std::ostringstream os;
        os << "measurement file: quality below " << options.minQuality << ": " << joined(poor);
        throw compensationError(os.str());
    }
    return out;
}

}  // namespace aeronc::compensation
