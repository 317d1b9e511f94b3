#include "CommonOptions.hpp"

#include <cstdio>
#include <filesystem>
#include <fstream>

#include "apps/config/ConfigFile.hpp"
#include "common/AtomicFile.hpp"
#include "host/cubemap/CalibrationPattern.hpp"
#include "host/cubemap/CubeMapLoader.hpp"
#include "common/InputError.hpp"

namespace arp::app {

void ConfigOptions::add_to(CLI::App& cmd) {
  cmd.add_option("--config", file, "JSON configuration file (every key: docs/configuration.md)");
  cmd.add_option("--set", sets, "Override one key, e.g. --set datapath.vec_frac=12 (repeatable)")
      ->type_name("SECTION.KEY=VALUE");
}

dp::ArpConfig ConfigOptions::resolve() const {
  dp::ArpConfig c;
  if (!file.empty()) c = config::load_file(file, c);
  if (!sets.empty()) c = config::apply_overrides(c, sets);
  config::check(c, file.empty() ? "configuration" : file);
  return c;
}

void CubeMapOptions::add_to(CLI::App& cmd) {
  auto* g = cmd.add_option_group("cube map", "Display memory contents (default: the calibration pattern)");
  g->add_option("--faces", faces, "Folder with px nx py ny pz nz.<ext>, each face_size square");
  g->add_option("--cross", cross, "One image, a 4:3 horizontal or 3:4 vertical cross");
  g->add_option("--equirect", equirect, "One 2:1 equirectangular panorama");
  g->require_option(0, 1);
}

host::CubeMapImages CubeMapOptions::load(int S, std::string& source) const {
  if (!faces.empty()) { source = faces; return host::load_six_faces(host::six_face_paths_in(faces), S); }
  if (!cross.empty()) { source = cross; return host::load_cross(cross, S); }
  if (!equirect.empty()) { source = equirect; return host::load_equirect(equirect, S); }
  source = "calibration pattern";
  return host::make_calibration_pattern(S);
}

ProgressLine::ProgressLine(std::string prefix, bool enabled)
    : prefix_(std::move(prefix)), enabled_(enabled), start_(std::chrono::steady_clock::now()) {}

void ProgressLine::update(double fraction, const std::string& detail) {
  if (!enabled_) return;
  const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  const bool done = fraction >= 1.0;
  if (!done && s - last_ < 0.25) return;  // a readable rate
  last_ = s;
  const double eta = fraction > 0 ? s * (1.0 - fraction) / fraction : 0.0;
  std::fprintf(stderr, "\r%s: %-12s %5.1f%%  elapsed %6.1f s  ETA %6.1f s ", prefix_.c_str(), detail.c_str(),
               100.0 * fraction, s, eta);
  if (done) std::fprintf(stderr, "\n");
}

void write_text_atomic(const std::string& path, const std::string& text) {
  const auto tmp = temp_path_beside(path);
  std::ofstream out(tmp, std::ios::binary);
  out << text;
  out.close();
  if (!out) {
    discard_temp_file(tmp);
    throw InputError(path, "", "cannot write the file");
  }
  commit_temp_file(tmp, path);
}

}  // namespace arp::app
