#include "TimedRun.hpp"

#include <systemc>

#include <chrono>
#include <cstdio>
#include <memory>
#include <stdexcept>

#include "ArpPipelineTop.hpp"
#include "ClockGenerator.hpp"
#include "FastCycleModel.hpp"
#include "FunctionalFrames.hpp"
#include "FunctionalStandIn.hpp"
#include "LooselyTimedModel.hpp"
#include "VcdClose.hpp"
#include "common/InputError.hpp"
#include "rtl_model/verilated/VerilatedFrameModel.hpp"

namespace arp::scm {

using namespace sc_core;

const EnumNames<Fidelity>& fidelity_names() {
  static const EnumNames<Fidelity> n{{Fidelity::Functional, "functional"}, {Fidelity::LooselyTimed, "lt"}, {Fidelity::Cycle, "cycle"}, {Fidelity::Detailed, "detailed"}, {Fidelity::Verilated, "verilated"}};
  return n;
}

bool parse(const std::string& s, Fidelity& out) {
  if (s == "rtl") {  // the name this level had before a level backed by real RTL existed
    out = Fidelity::Detailed;
    return true;
  }
  return enum_parse(fidelity_names(), s, out);
}

const char* describe(Fidelity f) {
  switch (f) {
    case Fidelity::Functional: return "untimed functional model (bit-accurate frames, computed photon times)";
    case Fidelity::LooselyTimed: return "loosely timed, one-scanline quantum (SystemC thread)";
    case Fidelity::Cycle: return "fast cycle-accurate, one SystemC process per clock domain";
    case Fidelity::Detailed: return "detailed cycle-accurate, one SC_MODULE per stage with clocked FIFO channels";
    case Fidelity::Verilated:
      return "the functional level's timing with the verilated RTL (rtl_model/hdl) doing the per-pixel arithmetic";
  }
  return "?";
}

namespace {

using Clock = std::chrono::steady_clock;

// The SystemC modules under these objects, at any depth (what the run elaborated).
int64_t count_modules(const std::vector<sc_object*>& objects) {
  int64_t n = 0;
  for (const sc_object* o : objects) n += (dynamic_cast<const sc_module*>(o) ? 1 : 0) + count_modules(o->get_child_objects());
  return n;
}

void check_inputs(const stage::TimedInputs& in, bool timed) {
  const auto issues = timed ? dp::validate_timed(in.config) : dp::validate(in.config);
  if (!issues.empty()) throw InputError("configuration", issues.front().key, issues.front().reason);
  if (!in.memories || !in.orientation) throw std::logic_error("run_timed: memories and orientation are required");
  // (every level reads the memories with the configuration's layout: face size, tiles, pools)
  if (!dp::matches(*in.memories, in.config)) throw std::logic_error("run_timed: the memory set does not match the configuration");
  if (in.frames < 1) throw InputError("frames", "", "must be at least 1");
  if (in.first_frame < 0) throw InputError("first frame", "", "must be >= 0");
  stage::check_host_jobs(in.host_jobs, in.config, "host write jobs");
}

// The functional and verilated levels: frames from the untimed model (or the
// verilated RTL), host jobs at their vertical blanks, photon times and
// latencies computed from the schedule.
TimedResult run_functional(const stage::TimedInputs& in, const TimedRunOptions& opt) {
  TimedResult r;
  r.fidelity = opt.fidelity;
  std::unique_ptr<vl::VerilatedFrameModel> rtl;
  FunctionalFrames::Renderer renderer;
  if (opt.fidelity == Fidelity::Verilated) {
    rtl = std::make_unique<vl::VerilatedFrameModel>(in.config);
    renderer = [&rtl, &in](int64_t frame, HmdFrame& f) { rtl->render(*in.memories, *in.orientation, frame, f, true); };
  }
  FunctionalFrames frames(in, opt.threads, renderer);
  const stage::StageContext ctx{in, dp::PipelineSchedule(in.config)};
  const dp::PipelineSchedule& sched = ctx.schedule;
  const auto& t = frames.model().timing();
  const stage::VideoTimingStage timing(ctx);  // the run's clocks and the frames' last slots, as the timed levels have them
  stage::PlannedHostWrites host(in.config, in.host_jobs);
  const auto t0 = Clock::now();
  for (int64_t k = 0; k < in.frames; ++k) {
    const int64_t frame = in.first_frame + k;
    if (in.before_frame) in.before_frame(frame, t.frame_start_s(frame));
    const stage::FrameReport fr = frames.render(frame);
    if (in.sink) in.sink(frames.frame(), fr);
    ++r.frames;
    r.swaps += host.at_vertical_blank(t.cycles_to_ps(sched.swap_cycle(frame)), *in.memories);
    if (opt.progress)
      opt.progress(static_cast<double>(k + 1) / static_cast<double>(in.frames),
                   "frame " + std::to_string(k + 1) + "/" + std::to_string(in.frames));
    if (k + 1 < in.frames && opt.stop && opt.stop()) {
      r.stopped = true;
      break;
    }
  }
  r.wall_seconds = std::chrono::duration<double>(Clock::now() - t0).count();
  r.host_jobs = host.timings();
  r.first_cycle = timing.first_cycle();
  r.end_cycle = r.stopped ? std::min(timing.end_cycle(), timing.scan().last_slot(in.first_frame + r.frames - 1) + 1) : timing.end_cycle();
  r.issue_lead = sched.issue_lead();
  r.orientation_lead = sched.orientation_lead();
  return r;
}

// What both cycle-accurate levels measure, from their stages.
template <class Model>
void fill_cycle_statistics(TimedResult& r, const Model& m, const stage::MemoryReadStage& memories,
                           const stage::HostWritePort& host, const stage::VideoTimingStage& timing,
                           const stage::ScanOutStage& scan_out, int64_t end_cycle) {
  r.stages_measured = r.fifos_modelled = true;
  r.stages = m.stage_stats();
  r.fifos = m.fifo_stats(end_cycle);
  r.host_jobs = host.timings();
  r.swaps = memories.swapper().swaps();
  r.underflows = scan_out.underflows();
  r.issue_stalls = timing.issue_stalls();
  r.orientation_writes = m.tracker_interface().writes();
  r.late_discarded = scan_out.late_discarded();
  r.evaluated_cycles = m.evaluated_cycles();
  r.evaluated_host_cycles = m.evaluated_host_cycles();
}

bool g_simulated = false;

}  // namespace

void claim_simulation() {
  if (g_simulated) throw std::logic_error("SystemC cannot run a second simulation in one process");
  g_simulated = true;
  sc_set_time_resolution(1, SC_PS);
  sc_report_handler::set_actions(SC_INFO, SC_DO_NOTHING);  // e.g. the trace file's time-unit notice
}

TimedResult run_timed(const stage::TimedInputs& in, const TimedRunOptions& opt) {
  if (opt.fidelity == Fidelity::Functional || opt.fidelity == Fidelity::Verilated) {
    check_inputs(in, false);
    return run_functional(in, opt);
  }
  check_inputs(in, true);
  const bool windows = !in.timed_frames.every_frame();
  if (windows && opt.fidelity != Fidelity::Detailed)
    throw InputError("--detail", "", "detailed windows switch between the functional and the detailed level (--fidelity functional or detailed)");
  claim_simulation();

  TimedResult r;
  r.fidelity = opt.fidelity;
  stage::TimedInputs run_in = in;  // the models keep references to the inputs
  const stage::FrameSink user_sink = in.sink;
  const int64_t frames = in.frames;
  run_in.sink = [&r, &user_sink, &opt, frames](const HmdFrame& f, const stage::FrameReport& fr) {
    ++r.frames;
    if (user_sink) user_sink(f, fr);
    if (opt.progress)
      opt.progress(static_cast<double>(r.frames) / static_cast<double>(frames),
                   "frame " + std::to_string(r.frames) + "/" + std::to_string(frames));
    if (r.frames < frames && opt.stop && opt.stop()) {
      r.stopped = true;
      sc_stop();  // the kernel returns from sc_start at the end of this delta cycle
    }
  };

  std::unique_ptr<ArpPipelineTop> rtl;
  std::unique_ptr<FastCycleModel> fast;
  std::unique_ptr<LooselyTimedModel> lt;
  std::unique_ptr<FunctionalStandIn> untimed;  // the frames between detailed windows
  RunWindow w{};
  switch (opt.fidelity) {
    case Fidelity::Detailed:
      rtl = std::make_unique<ArpPipelineTop>("arp", run_in, opt.clock_gating);
      w = rtl->window();
      if (windows) untimed = std::make_unique<FunctionalStandIn>("functional_frames", run_in, w.base_ps, opt.threads);
      break;
    case Fidelity::Cycle:
      // Waveforms show every stage's data: no speculation while tracing.
      fast = std::make_unique<FastCycleModel>("arp", run_in, opt.vcd.path.empty() && opt.speculate, opt.clock_gating);
      w = fast->window();
      break;
    default:
      lt = std::make_unique<LooselyTimedModel>("arp", run_in);
      w = lt->window();
      break;
  }
  r.modules = count_modules(sc_get_top_level_objects());
  const dp::PipelineSchedule sched = ArpStages::schedule(in.config);
  r.first_cycle = w.first_cycle;
  r.end_cycle = w.end_cycle;
  r.issue_lead = sched.issue_lead();
  r.orientation_lead = sched.orientation_lead();

  // The waveform window, in simulated time.
  const int64_t span = w.end_ps - w.base_ps;
  int64_t from = 0, to = span + 1;
  if (!opt.vcd.path.empty()) {
    from = std::max<int64_t>(0, std::min(span, opt.vcd.from_ps == INT64_MIN ? 0 : opt.vcd.from_ps - w.base_ps));
    to = std::max(from, std::min(span + 1, opt.vcd.to_ps == INT64_MAX ? span + 1 : opt.vcd.to_ps - w.base_ps));
    if (from > 0) {  // the models must not run ahead past the window's start before it opens
      if (fast) fast->trace_from(w.base_ps + from);
      if (rtl) rtl->trace_from(w.base_ps + from);
    }
  }
  sc_trace_file* tf = nullptr;
  const sc_time vcd_unit(1, SC_PS);
  auto open_trace = [&] {
    tf = sc_create_vcd_trace_file(opt.vcd.path.c_str());
    if (!tf) throw InputError(opt.vcd.path + ".vcd", "", "cannot create the waveform file");
    tf->set_time_unit(1, SC_PS);  // vcd_unit
    if (rtl) rtl->trace(tf, opt.vcd.data);
    if (fast) fast->trace(tf, opt.vcd.data);
    if (lt) lt->trace(tf);
  };

  // The host model's state before the first frame (the timed levels call it in each later vertical blank),
  // timed with the run: the host's wall time is reported apart (host_wall_ms_per_frame, every frame's render),
  // and what is left of wall_seconds is the pipeline's at every level.
  const auto t0 = Clock::now();
  if (in.before_frame) {
    const dp::VideoTiming vt(in.config.timing);
    in.before_frame(in.first_frame, vt.frame_start_s(in.first_frame));
  }
  auto advance_to = [&r](int64_t sim_ps) {
    const sc_time target = sc_time::from_value(static_cast<sc_time::value_type>(sim_ps));
    if (!r.stopped && target > sc_time_stamp()) sc_start(target - sc_time_stamp());
  };
  if (!opt.vcd.path.empty()) {
    if (from > 0) advance_to(from);
    open_trace();
    advance_to(to);
    const std::string file = opt.vcd.path + ".vcd";
    close_vcd_checked(tf, file, vcd_unit, opt.vcd.shown.empty() ? file : opt.vcd.shown);
    tf = nullptr;
    if (rtl) rtl->stop_tracing();
    if (fast) fast->stop_tracing();
  }
  advance_to(span + 1);
  r.wall_seconds = std::chrono::duration<double>(Clock::now() - t0).count();
  if (r.stopped) {  // statistics over the clocks simulated
    const dp::VideoTiming vt(in.config.timing);
    r.end_cycle = std::min(w.end_cycle, vt.ps_to_cycle_floor(w.base_ps + static_cast<int64_t>(sc_time_stamp().value())) + 1);
    w.end_cycle = r.end_cycle;
  }

  if (untimed) r.untimed_frames = untimed->frames_done();
  if (rtl) {
    fill_cycle_statistics(r, *rtl, rtl->memories().stage(), rtl->memories().host_port(), rtl->timing().stage(),
                          rtl->scan_out().stage(), w.end_cycle);
  } else if (fast) {
    fill_cycle_statistics(r, *fast, fast->memories(), fast->host_port(), fast->timing(), fast->scan_out(), w.end_cycle);
    if (fast->speculation()) {
      r.speculated_pixels = fast->speculation()->speculated;
      r.fallback_pixels = fast->speculation()->fallbacks;
    }
  } else {
    r.host_jobs = lt->host_timings();
    r.swaps = lt->swaps();
    r.orientation_writes = lt->tracker_interface().writes();
  }
  return r;
}

}  // namespace arp::scm
