// Reflector validation and JSON (de)serialisation. File I/O lives in reflector_io.cpp.
#include "scene/reflector.hpp"

#include "scene/errors.hpp"
#include "util/json_depth.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <charconv>
#include <cstring>
#include <cmath>
#include <limits>
#include <map>
#include <sstream>

namespace ppr::scene {

using nlohmann::json;
using detail::fail;
using detail::fmtNum;

bool Reflector::containsProjected(const glm::vec3& p, float margin) const {
    const glm::vec3 d = p - center;
    return std::abs(glm::dot(d, tangent)) <= halfExtents.x + margin &&
           std::abs(glm::dot(d, bitangent())) <= halfExtents.y + margin;
}

namespace {

constexpr const char* kKnownFields = "name, center, normal, tangent, half_extents, kind, reflectance";
constexpr const char* kKnownTopLevel = "version, reflectors";

bool finite(const glm::vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

// A JSON value quoted in a message, short and always printable (invalid UTF-8 replaced).
std::string describe(const json& j) {
    std::string s = j.dump(-1, ' ', false, json::error_handler_t::replace);
    if (s.size() > 40) s = s.substr(0, 40) + "...";
    return s;
}

// Checks a unit vector; returns "" or the problem (without the field name).
std::string unitProblem(const glm::vec3& v, const char* symbol) {
    if (!finite(v)) return "not finite";
    const float len = glm::length(v);
    if (len < 1e-6f) return "zero length";
    if (std::abs(len - 1.0f) > kUnitTolerance)
        return std::string("not unit length (|") + symbol + "| = " + fmtNum(len) + ")";
    return "";
}

struct FieldReader {
    const json& obj;
    const std::string& where;

    [[noreturn]] void bad(const std::string& field, const std::string& problem) const {
        fail(where + "." + field + ": " + problem);
    }
    float number(const json& j, const std::string& field) const {
        // nlohmann turns a NaN/inf produced in memory into null on dump, so null gets a NaN hint.
        if (!j.is_number()) bad(field, "expected a finite number, got " + describe(j) + (j.is_null() ? " (NaN?)" : ""));
        const double d = j.get<double>();
        if (!std::isfinite(d)) bad(field, "not a finite number");
        if (std::abs(d) > std::numeric_limits<float>::max()) bad(field, "out of float range (" + fmtNum(d) + ")");
        return static_cast<float>(d);
    }
    template <int N>
    glm::vec<N, float> vec(const std::string& field) const {
        const json& j = obj.at(field);
        if (!j.is_array() || j.size() != N)
            bad(field, "expected an array of " + std::to_string(N) + " numbers, got " + describe(j));
        glm::vec<N, float> v;
        for (int i = 0; i < N; ++i) v[i] = number(j[i], field + "[" + std::to_string(i) + "]");
        return v;
    }
};

// Shortest decimal that reads back (through double, as the parser does) to exactly `f`.
json exactFloat(float f) {
    char buf[64];
    auto res = std::to_chars(buf, buf + sizeof buf, f);
    double d = 0.0;
    if (std::from_chars(buf, res.ptr, d).ec == std::errc() && static_cast<float>(d) == f) return d;
    return static_cast<double>(f);
}

// Drops nlohmann's "[json.exception.parse_error.101] " tag: users need the position and the problem.
std::string withoutTag(std::string msg) {
    if (auto pos = msg.find("] "); msg.rfind("[json.exception", 0) == 0 && pos != std::string::npos) msg = msg.substr(pos + 2);
    return msg;
}

json exactArray(const float* v, int n) {
    json a = json::array();
    for (int i = 0; i < n; ++i) a.push_back(exactFloat(v[i]));
    return a;
}

}  // namespace

std::string validateReflector(const Reflector& r) {
    if (r.name.empty()) return "name: must not be empty";
    if (!finite(r.center)) return "center: not finite";
    if (std::max({std::abs(r.center.x), std::abs(r.center.y), std::abs(r.center.z)}) > kMaxCoordinate)
        return "center: beyond " + fmtNum(kMaxCoordinate) + " m of the origin";
    if (auto p = unitProblem(r.normal, "n"); !p.empty()) return "normal: " + p;
    if (auto p = unitProblem(r.tangent, "t"); !p.empty()) return "tangent: " + p;
    if (glm::length(glm::cross(r.normal, r.tangent)) < 1e-3f) return "tangent: parallel to normal";
    const float d = glm::dot(r.normal, r.tangent);
    if (std::abs(d) > kOrthoTolerance) return "tangent: not orthogonal to normal (dot = " + fmtNum(d) + ")";
    const auto& h = r.halfExtents;
    if (!std::isfinite(h.x) || !std::isfinite(h.y)) return "half_extents: not finite";
    if (!(h.x > kMinHalfExtent) || !(h.y > kMinHalfExtent))
        return "half_extents: must be > " + fmtNum(kMinHalfExtent) + " m, got [" + fmtNum(h.x) + ", " + fmtNum(h.y) + "]";
    if (h.x > kMaxHalfExtent || h.y > kMaxHalfExtent)
        return "half_extents: must be at most " + fmtNum(kMaxHalfExtent) + " m, got [" + fmtNum(h.x) + ", " + fmtNum(h.y) + "]";
    if (r.kind != ReflectorKind::Opaque && r.kind != ReflectorKind::Glass) return "kind: invalid value";
    if (!std::isfinite(r.reflectance) || r.reflectance < 0.0f || r.reflectance > 1.0f)
        return "reflectance: must be within 0..1, got " + fmtNum(r.reflectance);
    return "";
}

Reflector parseReflector(const json& j, const std::string& where) {
    if (!j.is_object()) fail(where + ": expected an object, got " + describe(j));
    static const char* kFields[] = {"name", "center", "normal", "tangent", "half_extents", "kind", "reflectance"};
    for (const auto& [key, value] : j.items()) {
        bool known = false;
        for (const char* f : kFields) known = known || key == f;
        if (!known) fail(where + "." + key + ": unknown field (known: " + kKnownFields + ")");
    }
    for (const char* f : {"name", "center", "normal", "tangent", "half_extents"})
        if (!j.contains(f)) fail(where + "." + f + ": missing required field");

    FieldReader in{j, where};
    Reflector r;
    const json& name = j.at("name");
    if (!name.is_string() || name.get<std::string>().empty())
        in.bad("name", "expected a non-empty string, got " + describe(name));
    r.name = name.get<std::string>();
    r.center = in.vec<3>("center");
    r.normal = in.vec<3>("normal");
    r.tangent = in.vec<3>("tangent");
    r.halfExtents = in.vec<2>("half_extents");
    if (j.contains("kind")) {
        const json& k = j.at("kind");
        if (k == "opaque") r.kind = ReflectorKind::Opaque;
        else if (k == "glass") r.kind = ReflectorKind::Glass;
        else in.bad("kind", "expected \"opaque\" or \"glass\", got " + describe(k));
    }
    if (j.contains("reflectance")) r.reflectance = in.number(j.at("reflectance"), "reflectance");

    if (auto problem = validateReflector(r); !problem.empty()) fail(where + "." + problem);
    return r;
}

std::vector<Reflector> parseReflectorFile(const std::string& text, const std::string& file) {
    if (const size_t at = util::jsonNestingExceeded(text); at != std::string::npos)
        fail(file + ": JSON nested deeper than " + std::to_string(util::kMaxJsonNesting) + " levels at byte " + std::to_string(at + 1));
    json doc;
    try {
        doc = json::parse(text);
    } catch (const json::parse_error& e) {
        std::string hint;
        const size_t at = e.byte > 0 ? e.byte - 1 : 0;  // nlohmann's byte is 1-based
        for (const char* word : {"NaN", "Infinity", "-Infinity", "nan", "inf", "-inf"})
            if (text.compare(std::min(at, text.size()), std::strlen(word), word) == 0 ||
                (at > 0 && text.compare(at - 1, std::strlen(word), word) == 0))
                hint = " (NaN/Infinity are not valid JSON numbers)";
        fail(file + ": JSON parse error at byte " + std::to_string(e.byte) + ": " + withoutTag(e.what()) + hint);
    } catch (const json::exception& e) {  // number overflow (1e999): infinity is not a valid value
        fail(file + ": JSON error: " + withoutTag(e.what()));
    }
    if (!doc.is_object()) fail(file + ": expected a JSON object {\"version\":1,\"reflectors\":[...]}, got " + describe(doc));
    // Version first: a newer file's new fields should be reported as a version mismatch.
    if (!doc.contains("version")) fail(file + ": version: missing required field (expected 1)");
    const json& version = doc.at("version");
    if (!version.is_number_integer() || version.get<long long>() != kReflectorFileVersion)
        fail(file + ": version: expected " + std::to_string(kReflectorFileVersion) + ", got " + describe(version));
    for (const auto& [key, value] : doc.items())
        if (key != "version" && key != "reflectors")
            fail(file + ": " + key + ": unknown field (known: " + kKnownTopLevel + ")");
    if (!doc.contains("reflectors")) fail(file + ": reflectors: missing required field");
    const json& list = doc.at("reflectors");
    if (!list.is_array()) fail(file + ": reflectors: expected an array, got " + describe(list));
    if (list.size() > kMaxReflectors)
        fail(file + ": reflectors: " + std::to_string(list.size()) + " entries, at most " + std::to_string(kMaxReflectors));

    std::vector<Reflector> out;
    std::map<std::string, size_t> seen;
    for (size_t i = 0; i < list.size(); ++i) {
        const std::string where = file + ": reflectors[" + std::to_string(i) + "]";
        Reflector r = parseReflector(list[i], where);
        if (auto [it, inserted] = seen.emplace(r.name, i); !inserted)
            fail(where + ".name: duplicate name '" + r.name + "' (also reflectors[" + std::to_string(it->second) + "])");
        out.push_back(std::move(r));
    }
    return out;
}

json reflectorToJson(const Reflector& r) {
    json j = json::object();
    j["name"] = r.name;
    j["center"] = exactArray(&r.center.x, 3);
    j["normal"] = exactArray(&r.normal.x, 3);
    j["tangent"] = exactArray(&r.tangent.x, 3);
    j["half_extents"] = exactArray(&r.halfExtents.x, 2);
    j["kind"] = r.kind == ReflectorKind::Glass ? "glass" : "opaque";
    j["reflectance"] = exactFloat(r.reflectance);
    return j;
}

std::string reflectorsToJson(const std::vector<Reflector>& reflectors) {
    // Hand-laid-out so each field stays on one line (diff-friendly), in the documented order.
    auto inlineValue = [](const json& v) {
        if (!v.is_array()) return v.dump(-1, ' ', false, json::error_handler_t::replace);
        std::string s = "[";
        for (size_t i = 0; i < v.size(); ++i) s += (i ? ", " : "") + v[i].dump();
        return s + "]";
    };
    std::ostringstream out;
    out << "{\n  \"version\": " << kReflectorFileVersion << ",\n  \"reflectors\": [";
    for (size_t i = 0; i < reflectors.size(); ++i) {
        const json j = reflectorToJson(reflectors[i]);
        out << (i ? ",\n" : "\n") << "    {\n";
        const char* order[] = {"name", "center", "normal", "tangent", "half_extents", "kind", "reflectance"};
        for (size_t k = 0; k < std::size(order); ++k)
            out << "      \"" << order[k] << "\": " << inlineValue(j.at(order[k])) << (k + 1 < std::size(order) ? ",\n" : "\n");
        out << "    }";
    }
    out << (reflectors.empty() ? "]\n}\n" : "\n  ]\n}\n");
    return out.str();
}

}  // namespace ppr::scene
