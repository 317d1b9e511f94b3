// The display memories' pipeline read port: every memory and tap read in
// parallel from the front buffers (the words DisplayMemoryBank::read
// returns), with the double-buffer swap at the vertical blank on the pixel
// clock (BufferSwapper) and, once, the host model's turn in that blank;
// timed.fetch_latency clocks. The memories are the host's too: the host write
// port (HostWritePort, host clock) fills their back buffers.
#pragma once
#include <cstdint>
#include <functional>
#include <limits>
#include <array>

#include "HostWritePort.hpp"
#include "RegisteredStage.hpp"
#include "rtl_model/datapath/AntiAliasingFilter.hpp"

namespace arp::stage {

// The pipeline side of the double buffers: at a vertical blank every bank
// whose commit came strictly before it swaps.
class BufferSwapper {
 public:
  // `hook`: a host model acting at each vertical blank before frames up to
  // `hook_end` (exclusive), called with the next frame and its start in seconds.
  BufferSwapper(const dp::ArpConfig& c, dp::DisplayMemorySet& mem, const HostWritePort* host, int64_t hook_end,
                std::function<void(int64_t, double)> hook);
  // Whose commits the swaps take.
  void connect(const HostWritePort* host) { host_ = host; }
  // Call every pixel clock before the memories are read; swaps at swap cycles.
  void tick(int64_t cycle);
  int64_t swaps() const { return swaps_; }
  // Changes to the front buffers so far: swaps and host-model calls (FrameSpeculation's check).
  int64_t generation() const { return swaps_ + host_calls_; }
  // Traced: which buffer of each bank is in front (bit per bank), pulsed swap strobe.
  uint32_t front_select = 0;
  bool swap_strobe = false;

 private:
  dp::DisplayMemorySet* mem_;
  const HostWritePort* host_;
  dp::VideoTiming timing_;
  dp::PipelineSchedule sched_;
  int64_t swaps_ = 0, host_calls_ = 0;
  std::function<void(int64_t, double)> hook_;
  int64_t hook_end_ = 0;
  int64_t next_swap_ = std::numeric_limits<int64_t>::min(), last_cycle_ = std::numeric_limits<int64_t>::max();
};

class MemoryReadStage : public RegisteredStage<MemoryReadStage, AddressToken, FetchToken, kMemoryReadInfo> {
 public:
  explicit MemoryReadStage(const StageContext& ctx);
  // The write port whose commits this port's swaps take (the same module's).
  void connect(const HostWritePort* host) { swapper_.connect(host); }

  // The swap happens first, in the same clock.
  template <class InFifo, class OutFifo, class Fn>
  void tick_with(int64_t cycle, InFifo& in, OutFifo& out, Fn&& compute) {
    swapper_.tick(cycle);
    RegisteredStage::tick_with(cycle, in, out, compute);
  }
  void compute(const AddressToken& in, FetchToken& t) const;

  template <class Fn>
  void for_each_own_probe(Fn&& fn) const {
    fn("front_select", swapper_.front_select);
    fn("swap_strobe", swapper_.swap_strobe);
  }
  const BufferSwapper& swapper() const { return swapper_; }
  BufferSwapper& swapper() { return swapper_; }
  const dp::DisplayMemorySet& memories() const { return mem_; }

 private:
  template <bool Bilinear>
  void fetch(const AddressToken& in, FetchToken& t) const;
  dp::DisplayMemorySet& mem_;
  BufferSwapper swapper_;
  int memories_, texel_frac_, face_size_, tiles_per_row_;
  bool bilinear_;
  uint64_t empty_word_;  // what every address of a face never written reads
};

}  // namespace arp::stage
