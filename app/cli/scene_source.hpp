#pragma once
// Where the scene and cameras come from: --scene / the built-in default scene, --reflectors, --camera.
#include "cli/cli.hpp"
#include "scene/scene.hpp"

#include <string>
#include <vector>

namespace ppr::app {

std::string defaultScenePath();  // built by content/ at build time
scene::Scene loadScene(const Options& options);
// The reflector file the editor saves to: --reflectors, else the scene's "<stem>.reflectors.json"
// sidecar ("" for the built-in stress scene).
std::string reflectorFilePath(const Options& options);

struct ResolvedCamera {
    std::string name;
    scene::CameraPose pose;
};
// --camera NAME or numeric pose; empty → every named camera (or one framing the scene if it has none).
// Throws naming the unknown camera and listing the known ones.
std::vector<ResolvedCamera> resolveCameras(const scene::Scene& scene, const std::string& spec);

}  // namespace ppr::app
