#include "render/headless_session.hpp"

#include "scene/camera_path.hpp"
#include "util/output_files.hpp"

#include <fstream>
#include <sstream>

#include <cstdio>
#include <stdexcept>

namespace ppr::app {

HeadlessSession::HeadlessSession(const Options& o) : options(o) {
    util::prepareOutputDirectory(o.out, "--out " + o.out);  // before minutes of rendering, not after
    scene = loadScene(o);
    cameras = resolveCameras(scene, o.camera);
    if (!o.path.empty() && !scene::isNamedCameraPath(o.path)) {
        std::ifstream in(o.path, std::ios::binary);
        if (!in) throw std::runtime_error("--path " + o.path + ": cannot read the file (or a path name: still, animate, strafe, dolly, orbit)");
        std::ostringstream text;
        text << in.rdbuf();
        pathFile = scene::parseCameraPath(text.str(), o.path);
        cameras = {{"path", pathFile.front()}};
    }
    vk::ContextOptions co;
    co.validation = o.validation;
    ctx = vk::Context::create(co);
    std::printf("ppr: %s (%s, Vulkan %s)%s\n", ctx->info().name.c_str(), ctx->info().type.c_str(), ctx->info().apiVersionString.c_str(),
                ctx->validationEnabled() ? ", validation + synchronization validation on" : "");
    renderer = std::make_unique<Renderer>(*ctx, scene);
    headless = std::make_unique<HeadlessRenderer>(*ctx, *renderer);
    for (const std::string& kv : o.sets) headless->settings().apply(kv);
    // capture renders one technique, with its own settings if it names any; compare sets each row's.
    const TechniqueVariant variant = parseTechniqueVariant(o.technique);
    if (o.mode != Mode::Compare)
        for (const std::string& kv : variant.sets) headless->settings().apply(kv);
    headless->setTechnique(variant.name);
    extent = {o.width, o.height};
    // A technique this device cannot run is refused before anything renders (one line, exit non-zero).
    const bool compare = o.mode == Mode::Compare;
    for (const std::string& t : compare ? o.techniques : std::vector<std::string>{o.technique})
        if (const std::string why = renderer->unsupported(parseTechniqueVariant(t).name, extent); !why.empty())
            throw std::runtime_error("--technique " + t + ": " + why);
    if (compare)
        if (const std::string why = renderer->unsupported(o.reference, extent); !why.empty())
            throw std::runtime_error("--reference " + o.reference + ": " + why);
    frames = o.frames ? o.frames : o.path.empty() ? 5 : kDefaultPathFrames;
}

std::vector<scene::CameraPose> HeadlessSession::path(const ResolvedCamera& camera) const {
    if (!pathFile.empty()) return pathFile;
    return scene::namedCameraPath(options.path, camera.pose, frames);
}

std::filesystem::path HeadlessSession::cameraDir(const std::string& camera) const {
    const std::filesystem::path dir = singleCamera() ? std::filesystem::path(options.out) : std::filesystem::path(options.out) / camera;
    util::prepareOutputDirectory(dir, "--out " + options.out);
    return dir;
}

int HeadlessSession::finish() const {
    if (ctx->validationErrors() > 0) {
        std::fprintf(stderr, "ppr: %u validation error(s)\n", ctx->validationErrors());
        return 1;
    }
    std::printf("ppr: wrote %s\n", std::filesystem::absolute(options.out).c_str());
    return 0;
}

}  // namespace ppr::app
