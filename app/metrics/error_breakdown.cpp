#include "metrics/error_breakdown.hpp"

#include "common/reflection.h"
#include "planar/planar.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <stdexcept>
#include <string>

namespace ppr::app {
namespace {

bool silhouetteBetween(float a, float b) {
    if ((a > 0.0f) != (b > 0.0f)) return true;  // sky on one side only
    return a > 0.0f && std::abs(a - b) > kSilhouetteRelativeJump * std::min(a, b);
}

double shareOfWorst(std::vector<double> errors, double fraction, double total) {
    if (errors.empty() || total <= 0.0) return 0.0;
    const size_t k = std::min(errors.size(), static_cast<size_t>(std::ceil(fraction * double(errors.size()))));
    std::nth_element(errors.begin(), errors.begin() + static_cast<std::ptrdiff_t>(k - 1), errors.end(), std::greater<double>());
    double worst = 0.0;
    for (size_t i = 0; i < k; ++i) worst += errors[i];
    return worst / total;
}

}  // namespace

const char* errorClassName(ErrorClass c) {
    switch (c) {
        case ErrorClass::ReflectorEdge: return "reflector_edge";
        case ErrorClass::DisocclusionEdge: return "disocclusion_edge";
        case ErrorClass::SilhouetteSeam: return "silhouette_seam";
        case ErrorClass::ParallelShape: return "parallel_shape";
        case ErrorClass::HoleFilled: return "hole_filled";
        case ErrorClass::Interior: return "interior";
    }
    return "interior";
}

ErrorClass classifyPixel(const FloatImage& technique, const FloatImage& reference, const std::vector<float>& referencePath, size_t i) {
    const int w = int(reference.width), h = int(reference.height);
    const int x = int(i % reference.width), y = int(i / reference.width);
    bool edge = false, disocclusion = false, seam = false;
    for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
            if (dx == 0 && dy == 0) continue;
            const int nx = x + dx, ny = y + dy;
            if (nx < 0 || ny < 0 || nx >= w || ny >= h) {
                edge = true;
                continue;
            }
            const size_t j = size_t(ny) * reference.width + size_t(nx);
            const float a = reference.rgba[j * 4 + 3];
            if (a == gpu::kReflectionNone) edge = true;
            else if (a != gpu::kReflectionHit) disocclusion = true;
            if (!referencePath.empty() && silhouetteBetween(referencePath[i * 2], referencePath[j * 2])) seam = true;
        }
    if (edge) return ErrorClass::ReflectorEdge;
    if (disocclusion) return ErrorClass::DisocclusionEdge;
    if (seam) return ErrorClass::SilhouetteSeam;
    if (!referencePath.empty() && (uint32_t(referencePath[i * 2 + 1]) & gpu::kPlanarParallelShape) != 0u) return ErrorClass::ParallelShape;
    if (!technique.rgba.empty() && technique.rgba[i * 4 + 3] == gpu::kReflectionFilled) return ErrorClass::HoleFilled;
    return ErrorClass::Interior;
}

ErrorBreakdown breakdownErrors(const util::Rgba8Image& techniqueFinal, const util::Rgba8Image& referenceFinal,
                               const FloatImage& techniqueReflection, const FloatImage& referenceReflection,
                               const std::vector<float>& referencePath) {
    const uint32_t w = referenceReflection.width, h = referenceReflection.height;
    const size_t n = size_t(w) * h;
    if (referenceReflection.rgba.size() != n * 4) throw std::invalid_argument("breakdownErrors: reference reflection has the wrong length");
    for (const util::Rgba8Image* img : {&techniqueFinal, &referenceFinal})
        if (img->width != w || img->height != h || img->pixels.size() != n * 4)
            throw std::invalid_argument("breakdownErrors: final images must be " + std::to_string(w) + "x" + std::to_string(h));
    if (!techniqueReflection.rgba.empty() && (techniqueReflection.width != w || techniqueReflection.height != h || techniqueReflection.rgba.size() != n * 4))
        throw std::invalid_argument("breakdownErrors: technique reflection must be " + std::to_string(w) + "x" + std::to_string(h));
    if (!referencePath.empty() && referencePath.size() != n * 2)
        throw std::invalid_argument("breakdownErrors: reflected paths hold " + std::to_string(referencePath.size()) + " floats, expected " +
                                    std::to_string(n * 2));
    ErrorBreakdown b;
    b.pathKnown = !referencePath.empty();
    std::vector<double> errors;
    std::array<double, kErrorClassCount> perClass{};
    for (size_t i = 0; i < n; ++i) {
        if (referenceReflection.rgba[i * 4 + 3] != gpu::kReflectionHit) continue;
        double e = 0.0;
        for (int c = 0; c < 3; ++c) {
            const double d = (double(techniqueFinal.pixels[i * 4 + c]) - double(referenceFinal.pixels[i * 4 + c])) / 255.0;
            e += d * d;
        }
        errors.push_back(e);
        b.squaredError += e;
        const size_t cls = static_cast<size_t>(classifyPixel(techniqueReflection, referenceReflection, referencePath, i));
        b.pixels[cls]++;
        perClass[cls] += e;
    }
    b.scoredPixels = errors.size();
    if (b.squaredError > 0.0)
        for (size_t c = 0; c < kErrorClassCount; ++c) b.share[c] = perClass[c] / b.squaredError;
    b.worst1PercentShare = shareOfWorst(errors, 0.01, b.squaredError);
    b.worst10PercentShare = shareOfWorst(std::move(errors), 0.10, b.squaredError);
    return b;
}

util::Rgba8Image errorClassImage(const FloatImage& referenceReflection, const std::vector<float>& referencePath, const util::Rgba8Image& context) {
    // One colour per class, in ErrorClass order; HoleFilled never appears (no technique here).
    static const uint8_t colours[kErrorClassCount][3] = {{255, 60, 60}, {255, 200, 40}, {60, 200, 255}, {200, 90, 255}, {255, 255, 255}, {70, 160, 70}};
    const size_t n = size_t(referenceReflection.width) * referenceReflection.height;
    if (context.pixels.size() != n * 4 || referenceReflection.rgba.size() != n * 4 || (!referencePath.empty() && referencePath.size() != n * 2))
        throw std::invalid_argument("errorClassImage: images of different sizes");
    util::Rgba8Image out = context;
    const FloatImage none;
    for (size_t i = 0; i < n; ++i) {
        uint8_t* p = &out.pixels[i * 4];
        if (referenceReflection.rgba[i * 4 + 3] != gpu::kReflectionHit) {
            for (int c = 0; c < 3; ++c) p[c] = static_cast<uint8_t>(p[c] / 4);
            continue;
        }
        const uint8_t* col = colours[static_cast<size_t>(classifyPixel(none, referenceReflection, referencePath, i))];
        p[0] = col[0], p[1] = col[1], p[2] = col[2];
    }
    return out;
}

}  // namespace ppr::app
