#pragma once
// What `ppr capture` and `ppr compare` share: the scene and cameras from the options, a Vulkan context
// (device line printed), the renderer with the --set values applied, the headless frame loop, the
// per-camera output folders and the exit code.
#include "cli/cli.hpp"
#include "cli/scene_source.hpp"
#include "render/headless.hpp"

#include <filesystem>
#include <memory>

namespace ppr::app {

struct HeadlessSession {
    explicit HeadlessSession(const Options& options);

    // One camera: files go straight into --out; several: one sub-folder per camera (created here).
    std::filesystem::path cameraDir(const std::string& camera) const;
    bool singleCamera() const { return cameras.size() == 1; }
    // --path: the poses from this camera, one per frame (a path file's own poses whatever the camera).
    std::vector<scene::CameraPose> path(const ResolvedCamera& camera) const;
    // 1 (with a message) when validation reported errors, else 0 after printing where the files are.
    int finish() const;

    const Options& options;
    // Declaration order is teardown order in reverse: the headless loop and renderer go before the context.
    scene::Scene scene;
    std::vector<ResolvedCamera> cameras;
    std::unique_ptr<vk::Context> ctx;
    std::unique_ptr<Renderer> renderer;
    std::unique_ptr<HeadlessRenderer> headless;
    VkExtent2D extent{};
    uint32_t frames = 5;
    std::vector<scene::CameraPose> pathFile;  // --path FILE's poses (cameras is then one, named "path")
};

}  // namespace ppr::app
