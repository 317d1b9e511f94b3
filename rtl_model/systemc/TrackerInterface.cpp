#include "TrackerInterface.hpp"

#include <cmath>
#include <string>

#include "ClockGenerator.hpp"

namespace arp::scm {

using namespace sc_core;

TrackerInterface::TrackerInterface(sc_module_name name, const dp::OrientationStream& s, int64_t base_ps,
                                   int64_t end_ps)
    : sc_module(name), s_(s), base_ps_(base_ps), end_ps_(end_ps) {
  // The register's value at the start: the last sample at or before the base (or the first).
  const size_t i = s.index_at(base_ps);
  load(i);
  next_ = i + 1;
  SC_METHOD(write_next);
}

void TrackerInterface::load(size_t i) {
  sample = static_cast<uint32_t>(i);
  const dp::Quat& q = s_[i].q;
  auto q14 = [](double v) { return static_cast<int32_t>(std::lround(v * 16384.0)); };
  qw = q14(q.w);
  qx = q14(q.x);
  qy = q14(q.y);
  qz = q14(q.z);
}

void TrackerInterface::write_next() {
  const sc_time now = sc_time_stamp();
  // Every sample due by now (several may share a picosecond; the last wins).
  while (next_ < s_.size() && sim_time(std::max(s_[next_].time_ps, base_ps_), base_ps_) <= now) {
    load(next_++);
    ++writes_;
  }
  if (next_ < s_.size() && s_[next_].time_ps <= end_ps_) next_trigger(sim_time(s_[next_].time_ps, base_ps_) - now);
}

void TrackerInterface::trace(sc_trace_file* tf) const {
  const std::string n = name();
  sc_trace(tf, sample, n + ".sample");
  sc_trace(tf, qw, n + ".qw_q14");
  sc_trace(tf, qx, n + ".qx_q14");
  sc_trace(tf, qy, n + ".qy_q14");
  sc_trace(tf, qz, n + ".qz_q14");
}

}  // namespace arp::scm
