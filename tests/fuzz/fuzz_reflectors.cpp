// Reflector files: parseReflectorFile (engine/scene/reflector.cpp), the parser behind --reflectors,
// scene sidecars and the editor's reopen. The input is the file's text. What parses must also hold
// up downstream: every reflector validates, the editor's serialiser round-trips it exactly, and the
// orientation/plane grouping and draw binding (against a fixed stress scene) run on it.
#include "fuzz_check.hpp"

#include "scene/reflector.hpp"
#include "scene/reflector_groups.hpp"
#include "scene/scene.hpp"
#include "scene/stress_scene.hpp"

#include <cstdint>
#include <string>
#include <vector>

using namespace ppr;

namespace {

bool same(const scene::Reflector& a, const scene::Reflector& b) {
    return a.name == b.name && a.center == b.center && a.normal == b.normal && a.tangent == b.tangent &&
           a.halfExtents == b.halfExtents && a.kind == b.kind && a.reflectance == b.reflectance;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    std::vector<scene::Reflector> reflectors;
    try {
        reflectors = scene::parseReflectorFile(text, "fuzz.reflectors.json");
    } catch (const std::runtime_error& e) {
        fuzz::checkOneLine(e);
        return 0;
    }
    for (const scene::Reflector& r : reflectors)
        fuzz::check(scene::validateReflector(r).empty(), "parsed reflector '" + r.name + "' fails validation: " + scene::validateReflector(r));

    // The editor saves with reflectorsToJson; what it writes must load back unchanged.
    std::vector<scene::Reflector> again;
    try {
        again = scene::parseReflectorFile(scene::reflectorsToJson(reflectors), "roundtrip.json");
    } catch (const std::runtime_error& e) {
        fuzz::broken(std::string("serialised reflectors do not parse: ") + e.what());
    }
    fuzz::check(again.size() == reflectors.size(), "round trip changed the reflector count");
    for (size_t i = 0; i < again.size(); ++i) fuzz::check(same(again[i], reflectors[i]), "round trip changed reflector " + std::to_string(i));

    const scene::ReflectorGroups groups = scene::groupReflectors(reflectors);
    fuzz::check(groups.orientationGroup.size() == reflectors.size() && groups.planeGroup.size() == reflectors.size() &&
                    groups.projectionOrder.size() == reflectors.size(),
                "groups do not cover every reflector");
    for (size_t i = 0; i < reflectors.size(); ++i)
        fuzz::check(groups.orientationGroup[i] < groups.orientationGroupCount && groups.planeGroup[i] < groups.planeGroupCount &&
                        groups.projectionOrder[i] < reflectors.size(),
                    "group index out of range");

    static const scene::Scene tiles = scene::makeStressScene(16);
    for (int b : scene::bindDraws(tiles, reflectors)) fuzz::check(b >= -1 && b < int(reflectors.size()), "draw bound out of range");
    return 0;
}
