#include "LiveLoop.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <thread>

#include "PoseConversion.hpp"
#include "common/InputError.hpp"

namespace arp::sim {

namespace {

using Clock = std::chrono::steady_clock;
constexpr int64_t kMotionAheadPs = 1'000'000'000'000;  // generated motion is kept a second around the frame (every latch lead)

const LiveSpec& checked(const LiveSpec& s, bool given_live) {
  if (!(s.seconds >= 0) || s.seconds > 24 * 3600) throw InputError("--seconds", "", "must be 0 (until the window closes) .. a day");
  const int sources = (!s.trace.empty()) + s.motion.given() + (!s.live.empty()) + given_live;
  if (sources > 1) throw InputError("--trace", "", "give one of --trace, --motion and --live");
  if (!s.live.empty() && s.live != "usb") throw InputError("--live", s.live, "the live source is usb (an Oculus Rift DK1/DK2)");
  check_record_live(s.record_live, !s.live.empty() || given_live);
  return s;
}

}  // namespace

LiveLoop::LiveLoop(const LiveSpec& spec) : LiveLoop(spec, nullptr) {}

LiveLoop::LiveLoop(const LiveSpec& spec, std::unique_ptr<tracker::PoseSource> live)
    : spec_(checked(spec, live != nullptr)),
      model_(spec_.config),
      frames_(spec_.seconds > 0 ? std::max<int64_t>(1, static_cast<int64_t>(std::llround(spec_.seconds * model_.timing().refresh_hz())))
                                : INT64_MAX),
      stream_(dp::OrientationStream::constant(dp::Quat{})),
      mem_(spec_.config.memory, spec_.config.timing.eyes) {
  // The head motion, from one pose source: all of it up front (trace, synthetic) or as it arrives (usb).
  source_ = live ? std::move(live) : tracker::live_source(spec_.live, spec_.tracker);  // none without --live (and --device alone is refused)
  if (!source_ && !spec_.trace.empty()) {
    source_ = tracker::trace_file_source(spec_.trace);
  } else if (!source_) {
    tracker::MotionSpec m = spec_.motion;
    if (!m.given()) m.motion = "shake";  // (at its peak: 100 deg/s by LiveSpec's default, or --peak)
    // Generated as the frames need it (a window ahead, trimmed behind): the loop starts at once and its
    // memory stays flat however long it runs. Until stopped: a day of motion, then its last pose held.
    const double span = (spec_.seconds > 0 ? spec_.seconds : 24 * 3600.0) + 1.0;
    motion_ = std::make_unique<tracker::MotionGenerator>(m.generator(0.0, span));  // the motion starts with frame 0
    source_name_ = "synthetic " + m.motion;
    std::vector<tracker::PoseSample> first;
    motion_->take_through(frame_start_ps(1) + kMotionAheadPs, first);
    stream_ = dp::OrientationStream(to_orientation_samples(first), source_name_);
  }
  if (source_) {
    source_name_ = source_->describe();
    if (!source_->live()) {
      source_->poll(got_, 0);
      stream_ = dp::OrientationStream(to_orientation_samples(got_), source_name_);
      got_.clear();
    }
    live_ = source_->live() ? source_.get() : nullptr;
  }
  if (live_) intake_ = std::make_unique<LiveIntake>(*live_, spec_.record_live);  // (--record-live opened before the work)
  MemoryContents contents = spec_.memories;
  contents.expect_plan(spec_.config, spec_.config_source);
  contents.fill(mem_, dp::Quat{}, memory_source_, spec_.threads);
}

// The loop's time 0: now, and a live source fixed against it (its last sample received is the pose at the start).
void LiveLoop::start_clock() {
  started_ = true;
  wall0_ = Clock::now();
  if (intake_) intake_->start(stream_, 0, source_name_);
}

LiveLoop::~LiveLoop() = default;

int64_t LiveLoop::frame_start_ps(int64_t k) const { return model_.timing().cycles_to_ps(model_.timing().frame_start_cycle(k)); }

std::vector<std::string> LiveLoop::take_events() { return live_ ? live_->take_events() : std::vector<std::string>{}; }

void LiveLoop::commit_record() {
  if (intake_) intake_->commit_record();
}

LiveFrame LiveLoop::next() {
  if (finished()) throw std::logic_error("LiveLoop::next after the last frame");
  if (!started_) start_clock();
  const double period_s = 1.0 / refresh_hz();
  // Frame k goes up k + 1 periods after the start (its scan-out ended). More than a frame behind, show the
  // latest frame due instead of each in turn: a loop that only counted its late frames stayed as far
  // behind as it ever fell (0.3 s of window set-up left a DK1's view half a second behind for good).
  const double elapsed_periods = std::chrono::duration<double>(Clock::now() - wall0_).count() / period_s;
  const int64_t latest_due = static_cast<int64_t>(std::min(elapsed_periods, 9e18)) - 1;
  const int64_t k = std::max(next_, std::min(latest_due, frames_ - 1));
  LiveFrame f;
  f.index = k;
  f.dropped = k - next_;
  dropped_ += f.dropped;
  next_ = k + 1;
  const auto due = wall0_ + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(static_cast<double>(k + 1) * period_s));
  while (Clock::now() < due) {
    if (live_) live_->poll(got_, 1);
    else std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  if (live_) {
    live_->poll(got_, 0);  // a late frame still takes every sample that arrived (frames are dropped, never samples)
    intake_->take(stream_, got_, source_name_);
    got_.clear();
    f.disconnected = !live_->connected();
  }
  if (motion_) {  // the generated motion's window: through the next frame and a second ahead
    std::vector<tracker::PoseSample> more;
    motion_->take_through(frame_start_ps(k + 2) + kMotionAheadPs, more);
    if (!more.empty()) stream_.append(to_orientation_samples(more), source_name_);
  }
  // Whatever the source, a second behind the frame is all a reader needs: memory stays flat however long
  // the loop runs (a tracker's 1 kHz held whole would grow by 144 MB an hour).
  stream_.discard_before(frame_start_ps(k) - kMotionAheadPs);
  RenderOptions ro;
  ro.threads = spec_.threads;
  ro.photon_times = true;
  const auto r0 = Clock::now();
  model_.render(mem_, stream_, k, frame_, ro);
  f.render_ms = std::chrono::duration<double, std::milli>(Clock::now() - r0).count();
  f.frame = &frame_;
  // Orientation sample -> photon over a grid of pixels (every 8th pixel and line).
  std::vector<int64_t> lat;
  for (int y = 0; y < frame_.height; y += 8)
    for (int x = 0; x < frame_.width; x += 8) {
      const size_t s = model_.latch_rule().sample(stream_, k, 0, x, y);
      lat.push_back(frame_.photon_ps[frame_.index(0, x, y)] - stream_[s].time_ps);
    }
  std::sort(lat.begin(), lat.end());
  f.latency_min_ps = lat.front();
  f.latency_median_ps = lat[lat.size() / 2];
  f.latency_max_ps = lat.back();
  return f;
}

}  // namespace arp::sim
