// The frames of a run with detailed windows (--detail) that the detailed
// model does not simulate: while it idles through them (its video timing
// issues none of their pixels, its pixel clock is gated to the buffer swaps),
// each is computed by the functional model at its frame's start -- when the
// vertical blank before it has swapped the buffers and run the host, and the
// frame before it has been scanned out -- and given to the sink then, so the
// sink sees every frame of the run in order.
#pragma once
#include <systemc>

#include <cstdint>

#include "FunctionalFrames.hpp"
#include "rtl_model/datapath/VideoTiming.hpp"
#include "rtl_model/stages/StageContext.hpp"

namespace arp::scm {

class FunctionalStandIn : public sc_core::sc_module {
 public:
  SC_HAS_PROCESS(FunctionalStandIn);
  // Simulated time 0 is absolute time base_ps (the run's window). Keeps a reference to `in`.
  FunctionalStandIn(sc_core::sc_module_name name, const stage::TimedInputs& in, int64_t base_ps, int threads);

  int64_t frames_done() const { return done_; }

 private:
  void next();
  int64_t next_untimed(int64_t from) const;  // the first frame at or after `from` outside the windows (or the end)
  const stage::TimedInputs& in_;
  FunctionalFrames frames_;
  dp::VideoTiming timing_;
  int64_t base_ps_, end_frame_, frame_;
  int64_t done_ = 0;
};

}  // namespace arp::scm
