#include "CommonOptions.hpp"

#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "apps/config/ConfigFile.hpp"
#include "host/cubemap/CalibrationPattern.hpp"
#include "host/cubemap/CubeMapLoader.hpp"
#include "rtl_model/datapath/InputError.hpp"

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

void write_text_atomic(const std::string& path, const std::string& text) {
  namespace fs = std::filesystem;
  const fs::path target(path);
  const fs::path dir = target.has_parent_path() ? target.parent_path() : fs::path(".");
  std::error_code ec;
  if (!fs::is_directory(dir, ec)) throw InputError(path, "", "folder " + dir.string() + " does not exist");
  const fs::path tmp = dir / ("." + target.filename().string() + ".tmp-" + std::to_string(::getpid()));
  {
    std::ofstream out(tmp, std::ios::binary);
    out << text;
    out.flush();
    if (!out) {
      fs::remove(tmp, ec);
      throw InputError(path, "", "cannot write the file");
    }
  }
  fs::rename(tmp, target, ec);
  if (ec) {
    fs::remove(tmp, ec);
    throw InputError(path, "", "cannot move the finished file into place: " + ec.message());
  }
}

}  // namespace arp::app
