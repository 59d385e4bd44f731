#pragma once
// The viewer's rolling per-pass GPU timing history: what the panel's timing table and plots show.
#include "graph/executor.hpp"

#include <deque>
#include <map>
#include <string>
#include <vector>

namespace ppr::app {

// Per-pass GPU times of the last kFrames frames, in the last frame's execution order.
class TimingHistory {
public:
    static constexpr size_t kFrames = 60;
    struct Row {
        std::string name;
        double medianMs = 0.0;
        std::vector<float> history;  // oldest first
    };
    void add(const std::vector<graph::PassTiming>& frame);
    std::vector<Row> rows() const;
    double totalMedianMs() const;
    std::vector<float> totals() const { return {totals_.begin(), totals_.end()}; }
    size_t passesHeld() const { return passes_.size(); }  // histories kept: the last frame's passes

private:
    std::vector<std::string> order_;
    std::map<std::string, std::deque<float>> passes_;
    std::deque<float> totals_;
};

}  // namespace ppr::app
