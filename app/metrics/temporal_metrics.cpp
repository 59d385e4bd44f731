#include "metrics/temporal_metrics.hpp"

#include "common/heat_map.h"
#include "metrics/compare_metrics.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace ppr::app {

double meanAbsoluteChange(const util::Rgba8Image& a, const util::Rgba8Image& b) {
    const double sum = sumOverRgbDifferences(a, b, "meanAbsoluteChange", [](double d) { return std::abs(d); });
    const size_t n = size_t(a.width) * a.height;
    return n ? sum / (3.0 * double(n)) : 0.0;
}

double meanAbsoluteExcessChange(const util::Rgba8Image& image, const util::Rgba8Image& previous, const util::Rgba8Image& reference,
                                const util::Rgba8Image& referencePrevious) {
    const size_t n = size_t(image.width) * image.height;
    for (const util::Rgba8Image* other : {&previous, &reference, &referencePrevious})
        if (other->width != image.width || other->height != image.height || other->pixels.size() != n * 4 || image.pixels.size() != n * 4)
            throw std::invalid_argument("meanAbsoluteExcessChange: image " + std::to_string(image.width) + "x" + std::to_string(image.height) +
                                        ", another " + std::to_string(other->width) + "x" + std::to_string(other->height));
    double sum = 0.0;
    for (size_t i = 0; i < n; ++i)
        for (int c = 0; c < 3; ++c) {
            const size_t k = i * 4 + c;
            sum += std::abs((double(image.pixels[k]) - double(previous.pixels[k])) - (double(reference.pixels[k]) - double(referencePrevious.pixels[k])));
        }
    return n ? sum / (3.0 * double(n)) : 0.0;
}

util::Rgba8Image displayErrorHeatMap(const util::Rgba8Image& image, const util::Rgba8Image& reference, const FloatImage& mask) {
    const size_t n = size_t(image.width) * image.height;
    const bool sameSize = reference.width == image.width && reference.height == image.height && mask.width == image.width &&
                          mask.height == image.height && image.pixels.size() == n * 4 && reference.pixels.size() == n * 4 &&
                          mask.rgba.size() == n * 4;
    if (!sameSize)
        throw std::invalid_argument("displayErrorHeatMap: image " + std::to_string(image.width) + "x" + std::to_string(image.height) +
                                    ", reference " + std::to_string(reference.width) + "x" + std::to_string(reference.height) + ", mask " +
                                    std::to_string(mask.width) + "x" + std::to_string(mask.height));
    util::Rgba8Image out = image;
    for (size_t i = 0; i < n; ++i) {
        uint8_t* p = &out.pixels[i * 4];
        if (mask.rgba[i * 4 + 3] > 0.0f) {
            int e = 0;
            for (int c = 0; c < 3; ++c) e = std::max(e, std::abs(int(image.pixels[i * 4 + c]) - int(reference.pixels[i * 4 + c])));
            const glm::vec3 heat = gpu::errorHeatColor(float(e) / 255.0f);
            for (int c = 0; c < 3; ++c) p[c] = static_cast<uint8_t>(std::lround(std::clamp(heat[c], 0.0f, 1.0f) * 255.0f));
        } else {
            for (int c = 0; c < 3; ++c) p[c] = static_cast<uint8_t>(p[c] / 4);
        }
        p[3] = 255;
    }
    return out;
}

TemporalSummary summarizeTemporal(const std::vector<TemporalFrame>& frames, bool still, uint32_t convergenceFrames) {
    if (frames.empty()) throw std::invalid_argument("summarizeTemporal: no frames");
    TemporalSummary s;
    s.frames = static_cast<uint32_t>(frames.size());
    for (const TemporalFrame& f : frames) {
        s.psnrDbMean += f.psnrDb / double(frames.size());
        s.reflectorPsnrDbMean += f.reflectorPsnrDb / double(frames.size());
        s.scoredPsnrDbMean += f.scoredPsnrDb / double(frames.size());
    }
    if (still) {
        // Frame 0 has no previous frame: a single frame has nothing to flicker with.
        s.settledFrom = std::max(1u, std::min(convergenceFrames, s.frames / 2));
        double sum = 0.0;
        uint32_t counted = 0;
        for (uint32_t i = s.settledFrom; i < s.frames; ++i, ++counted) sum += frames[i].excessChange;
        s.flicker = counted ? sum / counted : 0.0;
    }
    return s;
}

}  // namespace ppr::app
