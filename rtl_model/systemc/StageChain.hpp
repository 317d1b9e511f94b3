// A pipeline as a list of stage modules in data-flow order (StageList).
// From the list, elaboration makes everything else: each module, and between
// each module and the next one clocked FIFO named for what the producer's
// output carries (M::kOutput); the schedule (issue lead, every stage's
// distance to scan-out) from the modules' latencies. The fast level reads the
// same list for its stage objects and FIFOs (FastCycleModel), so a pipeline's
// stages and FIFOs are written down once. Inserting a register stage is one
// more type in a list (testbench/systemc/AddStageBench.cpp).
#pragma once
#include <systemc>

#include <cstdint>
#include <memory>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "ClockGenerator.hpp"
#include "FifoChannel.hpp"
#include "rtl_model/stages/StageContext.hpp"

namespace arp::scm {

template <class... M>
struct StageList {
  static constexpr size_t kSize = sizeof...(M);
  using Modules = std::tuple<M...>;
  template <size_t I>
  using Module = std::tuple_element_t<I, Modules>;
  // The schedule of this pipeline: every module after the timing generator.
  static dp::PipelineSchedule schedule(const dp::ArpConfig& c) {
    std::vector<dp::ScheduledStage> chain;
    for_each_after_first(c, chain, std::make_index_sequence<kSize - 1>{});
    return dp::PipelineSchedule(c, chain);
  }
  // The FIFO between module I and I + 1 carries Module<I>::Output: channels
  // (which SystemC does not let move) held by pointer, plain cores by value.
  template <template <class> class Fifo, size_t... I>
  static auto fifo_tuple(std::index_sequence<I...>) -> std::tuple<std::unique_ptr<Fifo<typename Module<I>::Output>>...>;
  template <template <class> class Fifo>
  using Fifos = decltype(fifo_tuple<Fifo>(std::make_index_sequence<kSize - 1>{}));
  template <template <class> class Fifo, size_t... I>
  static auto fifo_value_tuple(std::index_sequence<I...>) -> std::tuple<Fifo<typename Module<I>::Output>...>;
  template <template <class> class Fifo>
  using FifoValues = decltype(fifo_value_tuple<Fifo>(std::make_index_sequence<kSize - 1>{}));
  template <template <class> class Fifo, size_t... I>
  static FifoValues<Fifo> make_fifo_values(int depth, std::index_sequence<I...>) {
    return FifoValues<Fifo>(Fifo<typename Module<I>::Output>(Module<I>::kOutput, depth)...);
  }

 private:
  template <size_t... I>
  static void for_each_after_first(const dp::ArpConfig& c, std::vector<dp::ScheduledStage>& out, std::index_sequence<I...>) {
    (out.push_back(Module<I + 1>::scheduled(c)), ...);
  }
};

// The detailed model's modules and FIFOs for a StageList, created and bound.
template <class List>
class StageChain {
 public:
  explicit StageChain(const stage::TimedInputs& in) : ctx_{in, List::schedule(in.config)} {
    make_modules(std::make_index_sequence<List::kSize>{});
    make_fifos(std::make_index_sequence<List::kSize - 1>{});
  }

  const stage::StageContext& context() const { return ctx_; }
  template <size_t I>
  typename List::template Module<I>& module() { return *std::get<I>(modules_); }
  template <size_t I>
  const typename List::template Module<I>& module() const { return *std::get<I>(modules_); }
  template <class Fn>
  void for_each_module(Fn&& fn) {
    std::apply([&](auto&... m) { (fn(*m), ...); }, modules_);
  }
  template <class Fn>
  void for_each_module(Fn&& fn) const {
    std::apply([&](const auto&... m) { (fn(*m), ...); }, modules_);
  }
  // Each FIFO's core (cycle semantics and statistics), in data-flow order.
  template <class Fn>
  void for_each_fifo(Fn&& fn) const {
    std::apply([&](const auto&... f) { (fn(f->core()), ...); }, fifos_);
  }
  template <class Fn>
  void for_each_fifo(Fn&& fn) {
    std::apply([&](auto&... f) { (fn(f->core()), ...); }, fifos_);
  }
  // Every module's clock port to `pixel_clock`.
  void bind_clock(ClockIf& pixel_clock) {
    for_each_module([&](auto& m) { m.clk(pixel_clock); });
  }

 private:
  template <size_t... I>
  void make_modules(std::index_sequence<I...>) {
    ((std::get<I>(modules_) = std::make_unique<typename List::template Module<I>>(List::template Module<I>::kInstance, ctx_)),
     ...);
  }
  template <size_t... I>
  void make_fifos(std::index_sequence<I...>) {
    const int depth = ctx_.config().timed.fifo_depth;
    ((std::get<I>(fifos_) = std::make_unique<FifoChannel<typename List::template Module<I>::Output>>(
          List::template Module<I>::kOutput, depth),
      module<I>().output(*std::get<I>(fifos_)), module<I + 1>().input(*std::get<I>(fifos_))),
     ...);
  }
  template <class... M>
  static auto module_tuple(std::tuple<M...>*) -> std::tuple<std::unique_ptr<M>...>;

  stage::StageContext ctx_;
  decltype(module_tuple(static_cast<typename List::Modules*>(nullptr))) modules_;
  typename List::template Fifos<FifoChannel> fifos_;
};

}  // namespace arp::scm
