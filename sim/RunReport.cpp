#include "RunReport.hpp"

#include <cstring>

#include <cinttypes>
#include <cstdarg>
#include <cstdio>

#include "ConfigFile.hpp"
#include "common/Fingerprint.hpp"
#include "common/ResourceUsage.hpp"

namespace arp::sim {

namespace {

// A frame's fingerprint: four Fingerprint lanes over its words in turn (word i to lane i mod 4), then the
// count and the lanes folded into one. One lane is one chain of dependent multiplies, shifts and xors, and four
// run side by side in the core at the cost of one.
template <class V>
std::string hash_of(const V& values) {
  Fingerprint lane[4];
  const size_t n = values.size();
  size_t i = 0;
  for (; i + 4 <= n; i += 4)
    for (size_t j = 0; j < 4; ++j) lane[j].add(static_cast<uint64_t>(values[i + j]));
  for (; i < n; ++i) lane[i % 4].add(static_cast<uint64_t>(values[i]));
  Fingerprint h;
  h.add(static_cast<uint64_t>(n));
  for (const Fingerprint& l : lane) h.add(l.value());
  char hex[24];
  std::snprintf(hex, sizeof hex, "%016" PRIx64, h.value());
  return hex;
}

std::string line(const char* fmt, ...) __attribute__((format(printf, 1, 2)));
std::string line(const char* fmt, ...) {
  char b[512];
  va_list ap;
  va_start(ap, fmt);
  std::vsnprintf(b, sizeof b, fmt, ap);
  va_end(ap);
  return b;
}

}  // namespace

std::string pixel_hash(const HmdFrame& f) { return hash_of(f.pixels); }
std::string photon_hash(const HmdFrame& f) { return hash_of(f.photon_ps); }

FrameHashes frame_hashes(const HmdFrame& f, int threads) {
  FrameHashes h;
#pragma omp parallel sections num_threads(threads == 1 ? 1 : 2)
  {
#pragma omp section
    h.pixels = pixel_hash(f);
#pragma omp section
    h.photons = photon_hash(f);
  }
  return h;
}

std::string frame_csv_header() {
  return "frame,pixels,underflows,late_discarded,reset_pixels,latency_min_ns,latency_median_ns,latency_max_ns,"
         "first_photon_ps,last_photon_ps,pixel_hash,photon_hash\n";
}

nlohmann::json frame_row(const stage::FrameReport& r, size_t first_sample, size_t last_sample, const std::string& pixels,
                         const std::string& photons) {
  return {{"frame", r.frame},
          {"first_sample", first_sample},
          {"last_sample", last_sample},
          {"pixels", r.pixels},
          {"underflows", r.underflows},
          {"late_discarded", r.late_discarded},
          {"reset_pixels", r.reset_pixels},
          {"latency_ps", {{"min", r.latency_min_ps}, {"median", r.latency_median_ps}, {"max", r.latency_max_ps}}},
          {"first_photon_ps", r.first_photon_ps},
          {"last_photon_ps", r.last_photon_ps},
          {"pixel_hash", pixels},
          {"photon_hash", photons}};
}

std::string frame_csv_row(const stage::FrameReport& r, const std::string& pixels, const std::string& photons) {
  return line("%" PRId64 ",%" PRId64 ",%" PRId64 ",%" PRId64 ",%" PRId64 ",%.3f,%.3f,%.3f,%" PRId64 ",%" PRId64 ",%s,%s\n", r.frame,
              r.pixels, r.underflows, r.late_discarded, r.reset_pixels, r.latency_min_ps * 1e-3, r.latency_median_ps * 1e-3,
              r.latency_max_ps * 1e-3, r.first_photon_ps, r.last_photon_ps, pixels.c_str(), photons.c_str());
}

nlohmann::json pipeline_report(const scm::TimedResult& res, const dp::ArpConfig& c, const std::string& vcd) {
  const auto& tm = c.timed;
  const double period_ns = 1e9 / static_cast<double>(c.timing.pixel_clock_hz);
  nlohmann::json stages = nlohmann::json::array();
  for (int s = 0; s < dp::kStageCount; ++s) {
    const auto& st = res.stages[static_cast<size_t>(s)];
    const int lat = tm.stage[static_cast<size_t>(s)].latency_cycles;
    nlohmann::json j{{"stage", dp::stage_key(static_cast<dp::Stage>(s))}, {"latency_cycles", lat}, {"latency_ns", lat * period_ns}};
    if (res.stages_measured && s < dp::kStageCount - 1)
      j["measured"] = {{"pixels", st.pixels},
                       {"min_cycles", st.min_cycles},
                       {"mean_cycles", st.mean_cycles},
                       {"max_cycles", st.max_cycles},
                       {"stalled_cycles", st.stalled_cycles}};
    stages.push_back(j);
  }
  nlohmann::json fifos = nlohmann::json::array();
  for (const auto& [name, f] : res.fifos)
    fifos.push_back({{"fifo", name},
                     {"depth", f.depth},
                     {"writes", f.writes},
                     {"max_occupancy", f.max_occupancy},
                     {"mean_occupancy", f.mean_occupancy},
                     {"full_cycles", f.full_cycles},
                     {"empty_cycles", f.empty_cycles},
                     {"blocked_writes", f.blocked_writes}});
  nlohmann::json jobs = nlohmann::json::array();
  for (const auto& j : res.host_jobs)
    jobs.push_back({{"start_ps", j.start_ps}, {"commit_ps", j.commit_ps}, {"swap_ps", j.swap_ps}, {"swap_frame", j.swap_frame}});
  const dp::VideoTiming t(c.timing);
  nlohmann::json report = {{"fidelity", scm::to_string(res.fidelity)},
          {"fidelity_description", scm::describe(res.fidelity)},
          {"pipeline",
           {{"issue_lead_cycles", res.issue_lead},
            {"issue_lead_ns", res.issue_lead * period_ns},
            {"orientation_lead_cycles", res.orientation_lead},
            {"orientation_lead_ns", res.orientation_lead * period_ns},
            {"stages", stages}}},
          {"fifos_modelled", res.fifos_modelled},
          {"fifos", fifos},
          {"underflows", res.underflows},
          {"late_discarded", res.late_discarded},
          {"issue_stalls", res.issue_stalls},
          {"buffer_swaps", res.swaps},
          {"host_jobs", jobs},
          {"orientation_writes", res.orientation_writes},
          {"simulation",
           {{"pixel_clocks", res.end_cycle - res.first_cycle},
            {"wall_seconds", res.wall_seconds},
            {"pixel_clocks_per_second", res.cycles_per_second()},
            {"peak_resident_mb", static_cast<double>(peak_resident_bytes()) / (1 << 20)},
            {"speculated_pixels", res.speculated_pixels},
            {"fallback_pixels", res.fallback_pixels},
            {"vcd_time_zero_ps", t.cycles_to_ps(res.first_cycle)},
            {"vcd", vcd}}},
          {"config", config::to_json(c)}};
  // Only the cycle-accurate levels have clocks to evaluate or gate (--no-clock-gating).
  if (res.fidelity == scm::Fidelity::Cycle || res.fidelity == scm::Fidelity::Detailed) {
    report["simulation"]["pixel_clocks_evaluated"] = res.evaluated_cycles;
    report["simulation"]["host_clocks_evaluated"] = res.evaluated_host_cycles;
  }
  return report;
}

std::vector<std::string> RunSummary::lines() const {
  std::vector<std::string> out;
  out.push_back(line("arpsim run: %s level, %" PRId64 " frames (%" PRId64 "..%" PRId64 ") of %s with %s", fidelity.c_str(), frames,
                     first_frame, first_frame + frames - 1, motion_source.c_str(), memory_source.c_str()));
  if (!detail.empty()) out.push_back(detail);
  if (!complete())
    out.push_back(line("  STOPPED%s after %" PRId64 " of %" PRId64 " frames: the outputs cover those frames (the report says \"complete\": false)",
                       stop_signal ? (std::string(" by SIG") + sigabbrev_np(stop_signal)).c_str() : "", frames_done, frames));
  out.push_back(line("  orientation sample -> photon: min %.1f us, median %.1f us, max %.1f us", latency_min_ps * 1e-6,
                     latency_median_ps * 1e-6, latency_max_ps * 1e-6));
  if (cycle_accurate)
    out.push_back(line("  underflows %" PRId64 ", late pixels dropped %" PRId64 ", buffer swaps %" PRId64, underflows, late_discarded,
                       swaps));
  out.push_back(line("  %" PRId64 " pixel clocks in %.2f s: %.2f M pixel clocks/s, peak memory %.0f MB", pixel_clocks,
                     wall_seconds, wall_seconds > 0 ? static_cast<double>(pixel_clocks) / wall_seconds * 1e-6 : 0.0,
                     static_cast<double>(peak_resident_bytes()) / (1 << 20)));
  out.push_back(line("  modelled: display memory %.1f MiB allocated at the peak (the hardware holds %.1f MiB; %.1f MiB in the "
                     "tiles drawn on, %.1f MiB with a tile pool of those in use at once), %" PRId64 " banks, %" PRId64 " texels written, %" PRId64 " SystemC modules",
                     static_cast<double>(memory_bytes_peak) / (1 << 20), static_cast<double>(memory_bytes_hardware) / (1 << 20),
                     static_cast<double>(memory_bytes_hardware_tiled) / (1 << 20),
                     static_cast<double>(memory_bytes_hardware_pooled) / (1 << 20), memory_banks, texels_written,
                     systemc_modules));
  if (images) out.push_back(line("  %" PRId64 " images in %s", images, out_dir.c_str()));
  if (!vcd.empty()) out.push_back(line("  waveform %s (open: gtkwave %s %s)", vcd.c_str(), vcd.c_str(), gtkw.c_str()));
  out.insert(out.end(), notes.begin(), notes.end());
  return out;
}

}  // namespace arp::sim
