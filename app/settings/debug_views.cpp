#include "settings/debug_views.hpp"

#include "common/frame.h"

#include <stdexcept>

namespace ppr::app {

const std::vector<DebugViewDecl>& debugViews() {
    static const std::vector<DebugViewDecl> views = {
        {"none", gpu::kDebugNone, "composite", "the frame as rendered"},
        {"albedo", gpu::kDebugAlbedo, "composite", "G-buffer base colour"},
        {"normals", gpu::kDebugNormals, "composite", "G-buffer normals (normal-mapped), 0.5 + 0.5 n"},
        {"roughness", gpu::kDebugRoughness, "composite", "G-buffer material channels (roughness, metallic, reflective flag)"},
        {"reflectors", gpu::kDebugReflectors, "composite", "reflector ids over the scene, one colour per reflector"},
        {"depth", gpu::kDebugDepth, "composite", "reverse-Z depth (fourth root)"},
        {"shadow", gpu::kDebugShadow, "lighting", "shadow-map visibility of the sun (white = lit)"},
        {"intermediate", gpu::kDebugIntermediate, "ppr.reflect", "PPR's decoded intermediate buffer"},
        {"holes", gpu::kDebugHoles, "ppr.reflect", "PPR's hole mask per reflector pixel: own data (green) / hole-filled (yellow) / contact march (blue) / no data (red)"},
        {"tiles", gpu::kDebugTiles, "ppr.reflect", "reflectors surviving PPR's per-tile culling, as a heat map"},
        {"atlas", gpu::kDebugAtlas, "glass.atlas_view", "PPR's glass reflection atlas, fitted to the screen height"},
        {"motion", gpu::kDebugMotion, "composite",
         "TAA's motion to last frame: black = still, hue = direction, brightness = length (full at 4 px), magenta = behind last frame's camera"},
    };
    return views;
}

const DebugViewDecl& debugView(uint32_t value) {
    for (const DebugViewDecl& v : debugViews())
        if (v.value == value) return v;
    throw std::logic_error("debug view " + std::to_string(value) + " is not in debugViews()");
}

}  // namespace ppr::app
