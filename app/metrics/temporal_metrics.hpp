#pragma once
// Scores of a camera path run (compare --path, docs/temporal.md): per frame PSNR against the
// supersampled reference, over the whole frame, over reflector pixels and over the reflector pixels a
// screen-space technique can reflect, and the frame-to-frame change that is flicker when the camera
// stands still.
#include "metrics/compare_metrics.hpp"
#include "util/image_io.hpp"

#include <cstdint>
#include <optional>
#include <vector>

namespace ppr::app {

// Mean absolute difference of the rgb channels of two display images, in 8-bit levels (0..255).
// Throws std::invalid_argument when the sizes differ.
double meanAbsoluteChange(const util::Rgba8Image& a, const util::Rgba8Image& b);

// The change from `previous` to `image` beyond the reference's own change from `referencePrevious`
// to `reference`: the mean over rgb of |(image - previous) - (reference - referencePrevious)|, in
// 8-bit levels. Flicker on a still camera when the scene moves (what the truth does not do); equal to
// meanAbsoluteChange(image, previous) when the reference does not change. Throws
// std::invalid_argument when the sizes differ.
double meanAbsoluteExcessChange(const util::Rgba8Image& image, const util::Rgba8Image& previous, const util::Rgba8Image& reference,
                                const util::Rgba8Image& referencePrevious);

// A frame's error against its reference as compare's heat maps show it (common/heat_map.h): on the
// pixels where `mask` (a reflection image, screen-sized) has alpha > 0, e = max over rgb of the display
// difference, black → red → yellow → white up to kErrorHeatFullScale; elsewhere `image` at 25 %.
// Throws std::invalid_argument when the sizes differ.
util::Rgba8Image displayErrorHeatMap(const util::Rgba8Image& image, const util::Rgba8Image& reference, const FloatImage& mask);

struct TemporalFrame {
    double psnrDb = 0.0;           // whole frame, against the supersampled reference
    double reflectorPsnrDb = 0.0;  // reflector pixels only
    double change = 0.0;           // meanAbsoluteChange from the previous frame (0 on the first)
    double excessChange = 0.0;     // meanAbsoluteExcessChange: the change the reference does not make
    double scoredPsnrDb = 0.0;     // compare's scored pixels: reflector pixels whose reflected point is on screen and unoccluded
};

struct TemporalSummary {
    double psnrDbMean = 0.0, reflectorPsnrDbMean = 0.0, scoredPsnrDbMean = 0.0;
    std::optional<double> flicker;  // still camera only: the mean excess change after convergence
    uint32_t frames = 0;
    uint32_t settledFrom = 0;       // first frame flicker counts (still camera)
};

// The means over every frame; with `still` (a still camera, the scene still or moving), flicker is
// the mean excess change over the frames from min(convergenceFrames, frames / 2) on — the history
// has taken in a whole jitter cycle by then.
// Throws std::invalid_argument for no frames.
TemporalSummary summarizeTemporal(const std::vector<TemporalFrame>& frames, bool still, uint32_t convergenceFrames);

}  // namespace ppr::app
