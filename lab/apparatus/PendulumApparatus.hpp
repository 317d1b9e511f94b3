// Olano et al.'s external latency measurement, simulated (their figure 1):
// a tracker on a pendulum, an LED/photodiode pair at the pendulum's low point,
// the graphics system's render-start signal, and a photodiode on the screen.
//
// The world behind the screen is light on one side of the pendulum's
// low-point direction and dark on the other, so the image at the screen
// photodiode (the screen centre) turns light or dark exactly when the system
// draws it from a pose past the low point -- the equivalent of their "frames
// alternate dark and light, a new frame started when the low point is seen in
// the tracking data", for any architecture, the ARP included (its rotation is
// applied at scan-out, no re-render needed). The render-start signal pulses
// when the system starts computing the first such image (for the ARP: the
// orientation latch of the centre pixel; for just-in-time pixels: the centre
// line's transform; conventional: the transform stage; Slats: its field).
//
// Plain C++: the events each channel shows and the analysis of the edges the
// oscilloscope (Oscilloscope.hpp, SystemC) records.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "lab/DisplayArchitecture.hpp"
#include "lab/TrackerFeed.hpp"
#include "tracker/PoseSample.hpp"

namespace arp::apparatus {

struct PendulumSpec {
  double amplitude_deg = 20.0;
  double period_s = 1.2;
  double beam_half_width_deg = 0.25;  // the LED/photodiode pair sees the bob within this of the low point
  double scope_sample_s = 1e-6;       // the oscilloscope's sample interval
  double start_s = 0.0;               // angle = amplitude at start_s (released from rest)
};

// The pendulum's true motion about the yaw axis, sampled at rate_hz.
std::vector<tracker::PoseSample> pendulum_motion(const PendulumSpec& p, double seconds, double rate_hz);
// Its angle (degrees) and the low-point crossings in [t0, t1] (seconds).
double pendulum_angle_deg(const PendulumSpec& p, double t_s);
std::vector<double> low_point_crossings(const PendulumSpec& p, double t0_s, double t1_s);

// What one architecture puts on the oscilloscope.
struct ChannelEvents {
  std::string name;
  struct Refresh {
    int64_t photon_ps;      // the screen photodiode's pixel (the centre) is drawn
    bool light;             // from a pose past the low point on the light side
    int64_t compute_ps;     // when its computation started (render start)
    int64_t report_ps;      // sample time of the tracker report it used
  };
  std::vector<Refresh> refreshes;  // in photon order
  std::vector<int64_t> render_starts;  // compute times of refreshes that changed the shade
};

ChannelEvents observe(lab::DisplayArchitecture& a, const lab::DisplayRaster& d, const lab::TrackerFeed& feed,
                      lab::Prediction p, int64_t first_frame, int64_t frames);

// Edges the oscilloscope recorded (its sample times, picoseconds).
struct ScopeEdges {
  std::vector<int64_t> pendulum_rise, pendulum_fall;
  std::vector<std::vector<int64_t>> render_rise;  // per channel
  std::vector<std::vector<int64_t>> screen_edge;  // per channel, either direction
};

// One low-point passage measured both ways.
struct Passage {
  double crossing_s = 0;        // the true low point
  double pendulum_mid_s = 0;    // external: the middle of the pendulum photodiode's pulse
  double render_start_s = 0;    // external: the render-start edge
  double screen_s = 0;          // external: the screen photodiode's edge
  double tracking_ms = 0, rendering_ms = 0, external_total_ms = 0;
  double internal_total_ms = 0;     // internal timestamps: photon - true crossing
  double internal_report_ms = 0;    // photon - sample time of the report used
  double internal_render_ms = 0;    // photon - compute start
};

struct ChannelMeasurement {
  std::string name;
  std::vector<Passage> passages;
  double mean_tracking_ms = 0, mean_rendering_ms = 0, mean_external_ms = 0, mean_internal_ms = 0;
  double max_disagreement_ms = 0;   // |external - internal (photon - crossing)| over the passages
};

// Pairs each pendulum pulse with the channel's next render-start and screen
// edges (as the paper reads its oscilloscope), and the internal timestamps of
// the refresh that made the screen edge.
ChannelMeasurement analyse(const PendulumSpec& p, const ScopeEdges& e, size_t channel, const ChannelEvents& ev);

}  // namespace arp::apparatus
