#pragma once
// The GPU times of one frame's passes as either API's timestamp ring reads them back (gl/TimerQueryRing,
// vk/TimestampRing), frames after the frame was submitted.
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace sb {

struct PassTimes {
    uint64_t frame = 0;
    std::vector<std::pair<std::string, double>> passMs; ///< in pass order (a pass entered twice, twice)
    double totalMs = 0.0;                               ///< first stamp to the frame's end
};

} // namespace sb
