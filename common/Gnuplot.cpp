#include "Gnuplot.hpp"

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <stdexcept>

#include "AtomicFile.hpp"
#include "InputError.hpp"

extern char** environ;

namespace arp {

namespace fs = std::filesystem;

namespace {

// gnuplot on `script_name` in `dir`, its standard error into `log_name`: "" when it exits 0, else what went wrong.
// Spawned without a shell: the folder is a user's --out-dir, and a quote in it ran the rest as commands.
std::string spawn_gnuplot(const std::string& dir, const std::string& script_name, const std::string& log_name,
                          const std::string& shown) {
  const std::string name = "./" + script_name;  // (never read as an option)
  const std::string log = "./" + log_name;
  const std::string failed = "gnuplot failed on " + shown + " (see " + shown + ".log)";
  posix_spawn_file_actions_t actions;
  if (int e = posix_spawn_file_actions_init(&actions); e != 0) return std::string("gnuplot could not be started: ") + std::strerror(e);
  int e = posix_spawn_file_actions_addchdir_np(&actions, dir.c_str());
  if (e == 0) e = posix_spawn_file_actions_addopen(&actions, 2, log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  pid_t pid = 0;
  char* argv[] = {const_cast<char*>("gnuplot"), const_cast<char*>(name.c_str()), nullptr};
  if (e == 0) e = posix_spawnp(&pid, "gnuplot", &actions, nullptr, argv, environ);
  posix_spawn_file_actions_destroy(&actions);
  // (glibc reports a failed chdir or open in the child as the spawn's error)
  if (e != 0) return "gnuplot could not be started in " + dir + ": " + std::strerror(e);
  int status = 0;
  while (waitpid(pid, &status, 0) < 0)
    if (errno != EINTR) return failed;
  return WIFEXITED(status) && WEXITSTATUS(status) == 0 ? std::string() : failed;
}

// Whether `png` ends with its IEND chunk: a PNG cut short (a full disk, a file-size limit) does not, and gnuplot
// does not say so.
bool png_complete(const fs::path& png) {
  static const unsigned char kIend[12] = {0, 0, 0, 0, 'I', 'E', 'N', 'D', 0xAE, 0x42, 0x60, 0x82};
  std::FILE* f = std::fopen(png.c_str(), "rb");
  if (!f) return false;
  unsigned char tail[12] = {};
  const bool ok = std::fseek(f, -12, SEEK_END) == 0 && std::fread(tail, 1, 12, f) == 12 && std::memcmp(tail, kIend, 12) == 0;
  std::fclose(f);
  return ok;
}

}  // namespace

std::string run_gnuplot(const fs::path& script, const std::string& text) {
  write_text_atomic(script.string(), text);
  if (std::system("command -v gnuplot >/dev/null 2>&1") != 0) return "gnuplot not found; " + script.string() + " is ready for it";
  // The picture is drawn to a temporary file, run from a copy of the script that names it, checked whole and
  // then renamed into place: gnuplot writes in place and says nothing of a short write.
  const fs::path dir = script.has_parent_path() ? script.parent_path() : fs::path(".");
  const std::string key = "set output '";
  const size_t at = text.find(key), end = at == std::string::npos ? at : text.find('\'', at + key.size());
  if (end == std::string::npos) throw std::logic_error("run_gnuplot: " + script.string() + " has no set output '...'");
  const std::string image = text.substr(at + key.size(), end - at - key.size());
  const fs::path target = dir / image, tmp_image = temp_path_beside(target.string()), tmp_script = temp_path_beside(script.string());
  std::string run = text;
  run.replace(at + key.size(), image.size(), tmp_image.filename().string());
  std::string note;
  try {
    write_text_file(tmp_script, run, script.string());
    note = spawn_gnuplot(dir.string(), tmp_script.filename().string(), script.filename().string() + ".log", script.string());
  } catch (...) {
    discard_temp_file(tmp_script);
    discard_temp_file(tmp_image);
    throw;
  }
  discard_temp_file(tmp_script);
  if (!note.empty()) {
    discard_temp_file(tmp_image);
    return note;
  }
  if (!png_complete(tmp_image)) {
    discard_temp_file(tmp_image);
    throw InputError(target.string(), "", "writing the plot failed: gnuplot's picture was cut short (a full disk or a file-size limit?)");
  }
  commit_temp_file(tmp_image, target.string());
  return "";
}

std::string plot_columns(const std::string& file, int first_col, const std::vector<std::string>& names, const char* style) {
  std::string s;
  for (size_t i = 0; i < names.size(); ++i)
    s += (i ? ", " : "") + std::string("'") + file + "' using 1:" + std::to_string(first_col + static_cast<int>(i)) + " with " + style +
         " lw 2 title '" + names[i] + "'";
  return s;
}

}  // namespace arp
