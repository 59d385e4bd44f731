#pragma once
// `ppr compare`: where a technique's error is. Over the pixels the reference scores (alpha
// kReflectionHit), the squared error of the composited image (what psnr_db measures) is summed
// per pixel, and reported two ways:
//  - concentration: the share of all squared error carried by the worst 1 % and 10 % of the pixels;
//  - by kind of pixel: each scored pixel falls in the first class below that applies.
// The classes come from the reference (and, for HoleFilled, the technique's own alpha), so every
// technique's error is split over the same pixels (docs/quality.md).
#include "metrics/compare_metrics.hpp"

#include <array>
#include <cstdint>
#include <vector>

namespace ppr::app {

enum class ErrorClass : uint32_t {
    ReflectorEdge,     // a neighbour (3x3) is not a reflector pixel, or lies off the image
    DisocclusionEdge,  // a neighbour is a reflector pixel the reference does not score (its reflected
                       // point is hidden, off screen or another reflector)
    SilhouetteSeam,    // the reflected path length jumps to a neighbour (a depth discontinuity in the
                       // reflected image: an object's silhouette against what lies behind it)
    ParallelShape,     // a nearer parallel reflector also reflects this pixel's point (planar.h)
    HoleFilled,        // the technique took this pixel from a neighbour (alpha kReflectionFilled)
    Interior,          // none of the above
};
constexpr size_t kErrorClassCount = 6;
const char* errorClassName(ErrorClass c);  // "reflector_edge", … (the metrics.json keys)

// A silhouette seam: neighbouring reflected path lengths differ by more than this fraction of the
// shorter one, or one of them is sky.
constexpr float kSilhouetteRelativeJump = 0.1f;

struct ErrorBreakdown {
    uint64_t scoredPixels = 0;
    double squaredError = 0.0;        // sum over scored pixels and the 3 channels, display units
    double worst1PercentShare = 0.0;  // of squaredError, in the ceil(1 %) worst pixels; 0 without error
    double worst10PercentShare = 0.0;
    std::array<uint64_t, kErrorClassCount> pixels{};
    std::array<double, kErrorClassCount> share{};  // of squaredError; 0 without error
    bool pathKnown = false;  // false: no reflected paths (a reference other than planar), so no pixel
                             // is a silhouette seam or parallel shape
};

// The class of scored pixel i. `referencePath` is planar's planar.distance readback (2 floats per
// pixel) or empty; `technique` may be empty (0x0: a technique without a reflection image).
ErrorClass classifyPixel(const FloatImage& technique, const FloatImage& reference, const std::vector<float>& referencePath, size_t i);

// Throws std::invalid_argument when the sizes disagree (images, or a non-empty path of the wrong length).
ErrorBreakdown breakdownErrors(const util::Rgba8Image& techniqueFinal, const util::Rgba8Image& referenceFinal,
                               const FloatImage& techniqueReflection, const FloatImage& referenceReflection,
                               const std::vector<float>& referencePath);

// The classes as colours over the scored pixels (the reference's final image dimmed elsewhere);
// the HoleFilled class needs a technique, so this shows the reference's classes only.
util::Rgba8Image errorClassImage(const FloatImage& referenceReflection, const std::vector<float>& referencePath,
                                 const util::Rgba8Image& context);

}  // namespace ppr::app
