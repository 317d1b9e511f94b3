#include "ArpConfig.hpp"

#include <cmath>
#include <cstdio>

#include "PipelineSchedule.hpp"

namespace arp::dp {

std::string to_string(EyeScan v) { return v == EyeScan::Lockstep ? "lockstep" : "side_by_side"; }
std::string to_string(LatchPolicy v) {
  switch (v) {
    case LatchPolicy::PerFrame: return "frame";
    case LatchPolicy::PerField: return "field";
    case LatchPolicy::PerScanline: return "scanline";
    case LatchPolicy::PerPixel: return "pixel";
  }
  return "?";
}
std::string to_string(DividerKind v) { return v == DividerKind::Exact ? "exact" : "lut"; }
const char* stage_key(Stage s) {
  static const char* const keys[kStageCount] = {"lens", "rotate", "address", "fetch", "compose", "filter", "scanout"};
  return keys[static_cast<size_t>(s)];
}
std::string to_string(AaMode v) { return v == AaMode::Off ? "off" : "bilinear"; }

bool parse(const std::string& s, EyeScan& out) {
  if (s == "lockstep") { out = EyeScan::Lockstep; return true; }
  if (s == "side_by_side") { out = EyeScan::SideBySide; return true; }
  return false;
}
bool parse(const std::string& s, LatchPolicy& out) {
  if (s == "frame") { out = LatchPolicy::PerFrame; return true; }
  if (s == "field") { out = LatchPolicy::PerField; return true; }
  if (s == "scanline") { out = LatchPolicy::PerScanline; return true; }
  if (s == "pixel") { out = LatchPolicy::PerPixel; return true; }
  return false;
}
bool parse(const std::string& s, DividerKind& out) {
  if (s == "lut") { out = DividerKind::ReciprocalLut; return true; }
  if (s == "exact") { out = DividerKind::Exact; return true; }
  return false;
}
bool parse(const std::string& s, AaMode& out) {
  if (s == "off") { out = AaMode::Off; return true; }
  if (s == "bilinear") { out = AaMode::Bilinear; return true; }
  return false;
}

namespace {
struct Checker {
  std::vector<ConfigIssue>& out;
  void range(const std::string& key, int64_t v, int64_t lo, int64_t hi) {
    if (v < lo || v > hi)
      out.push_back({key, "is " + std::to_string(v) + ", must be in [" + std::to_string(lo) + ", " +
                              std::to_string(hi) + "]"});
  }
  void fail(const std::string& key, std::string reason) { out.push_back({key, std::move(reason)}); }
};
}  // namespace

std::vector<ConfigIssue> validate(const ArpConfig& c) {
  std::vector<ConfigIssue> issues;
  Checker ck{issues};
  const auto& t = c.timing;
  ck.range("display.eyes", t.eyes, 1, 2);
  ck.range("display.h_active", t.h_active, 1, 8192);
  ck.range("display.v_active", t.v_active, 1, 8192);
  ck.range("display.h_front_porch", t.h_front_porch, 0, 8192);
  ck.range("display.h_sync", t.h_sync, 0, 8192);
  ck.range("display.h_back_porch", t.h_back_porch, 0, 8192);
  ck.range("display.v_front_porch", t.v_front_porch, 0, 8192);
  ck.range("display.v_sync", t.v_sync, 0, 8192);
  ck.range("display.v_back_porch", t.v_back_porch, 0, 8192);
  ck.range("display.pixel_clock_hz", t.pixel_clock_hz, 1000, 100'000'000'000);
  ck.range("display.fields_per_frame", t.fields_per_frame, 1, 2);
  if (t.fields_per_frame == 2 && issues.empty()) {
    const int64_t frame = int64_t{t.h_total()} * t.v_total();
    const int64_t lines = (t.v_active + 1) / 2;
    if (frame % 2 != 0)
      ck.fail("display.v_front_porch", "interlaced timing needs an even number of pixel clocks per frame");
    else if (lines * t.h_total() > frame / 2)
      ck.fail("display.v_active", "the active lines of one field do not fit in half a frame");
  }

  const auto& l = c.lens;
  if (!std::isfinite(l.fov_deg) || l.fov_deg <= 0.0 || l.fov_deg >= 180.0)
    ck.fail("lens.fov_deg", "is " + std::to_string(l.fov_deg) + ", must be > 0 and < 180 degrees");
  for (int i = 0; i < 4; ++i)
    if (!std::isfinite(l.k[i])) ck.fail("lens.k", "coefficient k" + std::to_string(i) + " is not finite");
  if (!std::isfinite(l.center_offset_px) || std::abs(l.center_offset_px) >= t.h_active / 2.0)
    ck.fail("lens.center_offset_px", "must be finite and less than half of display.h_active in magnitude");
  if (issues.empty()) {
    // The distortion scale must stay positive over the whole panel, or the
    // table would fold the image over itself.
    const double hw = t.h_active / 2.0 + std::abs(l.center_offset_px);
    const double rmax = std::hypot(hw, t.v_active / 2.0) / (t.h_active / 2.0);
    for (int i = 0; i <= 1000; ++i) {
      const double r = rmax * i / 1000.0, r2 = r * r;
      const double s = l.k[0] + r2 * (l.k[1] + r2 * (l.k[2] + r2 * l.k[3]));
      if (!(s > 0.0)) {
        ck.fail("lens.k", "distortion scale k0+k1 r^2+k2 r^4+k3 r^6 is not positive at r=" + std::to_string(r));
        break;
      }
    }
  }

  const auto& w = c.widths;
  ck.range("datapath.vec_frac", w.vec_frac, 1, 28);
  ck.range("datapath.mat_frac", w.mat_frac, 1, 28);
  ck.range("datapath.rot_frac", w.rot_frac, 1, 28);
  ck.range("datapath.recip_index_bits", w.recip_index_bits, 1, 16);
  ck.range("datapath.recip_frac_bits", w.recip_frac_bits, 4, 30);
  ck.range("datapath.newton_steps", w.newton_steps, 0, 4);
  ck.range("datapath.quot_frac", w.quot_frac, 2, 30);
  ck.range("datapath.texel_frac", w.texel_frac, 0, 16);

  const auto& m = c.memory;
  ck.range("memory.count", m.count, 1, 16);
  ck.range("memory.face_size", m.face_size, 1, 16384);
  ck.range("memory.red_bits", m.red_bits, 1, 16);
  ck.range("memory.green_bits", m.green_bits, 1, 16);
  ck.range("memory.blue_bits", m.blue_bits, 1, 16);
  if (m.color_bits() > 32) ck.fail("memory.red_bits", "red+green+blue bits must not exceed 32");
  ck.range("memory.depth_bits", m.depth_bits, 2, 32);
  for (int i = 0; i < 3; ++i) ck.range("memory.background", m.background[i], 0, 255);

  const auto& p = c.pipeline;
  ck.range("pipeline.display_bits", p.display_bits, 1, 10);
  if (p.aa == AaMode::Bilinear && w.texel_frac < 1)
    ck.fail("datapath.texel_frac", "bilinear anti-aliasing needs at least 1 sub-texel bit");
  ck.range("pipeline.latch_lead_cycles", p.latch_lead_cycles, 0, 1'000'000'000);
  ck.range("pipeline.photon_delay_ps", p.photon_delay_ps, 0, 1'000'000'000'000);

  const auto& tm = c.timed;
  for (int s = 0; s < kStageCount; ++s) {
    const std::string k = std::string("timed.") + stage_key(static_cast<Stage>(s));
    ck.range(k + "_latency", tm.stage[static_cast<size_t>(s)].latency_cycles, 1, 64);
    ck.range(k + "_logic_ps", tm.stage[static_cast<size_t>(s)].logic_delay_ps, 0, 1'000'000'000);
  }
  ck.range("timed.fifo_depth", tm.fifo_depth, 1, 4096);
  ck.range("timed.issue_slack_cycles", tm.issue_slack_cycles, 0, 4096);
  ck.range("timed.host_clock_hz", tm.host_clock_hz, 1000, 100'000'000'000);
  ck.range("timed.host_texels_per_cycle", tm.host_texels_per_cycle, 1, 1 << 20);
  return issues;
}

std::vector<ConfigIssue> validate_timed(const ArpConfig& c) {
  std::vector<ConfigIssue> issues = validate(c);
  if (!issues.empty()) return issues;
  Checker ck{issues};
  const auto& tm = c.timed;
  const double period_ps = 1e12 / static_cast<double>(c.timing.pixel_clock_hz);
  for (int s = 0; s < kStageCount; ++s) {
    const auto& st = tm.stage[static_cast<size_t>(s)];
    const double per_register = static_cast<double>(st.logic_delay_ps) / st.latency_cycles;
    if (per_register > period_ps) {
      char buf[256];
      std::snprintf(buf, sizeof buf,
                    "%.0f ps of logic over %d register stage(s) needs %.0f ps per stage, more than the %.0f ps "
                    "pixel clock period (display.pixel_clock_hz %lld): add register stages or slow the clock",
                    static_cast<double>(st.logic_delay_ps), st.latency_cycles, per_register, period_ps,
                    static_cast<long long>(c.timing.pixel_clock_hz));
      ck.fail(std::string("timed.") + stage_key(static_cast<Stage>(s)) + "_latency", buf);
    }
  }
  if (c.memory.count > kCompositionInputs)
    ck.fail("memory.count", "is " + std::to_string(c.memory.count) + ", the timed models' composition unit compares at most " +
                                std::to_string(kCompositionInputs) + " memories");
  // The scan-out FIFO holds slack + 1 pixels at the start of each clock and,
  // having no bypass, must have room for one more while it is read.
  if (tm.fifo_depth < tm.issue_slack_cycles + 2)
    ck.fail("timed.fifo_depth", "is " + std::to_string(tm.fifo_depth) + ", must be at least the issue slack plus two (" +
                                    std::to_string(tm.issue_slack_cycles + 2) + ") or the scan-out FIFO backs up");
  const PipelineSchedule sched(c);
  if (sched.issue_lead() >= sched.vblank_cycles())
    ck.fail("timed.issue_slack_cycles",
            "the pipeline issues pixels " + std::to_string(sched.issue_lead()) +
                " cycles ahead, not less than the vertical blanking (" + std::to_string(sched.vblank_cycles()) +
                " cycles): the next frame would be fetched before the buffers swap");
  if (sched.issue_lead() > c.timing.h_total() * int64_t{c.timing.v_active})
    ck.fail("timed.issue_slack_cycles", "the pipeline is deeper than the active picture");
  return issues;
}

}  // namespace arp::dp
