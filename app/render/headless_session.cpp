#include "render/headless_session.hpp"

#include <cstdio>

namespace ppr::app {

HeadlessSession::HeadlessSession(const Options& o) : options(o) {
    scene = loadScene(o);
    cameras = resolveCameras(scene, o.camera);
    vk::ContextOptions co;
    co.validation = o.validation;
    ctx = vk::Context::create(co);
    std::printf("ppr: %s (%s, Vulkan %s)%s\n", ctx->info().name.c_str(), ctx->info().type.c_str(), ctx->info().apiVersionString.c_str(),
                ctx->validationEnabled() ? ", validation + synchronization validation on" : "");
    renderer = std::make_unique<Renderer>(*ctx, scene);
    headless = std::make_unique<HeadlessRenderer>(*ctx, *renderer);
    for (const std::string& kv : o.sets) headless->settings().apply(kv);
    headless->setTechnique(o.technique);
    extent = {o.width, o.height};
    frames = o.frames ? o.frames : 5;
}

std::filesystem::path HeadlessSession::cameraDir(const std::string& camera) const {
    const std::filesystem::path dir = singleCamera() ? std::filesystem::path(options.out) : std::filesystem::path(options.out) / camera;
    std::filesystem::create_directories(dir);
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
