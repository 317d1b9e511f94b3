#include "FuzzTargets.hpp"

#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <fstream>
#include <new>
#include <sstream>

#include "ReportDecoderFuzz.hpp"
#include "common/GtkwSaveFile.hpp"
#include "common/InputError.hpp"
#include "host/cubemap/CubeMapLoader.hpp"
#include "host/motion/WalkPath.hpp"
#include "host/scene/AssimpImport.hpp"
#include "host/scene/Mesh.hpp"
#include "host/scene/ModelImport.hpp"
#include "host/scene/ModelPrecheck.hpp"
#include "host/scene/SceneFile.hpp"
#include "sim/ConfigFile.hpp"
#include "tracker/DatasetImport.hpp"
#include "tracker/MotionSummary.hpp"
#include "tracker/TraceEdit.hpp"
#include "tracker/TraceFile.hpp"

namespace arp::fuzz {

namespace {

namespace fs = std::filesystem;

bool model_in_process = false;
thread_local bool refused = false;

// The longest message a refusal may carry: the file, the place, the reason
// and at most ~80 characters of the bad value -- a flood is a finding.
constexpr size_t kMaxMessage = 1000;

[[noreturn]] void fail(const char* target, const std::string& what) {
  std::fprintf(stderr, "fuzz target %s: %s\n", target, what.c_str());
  std::abort();
}

// Runs one parse: returning or an InputError with a short message is fine;
// anything else is a finding (aborts, so libFuzzer and the tests both see it).
template <class F>
int guarded(const char* target, F&& parse) {
  refused = false;
  try {
    parse();
  } catch (const InputError& e) {
    refused = true;
    const std::string m = e.what();
    if (m.empty()) fail(target, "an InputError without a message");
    if (m.size() > kMaxMessage) fail(target, "a message of " + std::to_string(m.size()) + " characters: " + m.substr(0, 200));
  } catch (const std::bad_alloc&) {
    fail(target, "out of memory (an allocation nothing bounded)");
  } catch (const std::exception& e) {
    fail(target, std::string("not an InputError: ") + e.what());
  } catch (...) {
    fail(target, "an exception of unknown type");
  }
  return 0;
}

// The input as a file (most readers take a path: the regular-file and size
// checks are part of what is fuzzed), in a folder of this process's own,
// empty but for it, so relative paths inside the input resolve to nothing.
class ScratchFile {
 public:
  ScratchFile() {
    const char* t = std::getenv("TMPDIR");
    std::string tmpl = std::string(t && *t ? t : "/tmp") + "/arpsim-fuzz-XXXXXX";
    if (!mkdtemp(tmpl.data())) fail("scratch", "cannot create a scratch folder in $TMPDIR");
    dir_ = tmpl;
  }
  ~ScratchFile() {
    std::error_code ec;
    fs::remove_all(dir_, ec);
  }
  std::string write(const uint8_t* data, size_t size, const std::string& extension) {
    std::error_code ec;
    fs::remove(path_, ec);
    path_ = dir_ + "/input" + extension;
    std::ofstream f(path_, std::ios::binary);
    f.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
    if (!f) fail("scratch", "cannot write " + path_);
    return path_;
  }

 private:
  std::string dir_, path_;
};

ScratchFile& scratch() {
  static ScratchFile s;
  return s;
}

std::string as_text(const uint8_t* data, size_t size) { return std::string(reinterpret_cast<const char*>(data), size); }

int config_one(const uint8_t* data, size_t size) {
  const std::string p = scratch().write(data, size, ".json");
  return guarded("config", [&] { config::check(config::load_file(p), p); });
}

// One --set per line, as the command line passes them.
int set_one(const uint8_t* data, size_t size) {
  std::vector<std::string> sets;
  std::istringstream in(as_text(data, size));
  for (std::string line; std::getline(in, line) && sets.size() < 16;) sets.push_back(line);
  return guarded("set", [&] { config::check(config::apply_overrides({}, sets), "--set"); });
}

int scene_one(const uint8_t* data, size_t size) {
  const std::string p = scratch().write(data, size, ".json");
  return guarded("scene", [&] { host::load_scene_file(p); });
}

int walk_one(const uint8_t* data, size_t size) {
  const std::string p = scratch().write(data, size, ".json");
  return guarded("walk", [&] { host::load_walk_file(p); });
}

int trace_one(const uint8_t* data, size_t size) {
  std::istringstream in(as_text(data, size));
  return guarded("trace", [&] { tracker::read_trace_csv(in, "fuzz trace"); });
}

// The first byte picks the layout (time unit, axes, quaternion order).
int dataset_one(const uint8_t* data, size_t size) {
  if (size == 0) return 0;
  // The first byte picks the time unit, the axes, quaternion (w first or last) or Euler angles, and named columns.
  tracker::DatasetLayout layout;
  layout.time_unit = static_cast<tracker::DatasetLayout::TimeUnit>(data[0] & 3);
  static const char* const kAxes[] = {"gl", "unity", "corbillon", "-y,+z,-x"};
  std::string why;
  tracker::parse_axes(kAxes[(data[0] >> 2) & 3], layout.axes, why);
  static const char* const kColumns[] = {"t=1,frame=2,qw=3,qx=4,qy=5,qz=6", "t=1,frame=2,qx=3,qy=4,qz=5,qw=6",
                                         "t=1,ry=2,rx=3,rz=4", "t=time,qw=w,qx=x,qy=y,qz=z"};
  tracker::parse_columns(kColumns[(data[0] >> 4) & 3], layout.columns, why);
  layout.angle_unit = (data[0] & 64) ? tracker::DatasetLayout::AngleUnit::Radians : tracker::DatasetLayout::AngleUnit::Degrees;
  const std::string p = scratch().write(data + 1, size - 1, ".txt");
  return guarded("dataset", [&] {
    auto samples = tracker::read_head_motion_dataset(p, layout);
    const auto s = tracker::summarize_motion(samples);
    tracker::describe(s);
    tracker::motion_warnings(s);
    tracker::drop_repeats(samples);
    if (samples.size() >= 2 && samples.back().time_ps - samples.front().time_ps < 1'000'000'000'000) tracker::resample(samples, 250.0);
  });
}

int vcd_one(const uint8_t* data, size_t size) {
  std::istringstream in(as_text(data, size));
  return guarded("vcd", [&] { gtkw_for_vcd(in, "fuzz.vcd", "fuzz.vcd", 0); });
}

// The first byte picks the extension OpenImageIO goes by and the layout.
int image_one(const uint8_t* data, size_t size) {
  if (size == 0) return 0;
  static const char* const kExt[] = {".png", ".jpg", ".tif", ".exr", ".hdr", ".ppm", ".bmp", ".tga"};
  const std::string p = scratch().write(data + 1, size - 1, kExt[data[0] & 7]);
  return guarded("image", [&] {
    if (data[0] & 8) host::load_equirect(p, 8);
    else host::load_cross(p, 8);
  });
}

// The first byte picks the format among those arpsim documents.
int model_one(const uint8_t* data, size_t size) {
  if (size == 0) return 0;
  static const char* const kExt[] = {".obj", ".ply", ".off", ".stl", ".gltf", ".glb", ".obj", ".ply"};
  const std::string p = scratch().write(data + 1, size - 1, kExt[data[0] & 7]);
  return guarded("model", [&] {
    if (model_in_process) {
      host::precheck_model(p);
      host::check_mesh(host::assimp_import(p), p);
    } else {
      host::import_model(p, host::ImportLimits{10, uint64_t{1} << 30});
    }
  });
}

}  // namespace

void set_model_import_in_process(bool in_process) { model_in_process = in_process; }
bool last_input_refused() { return refused; }

const std::vector<FuzzTarget>& fuzz_targets() {
  static const std::vector<FuzzTarget> kTargets = {
      {"config", "configuration file (sim/ConfigFile)", 1 << 16, true, false, config_one},
      {"set", "--set KEY=VALUE overrides, one per line (sim/ConfigFile)", 4096, true, false, set_one},
      {"scene", "scene file (host/scene/SceneFile)", 1 << 16, true, false, scene_one},
      {"walk", "walk file (host/motion/WalkPath)", 1 << 14, true, false, walk_one},
      {"trace", "trace CSV (tracker/TraceFile)", 1 << 16, true, false, trace_one},
      {"dataset", "head-motion dataset import (tracker/DatasetImport)", 1 << 16, true, false, dataset_one},
      {"vcd", "VCD behind arpsim gtkw (common/GtkwSaveFile)", 1 << 16, true, false, vcd_one},
      {"image", "cube-map image through OpenImageIO (host/cubemap/CubeMapLoader)", 1 << 16, false, false, image_one},
      {"model", "model file through precheck and import (host/scene/ModelImport)", 1 << 16, false, true, model_one},
      {"report", "Oculus DK1/DK2 USB report (tracker/OculusReport)", 128, true, false, report_decoder_one_input},
  };
  return kTargets;
}

const FuzzTarget* find_fuzz_target(const std::string& name) {
  for (const auto& t : fuzz_targets())
    if (name == t.name) return &t;
  return nullptr;
}

}  // namespace arp::fuzz
