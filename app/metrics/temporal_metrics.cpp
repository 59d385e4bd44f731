#include "metrics/temporal_metrics.hpp"

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

TemporalSummary summarizeTemporal(const std::vector<TemporalFrame>& frames, bool still, uint32_t convergenceFrames) {
    if (frames.empty()) throw std::invalid_argument("summarizeTemporal: no frames");
    TemporalSummary s;
    s.frames = static_cast<uint32_t>(frames.size());
    for (const TemporalFrame& f : frames) {
        s.psnrDbMean += f.psnrDb / double(frames.size());
        s.reflectorPsnrDbMean += f.reflectorPsnrDb / double(frames.size());
    }
    if (still) {
        // Frame 0 has no previous frame: a single frame has nothing to flicker with.
        s.settledFrom = std::max(1u, std::min(convergenceFrames, s.frames / 2));
        double sum = 0.0;
        uint32_t counted = 0;
        for (uint32_t i = s.settledFrom; i < s.frames; ++i, ++counted) sum += frames[i].change;
        s.flicker = counted ? sum / counted : 0.0;
    }
    return s;
}

}  // namespace ppr::app
