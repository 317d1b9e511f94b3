// The verilated level: whole HMD frames like the functional model's, with
// the per-pixel arithmetic of the orientation matrix unit, the cube-face
// address generator, the composition unit and the bilinear filter done by
// the verilated RTL (rtl_model/hdl) instead of the datapath's C++. The
// lens vectors, the latch, the tap addresses and the memory reads, and
// scan-out stay the datapath's. Single-threaded and slow: it is the RTL
// proving itself on real frames, bit for bit against every other level.
#pragma once
#include <cstdint>
#include <string>

#include "VerilatedUnits.hpp"
#include "rtl_model/datapath/AntiAliasingFilter.hpp"
#include "rtl_model/datapath/ArpConfig.hpp"
#include "rtl_model/datapath/DisplayMemoryBank.hpp"
#include "rtl_model/datapath/HmdFrame.hpp"
#include "rtl_model/datapath/HmdScanOut.hpp"
#include "rtl_model/datapath/LensVectorTable.hpp"
#include "rtl_model/datapath/OrientationMatrixUnit.hpp"
#include "rtl_model/datapath/VideoTiming.hpp"

namespace arp::vl {

class VerilatedFrameModel {
 public:
  // Validates the configuration and picks the RTL builds that match it;
  // InputError("configuration", ...) naming what is missing otherwise.
  explicit VerilatedFrameModel(const dp::ArpConfig& cfg);

  const std::string& rtl_configuration() const { return units_.configuration; }

  // Renders frame `frame`, as FunctionalModel::render does.
  void render(const dp::DisplayMemorySet& mem, const dp::OrientationStream& orientation, int64_t frame,
              HmdFrame& out, bool photon_times) const;

 private:
  dp::ArpConfig cfg_;
  dp::VideoTiming timing_;
  dp::LensVectorTable lens_;
  dp::MemoryFormat fmt_;
  dp::HmdScanOut scan_;
  dp::LatchRule latch_;
  mutable Units units_;  // the models' state moves as they run
};

}  // namespace arp::vl
