// The tracker's side of the orientation register: writes each sample into
// the register at its simulated time, so the register's contents (sample
// number and quaternion, Q1.14) can be seen in a waveform. The orientation
// matrix unit reads the same register (stage::OrientationStage).
#pragma once
#include <systemc>

#include <cstdint>

#include "rtl_model/datapath/OrientationMatrixUnit.hpp"

namespace arp::scm {

class TrackerInterface : public sc_core::sc_module {
 public:
  SC_HAS_PROCESS(TrackerInterface);
  // Writes the samples from absolute time base_ps up to end_ps.
  TrackerInterface(sc_core::sc_module_name name, const dp::OrientationStream& s, int64_t base_ps, int64_t end_ps);
  void trace(sc_core::sc_trace_file* tf) const;

  int64_t writes() const { return writes_; }

  // Traced: the register.
  uint32_t sample = 0;
  int32_t qw = 0, qx = 0, qy = 0, qz = 0;

 private:
  void write_next();
  void load(size_t i);
  const dp::OrientationStream& s_;
  int64_t base_ps_, end_ps_;
  size_t next_;
  int64_t writes_ = 0;
};

}  // namespace arp::scm
