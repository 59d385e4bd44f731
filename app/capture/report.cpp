#include "capture/report.hpp"

#include "techniques/technique_table.hpp"

#include <fstream>
#include <stdexcept>

namespace ppr::app {

double techniqueMs(const std::string& technique, const CaptureResult& r) {
    return techniqueCost(technique, r.passMedianMs);
}

nlohmann::json pprStatsJson(const CaptureResult& r, VkExtent2D size, size_t projected) {
    if (!r.pprStats) return nullptr;
    const gpu::PprFrameStats& s = *r.pprStats;
    const uint32_t tilesX = gpu::pprTilesCovering(size.width), tilesY = gpu::pprTilesCovering(size.height);
    return {{"tile_size", gpu::kPprTileSize},
            {"tiles", tilesX * tilesY},
            {"tiles_planar", s.dispatch[gpu::kTileClassPlanar].x},
            {"tiles_other", s.dispatch[gpu::kTileClassOther].x},
            {"tiles_with_content", s.tilesWithContent},
            {"tiles_projected", s.tilesProjected},  // the projection pass's workgroups
            {"tiles_with_survivors", s.tilesWithSurvivors},
            {"reflectors_projected", projected},
            // The bounds pass's compacted lists: what every tile's culling loops over.
            {"reflectors_on_screen", s.reflectorsOnScreen},
            {"reflectors_reflecting", s.reflectorsReflecting},
            // Without culling every content tile would test every reflector.
            {"reflector_tile_pairs_unculled", uint64_t(s.tilesWithContent) * projected},
            {"reflector_tile_pairs", s.reflectorTilePairs},
            {"occluder_tile_pairs", s.occluderTilePairs},
            {"max_reflectors_per_tile", s.maxTileSurvivors},
            // Tiles whose survivors all share one plane and whose pixels looked them up in a grid.
            {"tiles_plane_grid", s.tilesOnPlaneGrid},
            // The planar tiles holding a normal-mapped hole, which ppr.fallback.holes marches (listed
            // by ppr.reflect with indirect=1).
            {"tiles_mapped_holes", s.tilesWithMappedHoles}};
}

nlohmann::json makeReport(const vk::Context& ctx, const ReportInfo& info, const CaptureResult& r) {
    nlohmann::json j;
    j["device"] = ctx.info().name;
    j["device_type"] = ctx.info().type;
    j["driver"] = ctx.info().driver;
    j["api_version"] = ctx.info().apiVersionString;
    j["scene"] = info.scene;
    j["camera"] = {{"name", info.camera},
                   {"position", {info.pose.position.x, info.pose.position.y, info.pose.position.z}},
                   {"yaw_deg", info.pose.yawDeg},
                   {"pitch_deg", info.pose.pitchDeg},
                   {"fov_y_deg", info.pose.fovYDeg}};
    j["size"] = {info.size.width, info.size.height};
    j["technique"] = info.technique;
    j["settings"] = nlohmann::json::object();
    if (info.settings)
        for (const auto& [k, v] : info.settings->canonicalTexts()) j["settings"][k] = v;  // every declared key
    j["frames"] = r.frames;
    nlohmann::json passes = nlohmann::json::object();
    for (const std::string& name : r.passOrder) passes[name] = {{"gpu_ms", r.passMedianMs.at(name)}};
    for (const auto& [name, ms] : r.passMedianMs)
        if (!passes.contains(name)) passes[name] = {{"gpu_ms", ms}};
    j["passes"] = passes;
    j["pass_order"] = r.passOrder;
    j["total_gpu_ms"] = r.totalMedianMs;
    j["technique_gpu_ms"] = techniqueMs(info.technique, r);
    j["reflectors"] = info.reflectors;
    j["ppr"] = pprStatsJson(r, info.size, info.reflectorsProjected);
    j["glass"] = nullptr;
    if (r.glass)
        j["glass"] = {{"atlas_size", r.glass->atlasSize}, {"panels_visible", r.glass->visible}, {"regions", r.glass->regions()},
                      {"regions_scaled", r.glass->scaled}, {"panels_dropped", r.glass->dropped}, {"scale", r.glass->scale},
                      {"overflow", r.glass->overflowed()}};
    j["environment_probe"] = nullptr;
    if (const std::optional<EnvironmentProbe::Stats>& p = r.environmentProbe) {
        const auto xyz = [](const glm::vec3& v) { return nlohmann::json::array({v.x, v.y, v.z}); };
        j["environment_probe"] = {{"face_size", p->faceSize},     {"centre", xyz(p->placement.centre)}, {"box_min", xyz(p->placement.boxMin)},
                                  {"box_max", xyz(p->placement.boxMax)}, {"gpu_ms", p->gpuMs}, {"wall_ms", p->wallMs},
                                  {"bytes", p->bytes}};
    }
    j["warnings"] = r.warning.empty() ? nlohmann::json::array() : nlohmann::json::array({r.warning});
    j["validation"] = info.validationEnabled;
    j["validation_errors"] = info.validationErrors;
    j["images"] = info.images;
    return j;
}

void writeJsonFile(const std::string& path, const nlohmann::json& j) {
    std::ofstream f(path);
    if (!f) throw std::runtime_error(path + ": cannot open for writing");
    f << j.dump(2) << "\n";
    if (!f) throw std::runtime_error(path + ": write failed");
}

}  // namespace ppr::app
