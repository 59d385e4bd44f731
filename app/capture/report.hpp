#pragma once
// report.json of `ppr capture` (fields per the DESIGN.md contract).
#include "render/headless.hpp"
#include "vk/context.hpp"

#include <nlohmann/json.hpp>

namespace ppr::app {

struct ReportInfo {
    std::string scene;
    std::string camera;
    scene::CameraPose pose;
    VkExtent2D size{};
    std::string technique;
    size_t reflectors = 0;
    size_t reflectorsProjected = 0;  // PPR's share (budget)
    const Settings* settings = nullptr;
    uint32_t validationErrors = 0;
    bool validationEnabled = false;
    std::map<std::string, std::string> images;  // role → file
};

// Sum of the median GPU times of the technique's passes (techniques/technique_table.hpp).
double techniqueMs(const std::string& technique, const CaptureResult& result);
// The "ppr" block of report.json: tile classification and culling counts (null when PPR did not run).
nlohmann::json pprStatsJson(const CaptureResult& result, VkExtent2D size, size_t reflectorsProjected);
nlohmann::json makeReport(const vk::Context& ctx, const ReportInfo& info, const CaptureResult& result);
void writeJsonFile(const std::string& path, const nlohmann::json& j);

}  // namespace ppr::app
