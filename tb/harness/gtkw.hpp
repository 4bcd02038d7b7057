// GTKWave save file that opens a mismatch waveform with the block's ports shown, the view
// on the window and the marker on the mismatching cycle.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "harness/block.hpp"

namespace tmu::tb {

void write_gtkw(const std::string& path, const std::string& fst_path,
                const std::vector<Port>& ports, uint64_t time_start, uint64_t time_end,
                uint64_t marker_time);

}  // namespace tmu::tb
