#include "viewer/timing_history.hpp"

#include "metrics/median.hpp"

#include <algorithm>

namespace ppr::app {

void TimingHistory::add(const std::vector<graph::PassTiming>& frame) {
    if (frame.empty()) return;
    auto push = [](std::deque<float>& d, float v) {
        d.push_back(v);
        while (d.size() > kFrames) d.pop_front();
    };
    order_.clear();
    double total = 0.0;
    for (const graph::PassTiming& t : frame) {
        order_.push_back(t.name);
        push(passes_[t.name], static_cast<float>(t.gpuMs));
        total += t.gpuMs;
    }
    push(totals_, static_cast<float>(total));
    // A pass no longer in the frame (another technique, a debug view switched off) drops its history:
    // coming back it starts afresh rather than mixing in stale times, and the map holds only the
    // passes of the current frame however many the session visits.
    std::erase_if(passes_, [&](const auto& pass) { return std::find(order_.begin(), order_.end(), pass.first) == order_.end(); });
}

std::vector<TimingHistory::Row> TimingHistory::rows() const {
    std::vector<Row> rows;
    for (const std::string& name : order_) {
        const std::deque<float>& d = passes_.at(name);
        Row r;
        r.name = name;
        r.history.assign(d.begin(), d.end());
        r.medianMs = median(std::vector<double>(d.begin(), d.end()));
        rows.push_back(std::move(r));
    }
    return rows;
}

double TimingHistory::totalMedianMs() const { return median(std::vector<double>(totals_.begin(), totals_.end())); }

}  // namespace ppr::app
