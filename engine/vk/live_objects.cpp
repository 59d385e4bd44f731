#include "vk/live_objects.hpp"

namespace ppr::vk {

LiveObjects& liveObjects() {
    static LiveObjects counts;
    return counts;
}

}  // namespace ppr::vk
