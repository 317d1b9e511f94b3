#include "CommonOptions.hpp"


namespace arp::app {

void ConfigOptions::add_to(CLI::App& cmd) {
  cmd.add_option("--config", file, "JSON configuration file (every key: docs/configuration.md)");
  cmd.add_option("--set", sets, "Override one key, e.g. --set datapath.vec_frac=12 (repeatable)")
      ->type_name("SECTION.KEY=VALUE");
}

void add_memory_options(CLI::App& cmd, sim::MemoryContents& m) {
  auto* g = cmd.add_option_group("cube map", "Display memory contents (default: the calibration pattern)");
  g->add_option("--faces", m.faces, "Folder with px nx py ny pz nz.<ext>, each face_size square");
  g->add_option("--cross", m.cross, "One image, a 4:3 horizontal or 3:4 vertical cross");
  g->add_option("--equirect", m.equirect, "One 2:1 equirectangular panorama");
  g->add_option("--scene", m.scene, "Render a scene into the memories: a scene file (docs/host.md) or 'gallery'");
  g->require_option(0, 1);
  cmd.add_option("--position", m.position, "--scene: head position x,y,z in metres (default: the gallery walk's start)");
  cmd.add_option("--time", m.time_s, "--scene: scene time in seconds (animations)")->capture_default_str();
  cmd.add_option("--ipd", m.ipd_m, "--scene: distance between the eyes, metres")->capture_default_str();
}

}  // namespace arp::app
