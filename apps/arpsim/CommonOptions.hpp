// Options every arpsim command shares: the configuration file and overrides.
#pragma once
#include <CLI/CLI.hpp>
#include <string>
#include <vector>

#include "common/ProgressLine.hpp"
#include "host/cubemap/CubeMapImages.hpp"
#include "rtl_model/datapath/ArpConfig.hpp"
#include "rtl_model/datapath/DisplayMemoryBank.hpp"
#include "rtl_model/datapath/OrientationMatrixUnit.hpp"

namespace arp::app {

struct ConfigOptions {
  std::string file;
  std::vector<std::string> sets;
  void add_to(CLI::App& cmd);
  // Embedded defaults, then the file, then --set overrides (later wins).
  dp::ArpConfig resolve() const;
};

// What fills the display memories: a cube map from files, or the calibration pattern.
struct CubeMapOptions {
  std::string faces, cross, equirect, scene, position;
  double time_s = 0.0, ipd_m = 0.064;
  void add_to(CLI::App& cmd);
  // Loads the chosen cube map at face size S; `source` names it for messages.
  host::CubeMapImages load(int face_size, std::string& source) const;
  // Fills memory 0 of every eye and swaps it in: the cube map, or the scene
  // rendered from each eye's position (head at `head`, eyes IPD apart along its x axis).
  void fill(dp::DisplayMemorySet& mem, const dp::Quat& head, std::string& source) const;
};

// Writes text to path through a temporary file and a rename.
void write_text_atomic(const std::string& path, const std::string& text);

}  // namespace arp::app
