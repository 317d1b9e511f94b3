// One run, as a library: from a RunSpec it builds the head motion (trace,
// synthetic, a walk, or a live tracker), the display memories (a cube map, or
// a host simulating priority rendering over a walk), the probes (error
// against the truth), checks every output can be written, then drives the
// pipeline at the chosen fidelity frame by frame and writes the outputs.
// `arpsim run`, the benches and the tests all run through it.
#pragma once
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "HostReport.hpp"
#include "LiveIntake.hpp"
#include "RunReport.hpp"
#include "RunSpec.hpp"
#include "host/motion/WalkPath.hpp"
#include "host/priority/HostSimulation.hpp"
#include "host/regions/RegionScheduler.hpp"
#include "host/regions/Segmentation.hpp"
#include "rtl_model/systemc/TimedRun.hpp"
#include "tracker/MotionSummary.hpp"
#include "tracker/PoseSource.hpp"
#include "tracker/TraceFile.hpp"

namespace arp::sim {

class TruthProbe;

class Session {
 public:
  // Validates the spec and builds everything a run needs; InputError (naming
  // the option, file or key) before anything is simulated or written.
  explicit Session(RunSpec spec);
  ~Session();

  // Hooks: progress (fraction done, what), and each frame as it is scanned out.
  std::function<void(double, const std::string&)> on_progress;
  std::function<void(const HmdFrame&, const stage::FrameReport&)> on_frame;
  // Polled after each frame: non-zero ends the run there (the signal that
  // asked, e.g. from common/Interrupt). The outputs then cover the frames
  // finished; the report says "complete": false.
  std::function<int()> stop_when;

  // Runs the pipeline and writes the outputs; the summary for the command to print.
  RunSummary run();

  const RunSpec& spec() const { return spec_; }
  scm::Fidelity fidelity() const { return fidelity_; }
  // The frames simulated at the timed level (--detail; default: every frame).
  const stage::FrameWindows& timed_frames() const { return timed_frames_; }
  const std::string& motion_source() const { return motion_source_; }
  // The display memories (after run(): as the run left them, with the tiles it drew on).
  const dp::DisplayMemorySet& memories() const { return memories_; }
  const std::string& memory_source() const { return memory_source_; }
  // What the motion looks like, for the command to print before the run: a
  // trace's summary over the run's window and its warnings (empty otherwise).
  const std::vector<std::string>& motion_notes() const { return motion_notes_; }

 private:
  void build_detail_windows();
  void add_auto_detail();
  std::pair<int64_t, int64_t> stall_frames(const stage::StallWindow& st) const;
  void build_motion();
  using MorePoses = std::function<bool(int64_t, std::vector<tracker::PoseSample>&)>;
  MorePoses pose_source(bool consume) const;
  void face_walk(std::vector<tracker::PoseSample>& poses) const;
  std::vector<double> frame_speeds_dps() const;
  void warn_if_planned_for_another_motion() const;
  void check_assignment() const;
  void extend_motion(int64_t through_ps);
  void advance_motion(int64_t frame);
  void build_memories();
  void build_live_input(stage::TimedInputs& in);
  void build_outputs(scm::TimedRunOptions& opt);
  std::vector<stage::StallWindow> stall_windows() const;
  std::optional<std::pair<int64_t, int64_t>> vcd_option_window() const;
  void on_scanned_out(const HmdFrame& f, const stage::FrameReport& r);

  RunSpec spec_;
  scm::Fidelity fidelity_ = scm::Fidelity::Functional;
  stage::FrameWindows timed_frames_;
  // --stall's windows and --vcd-lines' or --vcd-time-us' span (ps), checked with the options, before any work.
  std::vector<stage::StallWindow> stalls_;
  std::optional<std::pair<int64_t, int64_t>> vcd_window_;
  std::vector<stage::FrameWindows::Window> detail_windows_;  // --detail's, counted from the first frame
  bool auto_detail_ = false;                                   // --detail auto
  int64_t auto_fast_frames_ = 0, auto_stall_frames_ = 0;
  dp::VideoTiming timing_;
  int64_t start_ps_ = 0, end_ps_ = 0;  // the run's first frame's start, the start of the frame after its last
  int64_t timed_end_ps_ = 0;            // where the timed levels stop: the last frame's vertical blank (swap)
  // The motion not yet in the stream: appends the poses through a time (and
  // one past it) and says whether it has given all it has.
  MorePoses more_poses_;
  std::shared_ptr<std::vector<tracker::PoseSample>> trace_poses_;  // a trace over the run's window, until the run takes it
  bool motion_started_ = false, motion_done_ = false;
  int64_t last_pose_ps_ = 0;
  std::string motion_source_ = "still head", memory_source_;
  std::optional<tracker::MotionSummary> trace_summary_;
  std::vector<std::string> motion_notes_;
  std::unique_ptr<host::WalkPath> walk_;
  std::unique_ptr<tracker::PoseSource> live_;
  std::unique_ptr<LiveIntake> live_intake_;  // what the run takes from live_, recorded (--record-live) and counted
  dp::OrientationStream stream_;
  dp::DisplayMemorySet memories_;
  std::unique_ptr<host::Scene> scene_;
  std::unique_ptr<host::HostSimulation> host_;
  std::unique_ptr<host::RegionGrid> grid_;
  std::unique_ptr<host::RegionScheduler> regions_;
  host::Segmented segmented_;
  std::unique_ptr<TruthProbe> probe_;
  std::unique_ptr<FrameLog> log_;
  std::string vcd_final_, vcd_tmp_base_;
  int64_t images_ = 0, baseline_triangles_ = 0;
  int64_t live_behind_ps_ = 0, live_behind_max_ps_ = 0;  // how far the run's frames lag the tracker's clock
  int64_t live_held_max_ = 0;  // the most live samples the stream held at a frame's end (trimmed behind the frame)
  std::string live_lag_text() const;
  double host_wall_s_ = 0;
  double probe_wall_s_ = 0;  // measuring the error against the truth (its renders and its pipeline)
  size_t memory_peak_bytes_ = 0;  // the display memories' storage, largest at a frame's end
};

}  // namespace arp::sim
