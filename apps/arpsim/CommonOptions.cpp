#include "CommonOptions.hpp"

#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <utility>

#include "common/InputError.hpp"
#include "common/PrintfText.hpp"

namespace arp::app {

namespace {

// "" if `s` is a whole number of type T (then without leading zeros, so CLI11 reads it as decimal), else why not.
template <class T>
std::string whole_number(std::string& s) {
  const bool neg = !s.empty() && s[0] == '-';
  const size_t digits = !s.empty() && (s[0] == '-' || s[0] == '+') ? 1 : 0;
  if (s.size() == digits || s.find_first_not_of("0123456789", digits) != std::string::npos)
    return "'" + quoted(s) + "' is not a whole number";
  T v{};
  const auto [end, ec] = std::from_chars(s.data() + digits - (neg ? 1 : 0), s.data() + s.size(), v);
  if (ec != std::errc() || end != s.data() + s.size())
    return quoted(s) + " is outside the range " + std::to_string(std::numeric_limits<T>::min()) + " .. " +
           std::to_string(std::numeric_limits<T>::max());
  s = std::to_string(v);
  return "";
}

std::string real_number(const std::string& s) {
  errno = 0;
  char* end = nullptr;
  const double v = std::strtod(s.c_str(), &end);
  if (s.empty() || end != s.c_str() + s.size()) return "'" + quoted(s) + "' is not a number";
  if (!std::isfinite(v)) return quoted(s) + " is not a finite number";
  if (errno == ERANGE && std::fabs(v) > 1.0) return quoted(s) + " is too large for a double (beyond 1.8e308)";
  return "";  // an underflow (1e-320) is a number: its nearest double
}

void strict_options(CLI::App& app, const CLI::Validator& whole, const CLI::Validator& uwhole, const CLI::Validator& real) {
  for (CLI::Option* o : app.get_options()) {
    const std::string type = o->get_type_name();
    if (type.rfind("UINT", 0) == 0) o->transform(uwhole);  // a transform: it may drop leading zeros
    else if (type.rfind("INT", 0) == 0) o->transform(whole);
    else if (type.rfind("FLOAT", 0) == 0) o->check(real);
  }
  for (CLI::App* sub : app.get_subcommands({})) strict_options(*sub, whole, uwhole, real);
}

}  // namespace

void strict_numbers(CLI::App& app) {
  const CLI::Validator whole([](std::string& s) { return whole_number<int64_t>(s); }, "", "whole number");
  const CLI::Validator uwhole([](std::string& s) { return whole_number<uint64_t>(s); }, "", "whole number >= 0");
  const CLI::Validator real([](std::string& s) { return real_number(s); }, "", "number");
  strict_options(app, whole, uwhole, real);
}

CLI::App* ConfigOptions::add_command(CLI::App& app, std::string name, std::string description) {
  CLI::App* cmd = app.add_subcommand(std::move(name), std::move(description));
  cmd->add_option("--config", file, "JSON configuration file (every key: docs/configuration.md)");
  cmd->add_option("--set", sets, "Override one key, e.g. --set datapath.vec_frac=12 (repeatable)")->type_name("SECTION.KEY=VALUE");
  return cmd;
}

void add_walk_options(CLI::App& cmd, std::string& walk, std::optional<double>& speed, std::optional<double>& threshold_deg) {
  cmd.add_option("--walk", walk, "With --scene: walk through it, 'gallery' (the built-in walk) or a walk file (docs/host.md); "
                 "the host renders by priority between frames");
  cmd.add_option("--speed", speed, "Walking speed, m/s, 0 .. 1000 (default 1, or the walk file's; 0: standing at the walk's first point)");
  cmd.add_option("--threshold-deg", threshold_deg,
                 "Priority rendering's threshold angle theta_t, 0 .. 90 (0: one display-memory texel; default: the "
                 "configuration's memory.threshold_deg, which a plan sets)");
}

void add_threads_option(CLI::App& cmd, int& threads) {
  cmd.add_option("--threads", threads, "Worker threads of the functional model and the scene renderer (0: all cores)")
      ->check(CLI::Range(0, 256));
}

void add_quiet_flag(CLI::App& cmd, bool& quiet) { cmd.add_flag("--quiet,-q", quiet, "No progress line"); }

void add_memory_options(CLI::App& cmd, sim::MemoryContents& m) {
  auto* g = cmd.add_option_group("cube map", "Display memory contents (default: the calibration pattern)");
  g->add_option("--faces", m.faces, "Folder with px nx py ny pz nz.<ext>, each face_size square");
  g->add_option("--cross", m.cross, "One image, a 4:3 horizontal or 3:4 vertical cross");
  g->add_option("--equirect", m.equirect, "One 2:1 equirectangular panorama");
  g->add_option("--scene", m.scene, "Render a scene into the memories: a scene file (docs/host.md) or 'gallery'");
  g->require_option(0, 1);
  cmd.add_option("--position", m.position, "--scene: head position x,y,z in metres (default: the gallery walk's start)");
  cmd.add_option("--time", m.time_s, "--scene: scene time in seconds (animations); default 0");
  cmd.add_option("--renderer", m.renderer,
                 "--scene: draw with 'software' (the deterministic reference) or 'gl' (OpenGL through EGL: the GPU, or "
                 "Mesa's llvmpipe without one; docs/performance.md)")
      ->capture_default_str();
  cmd.add_option("--ipd", m.ipd_m, "--scene: distance between the eyes, metres; default " + printf_text("%g", dp::kDefaultIpdM));
  cmd.add_flag("--no-face-culling{false}", m.face_culling,
               "--scene: draw every object on all six faces, clipped there, instead of only on the faces its bound reaches "
               "(the same texels, more work: to measure what the culling saves)");
}

}  // namespace arp::app
