#pragma once
// The median of a list of measurements (GPU times over frames, over bench rounds).
#include <vector>

namespace ppr::app {

// The middle value, or the mean of the two middle ones; 0 for an empty list.
double median(std::vector<double> values);

}  // namespace ppr::app
