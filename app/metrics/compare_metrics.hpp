#pragma once
// `ppr compare`, CPU side: scoring a technique's reflection image against the planar ground truth,
// and the images that show the result (reflection term as displayed, error heat map).
//
// Both images are the RGBA16F reflection image of passes/common/reflection.h read back to the host:
// rgb = reflected radiance (linear HDR), a = kReflection* code. Errors are measured in display space
// (passes/tonemap/tonemap.h, the code the tonemap shader runs), so they match what the user sees.
#include "common/heat_map.h"
#include "scene/glass_atlas.hpp"
#include "util/image_io.hpp"

#include <cstdint>
#include <vector>

namespace ppr::app {

// Linear HDR image, 4 floats per pixel (rgba), rows top to bottom.
struct FloatImage {
    uint32_t width = 0, height = 0;
    std::vector<float> rgba;
};

// Converts VK_FORMAT_R16G16B16A16_SFLOAT bytes (tightly packed rows) to floats.
// Throws std::invalid_argument for a null pointer with a non-empty size.
FloatImage floatImageFromHalf(const void* rgba16f, uint32_t width, uint32_t height);

struct ReflectionScore {
    double psnrDb = 0.0;         // over the mask; capped at kPsnrCapDb (zero or negligible error)
    double coverage = 0.0;       // coveredPixels / maskPixels
    double mse = 0.0;            // mean over mask pixels and the 3 colour channels, display space [0,1]
    uint64_t maskPixels = 0;     // reference alpha == kReflectionHit
    uint64_t coveredPixels = 0;  // mask pixels where the technique's alpha > 0
};
constexpr double kPsnrCapDb = 100.0;

// Mask = pixels where the reference's alpha is kReflectionHit (a reflector pixel whose reflected point
// is on screen and unoccluded in the main view); everything else is ignored. PSNR compares
// displayFromRadiance(rgb, exposure) of technique and reference over the mask, peak 1:
// 10*log10(1/mse). Mask pixels where the technique has no reflection (alpha 0) count with the
// technique's rgb as-is (0, i.e. black): a missing reflection is an error.
// Display values that are not finite (NaN radiance) count as 1, so a NaN is a large error rather than
// a NaN score.
// Empty mask: psnrDb = kPsnrCapDb, coverage = 1, mse = 0, maskPixels = 0 (nothing to get wrong).
// Throws std::invalid_argument when the sizes differ or an image's rgba has the wrong length.
ReflectionScore scoreReflection(const FloatImage& technique, const FloatImage& reference, float exposure);

// The reference with every reflector pixel it has a reflection for marked kReflectionHit — those whose
// reflected point is on screen and those where it is off screen or hidden (kReflectionOffscreen) —
// so scoreReflection and compositedPsnrDb over it give the "all reflector pixels" figures
// (psnr_db_all, coverage_all: what the user sees, not only what the screen holds). Second bounces
// (kReflectionSecondary) stay out, as in the primary figure. Throws as scoreReflection.
FloatImage allReflectorPixels(const FloatImage& reference);

// Glass panels are scored in their reflection atlas (glass_reflect/glass_regions.hpp), texel by texel,
// with scoreReflection over the texels the reference marks kReflectionHit. For the composited score
// the screen pixels those texels stand for are needed: this returns a screen-sized image whose alpha
// is kReflectionHit exactly at the pixels (of the panels' footprints in `layout`) whose atlas texel the
// reference scores, 0 elsewhere — usable as compositedPsnrDb's `referenceReflection`.
FloatImage glassScreenMask(const FloatImage& referenceAtlas, const std::vector<scene::GlassRegion>& layout, uint32_t width,
                           uint32_t height);

// Pixel rectangle; x, y top-left.
struct PixelRect {
    uint32_t x = 0, y = 0, width = 0, height = 0;
};
// Same score, counting only pixels inside `region`. Throws std::invalid_argument when the region
// does not lie inside the images.
ReflectionScore scoreReflection(const FloatImage& technique, const FloatImage& reference, float exposure,
                                const PixelRect& region);

// PSNR of the reflection term as composited: the displayed final images (8-bit, identical lit scene)
// compared over the same mask, taken from `referenceReflection`. Outside reflections the two finals
// are the same picture, so every difference here is Fresnel × reflectance × the reflection error,
// tonemapped. Optional region as above. Same cap and empty-mask rules as scoreReflection.
double compositedPsnrDb(const util::Rgba8Image& technique, const util::Rgba8Image& reference, const FloatImage& referenceReflection,
                        const PixelRect* region = nullptr);

// The sum over every pixel's r, g and b of f(a − b), the difference in 8-bit levels (alpha is not a
// colour). Throws std::invalid_argument naming `what` when the sizes differ.
double sumOverRgbDifferences(const util::Rgba8Image& a, const util::Rgba8Image& b, const char* what, double (*f)(double));

// PSNR of two whole display images (rgb, 8-bit, peak 255), capped at kPsnrCapDb: TAA against its
// supersampled reference. Throws std::invalid_argument when the sizes differ.
double imagePsnrDb(const util::Rgba8Image& a, const util::Rgba8Image& b);

// The reflection term as the user sees it: displayFromRadiance(rgb) where alpha > 0, black elsewhere;
// 8-bit sRGB (display value * 255, rounded), alpha 255.
util::Rgba8Image reflectionDisplayImage(const FloatImage& reflection, float exposure);

// Full-scale error of the heat map: e >= this is white.
constexpr float kHeatMapFullScale = gpu::kErrorHeatFullScale;  // common/heat_map.h
// Colour of reflector pixels outside the mask (reference alpha kReflectionOffscreen / kReflectionSecondary).
constexpr uint8_t kHeatMapOffscreenGrey = 64;

// Error heat map. Mask pixels: e = max over rgb of |display(technique) - display(reference)|, mapped
// through black → red → yellow → white (equal thirds of [0, kHeatMapFullScale], clamped above).
// Other reference reflections (alpha > 0 but not kReflectionHit): grey kHeatMapOffscreenGrey. Everything else: `context` (the
// technique's final image) at 25 % brightness so the viewer can orient themselves; an empty context
// (0x0) gives black there. Throws std::invalid_argument on size mismatch.
util::Rgba8Image errorHeatMap(const FloatImage& technique, const FloatImage& reference, float exposure,
                              const util::Rgba8Image& context);

}  // namespace ppr::app
