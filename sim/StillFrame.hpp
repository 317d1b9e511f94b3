// One HMD frame of the display memories' contents at one head orientation,
// through the functional model: what `arpsim frame` shows and reports.
#pragma once
#include <nlohmann/json.hpp>

#include <cstdint>
#include <string>

#include "MemoryContents.hpp"
#include "rtl_model/datapath/ArpConfig.hpp"
#include "rtl_model/datapath/HmdFrame.hpp"

namespace arp::sim {

struct StillSpec {
  dp::ArpConfig config;
  std::string config_source = "the configuration";  // names it in messages (--config's file)
  MemoryContents memories;
  dp::Quat orientation;  // head frame -> world
  int64_t frame = 0;     // its index: its photon times
  int threads = 0;
};

struct StillFrame {
  HmdFrame frame;
  std::string source;  // what filled the memories
  double refresh_hz = 0, render_ms = 0;
  int64_t first_photon_ps = 0, last_photon_ps = 0;
  size_t memory_bytes = 0;  // display memory allocated
  // Texels the fill drew where the memories have no storage: absent faces, tiles not held, a full tile pool.
  int64_t lost_on_absent_faces = 0, lost_off_tiles = 0, lost_pool_full = 0;
};

StillFrame render_still(const StillSpec& spec);
nlohmann::json still_report(const StillSpec& spec, const StillFrame& f, const std::string& image);

}  // namespace arp::sim
