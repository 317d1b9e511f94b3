// Inputs for tests that render whole frames: layered display memories, a
// turning head, a small display.
#pragma once
#include <cstdint>

#include "rtl_model/datapath/ArpConfig.hpp"
#include "rtl_model/datapath/DisplayMemoryBank.hpp"
#include "rtl_model/datapath/OrientationMatrixUnit.hpp"
#include "rtl_model/datapath/VideoTiming.hpp"

namespace arp::test {

// Calibration pattern far away in memory 0; nearer squares in memories 1 and 2
// (overlapping at equal depth: the tie rule); the others left empty.
void fill_layered(dp::DisplayMemorySet& mem);

// 24 samples a millisecond apart from 2 ms before frame `frame` starts,
// turning `deg_per_ms` in yaw (and a third of that down in pitch) each millisecond.
dp::OrientationStream turning(const dp::VideoTiming& t, int64_t frame, double deg_per_ms);

// The configuration with a 160 x 120 display (fields and eye scan kept).
dp::ArpConfig small_display(dp::ArpConfig c);

}  // namespace arp::test
