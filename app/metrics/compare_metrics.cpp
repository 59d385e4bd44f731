#include "metrics/compare_metrics.hpp"

#include "common/heat_map.h"
#include "common/reflection.h"
#include "tonemap/tonemap.h"

#include <glm/gtc/packing.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <stdexcept>

namespace ppr::app {

namespace {

size_t pixelCount(const FloatImage& img) { return size_t(img.width) * img.height; }

void checkImage(const FloatImage& img, const char* what) {
    if (img.rgba.size() != pixelCount(img) * 4)
        throw std::invalid_argument(std::string(what) + ": rgba holds " + std::to_string(img.rgba.size()) +
                                    " floats, expected width * height * 4");
}

void checkSameSize(const FloatImage& technique, const FloatImage& reference) {
    checkImage(technique, "technique");
    checkImage(reference, "reference");
    if (technique.width != reference.width || technique.height != reference.height)
        throw std::invalid_argument("technique is " + std::to_string(technique.width) + "x" +
                                    std::to_string(technique.height) + ", reference is " +
                                    std::to_string(reference.width) + "x" + std::to_string(reference.height));
}

// Display value of pixel i; non-finite components count as 1 so a NaN cannot poison the mean.
glm::vec3 displayAt(const FloatImage& img, size_t i, float exposure) {
    const float* p = &img.rgba[i * 4];
    glm::vec3 d = gpu::displayFromRadiance(glm::vec3(p[0], p[1], p[2]), exposure);
    for (int c = 0; c < 3; ++c)
        if (!std::isfinite(d[c])) d[c] = 1.0f;
    return d;
}

float alphaAt(const FloatImage& img, size_t i) { return img.rgba[i * 4 + 3]; }

uint8_t toByte(float v) { return static_cast<uint8_t>(std::lround(std::clamp(v, 0.0f, 1.0f) * 255.0f)); }

void setPixel(util::Rgba8Image& img, size_t i, uint8_t r, uint8_t g, uint8_t b) {
    uint8_t* p = &img.pixels[i * 4];
    p[0] = r, p[1] = g, p[2] = b, p[3] = 255;
}

}  // namespace

FloatImage floatImageFromHalf(const void* rgba16f, uint32_t width, uint32_t height) {
    FloatImage img;
    img.width = width;
    img.height = height;
    const size_t n = size_t(width) * height * 4;
    if (n && !rgba16f) throw std::invalid_argument("floatImageFromHalf: null data");
    img.rgba.resize(n);
    const auto* bytes = static_cast<const unsigned char*>(rgba16f);
    for (size_t i = 0; i < n; ++i) {
        uint16_t h;
        std::memcpy(&h, bytes + i * 2, 2);  // readback memory carries no alignment promise
        img.rgba[i] = glm::unpackHalf1x16(h);
    }
    return img;
}

FloatImage allReflectorPixels(const FloatImage& reference) {
    checkImage(reference, "reference");
    FloatImage all = reference;
    for (size_t i = 0; i < pixelCount(all); ++i) {
        float& a = all.rgba[i * 4 + 3];
        a = a == gpu::kReflectionHit || a == gpu::kReflectionOffscreen ? gpu::kReflectionHit : gpu::kReflectionNone;
    }
    return all;
}

ReflectionScore scoreReflection(const FloatImage& technique, const FloatImage& reference, float exposure,
                                const PixelRect& region) {
    checkSameSize(technique, reference);
    if (uint64_t(region.x) + region.width > reference.width || uint64_t(region.y) + region.height > reference.height)
        throw std::invalid_argument("region " + std::to_string(region.width) + "x" + std::to_string(region.height) +
                                    " at (" + std::to_string(region.x) + ", " + std::to_string(region.y) +
                                    ") is outside the " + std::to_string(reference.width) + "x" +
                                    std::to_string(reference.height) + " image");
    ReflectionScore s;
    double sumSq = 0.0;
    for (uint32_t y = region.y; y < region.y + region.height; ++y)
        for (uint32_t x = region.x; x < region.x + region.width; ++x) {
            const size_t i = size_t(y) * reference.width + x;
            if (alphaAt(reference, i) != gpu::kReflectionHit) continue;
            ++s.maskPixels;
            if (alphaAt(technique, i) > 0.0f) ++s.coveredPixels;
            // A technique pixel without a reflection keeps its rgb (0): missing is an error.
            const glm::vec3 d = displayAt(technique, i, exposure) - displayAt(reference, i, exposure);
            sumSq += double(d.x) * d.x + double(d.y) * d.y + double(d.z) * d.z;
        }
    if (s.maskPixels == 0) {  // nothing the technique could get wrong
        s.psnrDb = kPsnrCapDb;
        s.coverage = 1.0;
        return s;
    }
    s.mse = sumSq / (3.0 * double(s.maskPixels));
    s.coverage = double(s.coveredPixels) / double(s.maskPixels);
    s.psnrDb = s.mse > 0.0 ? std::min(kPsnrCapDb, 10.0 * std::log10(1.0 / s.mse)) : kPsnrCapDb;
    return s;
}

ReflectionScore scoreReflection(const FloatImage& technique, const FloatImage& reference, float exposure) {
    return scoreReflection(technique, reference, exposure, PixelRect{0, 0, reference.width, reference.height});
}

double compositedPsnrDb(const util::Rgba8Image& technique, const util::Rgba8Image& reference, const FloatImage& referenceReflection,
                        const PixelRect* region) {
    checkImage(referenceReflection, "reference reflection");
    const uint32_t w = referenceReflection.width, h = referenceReflection.height;
    for (const util::Rgba8Image* img : {&technique, &reference})
        if (img->width != w || img->height != h || img->pixels.size() != size_t(w) * h * 4)
            throw std::invalid_argument("compositedPsnrDb: final images must be " + std::to_string(w) + "x" + std::to_string(h));
    const PixelRect r = region ? *region : PixelRect{0, 0, w, h};
    if (uint64_t(r.x) + r.width > w || uint64_t(r.y) + r.height > h) throw std::invalid_argument("compositedPsnrDb: region outside the image");
    double sumSq = 0.0;
    uint64_t n = 0;
    for (uint32_t y = r.y; y < r.y + r.height; ++y)
        for (uint32_t x = r.x; x < r.x + r.width; ++x) {
            const size_t i = size_t(y) * w + x;
            if (alphaAt(referenceReflection, i) != gpu::kReflectionHit) continue;
            ++n;
            for (int c = 0; c < 3; ++c) {
                const double d = (double(technique.pixels[i * 4 + c]) - double(reference.pixels[i * 4 + c])) / 255.0;
                sumSq += d * d;
            }
        }
    if (n == 0) return kPsnrCapDb;
    const double mse = sumSq / (3.0 * double(n));
    return mse > 0.0 ? std::min(kPsnrCapDb, 10.0 * std::log10(1.0 / mse)) : kPsnrCapDb;
}

double sumOverRgbDifferences(const util::Rgba8Image& a, const util::Rgba8Image& b, const char* what, double (*f)(double)) {
    const size_t n = size_t(a.width) * a.height;
    if (a.width != b.width || a.height != b.height || a.pixels.size() != n * 4 || b.pixels.size() != n * 4)
        throw std::invalid_argument(std::string(what) + ": images of " + std::to_string(a.width) + "x" + std::to_string(a.height) + " and " +
                                    std::to_string(b.width) + "x" + std::to_string(b.height));
    double sum = 0.0;
    for (size_t i = 0; i < n; ++i)
        for (int c = 0; c < 3; ++c) sum += f(double(a.pixels[i * 4 + c]) - double(b.pixels[i * 4 + c]));
    return sum;
}

double imagePsnrDb(const util::Rgba8Image& a, const util::Rgba8Image& b) {
    const double sumSq = sumOverRgbDifferences(a, b, "imagePsnrDb", [](double d) { return d * d; }) / (255.0 * 255.0);
    const size_t n = size_t(a.width) * a.height;
    const double mse = n ? sumSq / (3.0 * double(n)) : 0.0;
    return mse > 0.0 ? std::min(kPsnrCapDb, 10.0 * std::log10(1.0 / mse)) : kPsnrCapDb;
}

util::Rgba8Image reflectionDisplayImage(const FloatImage& reflection, float exposure) {
    checkImage(reflection, "reflection");
    util::Rgba8Image out;
    out.width = reflection.width;
    out.height = reflection.height;
    out.pixels.assign(pixelCount(reflection) * 4, 0);
    for (size_t i = 0; i < pixelCount(reflection); ++i) {
        if (alphaAt(reflection, i) > 0.0f) {
            const glm::vec3 d = displayAt(reflection, i, exposure);
            setPixel(out, i, toByte(d.r), toByte(d.g), toByte(d.b));
        } else {
            setPixel(out, i, 0, 0, 0);
        }
    }
    return out;
}

util::Rgba8Image errorHeatMap(const FloatImage& technique, const FloatImage& reference, float exposure,
                              const util::Rgba8Image& context) {
    checkSameSize(technique, reference);
    const bool hasContext = context.width != 0 || context.height != 0;
    if (hasContext && (context.width != reference.width || context.height != reference.height ||
                       context.pixels.size() != pixelCount(reference) * 4))
        throw std::invalid_argument("context image is " + std::to_string(context.width) + "x" +
                                    std::to_string(context.height) + ", reflection images are " +
                                    std::to_string(reference.width) + "x" + std::to_string(reference.height));
    util::Rgba8Image out;
    out.width = reference.width;
    out.height = reference.height;
    out.pixels.assign(pixelCount(reference) * 4, 0);
    for (size_t i = 0; i < pixelCount(reference); ++i) {
        const float refAlpha = alphaAt(reference, i);
        if (refAlpha == gpu::kReflectionHit) {
            const glm::vec3 d = glm::abs(displayAt(technique, i, exposure) - displayAt(reference, i, exposure));
            const glm::vec3 c = gpu::errorHeatColor(std::max({d.x, d.y, d.z}));
            setPixel(out, i, toByte(c.r), toByte(c.g), toByte(c.b));
        } else if (refAlpha > 0.0f) {  // a reflection the score leaves out (off screen, sky, second bounce)
            setPixel(out, i, kHeatMapOffscreenGrey, kHeatMapOffscreenGrey, kHeatMapOffscreenGrey);
        } else if (hasContext) {
            // Darkened on the encoded bytes: only for orientation, not a radiometric quantity.
            const uint8_t* p = &context.pixels[i * 4];
            auto dark = [](uint8_t v) { return static_cast<uint8_t>((v + 2) / 4); };
            setPixel(out, i, dark(p[0]), dark(p[1]), dark(p[2]));
        } else {
            setPixel(out, i, 0, 0, 0);
        }
    }
    return out;
}

FloatImage glassScreenMask(const FloatImage& referenceAtlas, const std::vector<scene::GlassRegion>& layout, uint32_t width,
                           uint32_t height) {
    FloatImage mask;
    mask.width = width;
    mask.height = height;
    mask.rgba.assign(size_t(width) * height * 4, 0.0f);
    for (const scene::GlassRegion& r : layout) {
        for (int32_t y = std::max(r.screen.y0, 0); y < std::min(r.screen.y1, int32_t(height)); ++y) {
            for (int32_t x = std::max(r.screen.x0, 0); x < std::min(r.screen.x1, int32_t(width)); ++x) {
                const glm::ivec2 t = glm::ivec2(glm::floor(scene::atlasFromScreen(r, glm::vec2(x, y) + 0.5f)));
                if (t.x < r.atlasOrigin.x || t.y < r.atlasOrigin.y || t.x >= r.atlasOrigin.x + r.atlasSize.x ||
                    t.y >= r.atlasOrigin.y + r.atlasSize.y || uint32_t(t.x) >= referenceAtlas.width || uint32_t(t.y) >= referenceAtlas.height)
                    continue;
                if (referenceAtlas.rgba[(size_t(t.y) * referenceAtlas.width + t.x) * 4 + 3] == gpu::kReflectionHit)
                    mask.rgba[(size_t(y) * width + x) * 4 + 3] = gpu::kReflectionHit;
            }
        }
    }
    return mask;
}

}  // namespace ppr::app
