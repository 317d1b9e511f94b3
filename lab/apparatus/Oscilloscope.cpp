#include "Oscilloscope.hpp"

#include <systemc>

#include <algorithm>
#include <cmath>
#include <memory>

#include "rtl_model/systemc/TimedRun.hpp"
#include "rtl_model/systemc/VcdClose.hpp"

namespace arp::apparatus {

namespace {

using namespace sc_core;

std::string signal_name(const std::string& s) {
  std::string o = s;
  for (char& c : o)
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  return o;
}

SC_MODULE(PendulumScope) {
  SC_HAS_PROCESS(PendulumScope);
  sc_signal<bool> pendulum_photodiode{"pendulum_photodiode"};
  sc_signal<int> pendulum_angle_mdeg{"pendulum_angle_mdeg"};
  std::vector<std::unique_ptr<sc_signal<bool>>> render_start, screen_photodiode;

  PendulumScope(sc_module_name n, const PendulumSpec& p, const std::vector<ChannelEvents>& ch, const ScopeRun& run, ScopeEdges& edges)
      : sc_module(n), p_(p), ch_(ch), run_(run), edges_(edges), next_refresh_(ch.size(), 0), next_render_(ch.size(), 0),
        render_until_(ch.size(), -1), level_(ch.size(), false), render_level_(ch.size(), false) {
    for (const auto& c : ch) {
      render_start.push_back(std::make_unique<sc_signal<bool>>((signal_name(c.name) + "_render_start").c_str()));
      screen_photodiode.push_back(std::make_unique<sc_signal<bool>>((signal_name(c.name) + "_screen_photodiode").c_str()));
    }
    edges_.render_rise.assign(ch.size(), {});
    edges_.screen_edge.assign(ch.size(), {});
    period_ps_ = std::max<int64_t>(1, static_cast<int64_t>(std::llround(p.scope_sample_s * 1e12)));
    pulse_ps_ = static_cast<int64_t>(std::llround(run.render_pulse_s * 1e12));
    SC_METHOD(sample);
  }

  void sample() {
    const int64_t t = run_.start_ps + static_cast<int64_t>(sc_time_stamp().value());  // 1 ps resolution
    const double ts = static_cast<double>(t) * 1e-12;
    const double angle = pendulum_angle_deg(p_, ts);
    const bool beam = std::abs(angle) < p_.beam_half_width_deg;
    if (beam && !beam_) edges_.pendulum_rise.push_back(t);
    if (!beam && beam_ && !edges_.pendulum_rise.empty()) edges_.pendulum_fall.push_back(t);
    beam_ = beam;
    pendulum_photodiode.write(beam);
    if (++angle_div_ >= 100) {  // the angle trace every 100 samples keeps the VCD small
      angle_div_ = 0;
      pendulum_angle_mdeg.write(static_cast<int>(std::lround(angle * 1e3)));
    }
    for (size_t c = 0; c < ch_.size(); ++c) {
      const auto& ev = ch_[c];
      // The screen photodiode holds the centre pixel's last drawn shade.
      size_t& i = next_refresh_[c];
      while (i < ev.refreshes.size() && ev.refreshes[i].photon_ps <= t) level_[c] = ev.refreshes[i++].light;
      if (i > 0 && level_[c] != static_cast<bool>(screen_photodiode[c]->read()) && seen_[c])
        edges_.screen_edge[c].push_back(t);
      seen_[c] = seen_[c] || i > 0;
      screen_photodiode[c]->write(level_[c]);
      // The render-start pulse.
      size_t& r = next_render_[c];
      while (r < ev.render_starts.size() && ev.render_starts[r] <= t) render_until_[c] = ev.render_starts[r++] + pulse_ps_;
      const bool pulse = t < render_until_[c];
      if (pulse && !render_level_[c]) edges_.render_rise[c].push_back(t);
      render_level_[c] = pulse;
      render_start[c]->write(pulse);
    }
    next_trigger(sc_time(static_cast<double>(period_ps_), SC_PS));
  }

 private:
  const PendulumSpec& p_;
  const std::vector<ChannelEvents>& ch_;
  const ScopeRun& run_;
  ScopeEdges& edges_;
  std::vector<size_t> next_refresh_, next_render_;
  std::vector<int64_t> render_until_;
  std::vector<char> level_, render_level_, seen_ = std::vector<char>(ch_.size(), 0);
  int64_t period_ps_ = 1, pulse_ps_ = 0;
  bool beam_ = false;
  int angle_div_ = 0;
};

}  // namespace

ScopeEdges run_oscilloscope(const PendulumSpec& p, const std::vector<ChannelEvents>& channels, const ScopeRun& run) {
  scm::claim_simulation();
  ScopeEdges edges;
  PendulumScope scope("scope", p, channels, run, edges);
  sc_trace_file* tf = nullptr;
  const sc_time vcd_unit(1, SC_NS);
  if (!run.vcd_path.empty()) {
    tf = sc_create_vcd_trace_file(run.vcd_path.c_str());
    tf->set_time_unit(1, SC_NS);  // vcd_unit
    sc_trace(tf, scope.pendulum_angle_mdeg, "pendulum_angle_mdeg");
    sc_trace(tf, scope.pendulum_photodiode, "pendulum_photodiode");
    for (size_t c = 0; c < channels.size(); ++c) {
      sc_trace(tf, *scope.render_start[c], scope.render_start[c]->basename());
      sc_trace(tf, *scope.screen_photodiode[c], scope.screen_photodiode[c]->basename());
    }
  }
  sc_start(sc_time(static_cast<double>(run.end_ps - run.start_ps), SC_PS));
  if (tf) scm::close_vcd_checked(tf, run.vcd_path + ".vcd", vcd_unit, run.vcd_shown.empty() ? run.vcd_path + ".vcd" : run.vcd_shown);
  return edges;
}

}  // namespace arp::apparatus
