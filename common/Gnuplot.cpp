#include "Gnuplot.hpp"

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>

#include <cerrno>
#include <cstdlib>

#include "AtomicFile.hpp"

extern char** environ;

namespace arp {

namespace {

// gnuplot on `script` in the script's folder, its standard error into SCRIPT.log; true when it exits 0.
// Spawned without a shell: the folder is a user's --out-dir, and a quote in it ran the rest as commands.
bool spawn_gnuplot(const std::filesystem::path& script) {
  const std::string dir = script.has_parent_path() ? script.parent_path().string() : std::string(".");
  const std::string name = "./" + script.filename().string();  // (never read as an option)
  const std::string log = name + ".log";
  posix_spawn_file_actions_t actions;
  if (posix_spawn_file_actions_init(&actions) != 0) return false;
  bool ok = posix_spawn_file_actions_addchdir_np(&actions, dir.c_str()) == 0 &&
            posix_spawn_file_actions_addopen(&actions, 2, log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644) == 0;
  pid_t pid = 0;
  char* argv[] = {const_cast<char*>("gnuplot"), const_cast<char*>(name.c_str()), nullptr};
  ok = ok && posix_spawnp(&pid, "gnuplot", &actions, nullptr, argv, environ) == 0;
  posix_spawn_file_actions_destroy(&actions);
  if (!ok) return false;
  int status = 0;
  while (waitpid(pid, &status, 0) < 0)
    if (errno != EINTR) return false;
  return WIFEXITED(status) && WEXITSTATUS(status) == 0;
}

}  // namespace

std::string run_gnuplot(const std::filesystem::path& script, const std::string& text) {
  write_text_atomic(script.string(), text);
  if (std::system("command -v gnuplot >/dev/null 2>&1") != 0) return "gnuplot not found; " + script.string() + " is ready for it";
  if (!spawn_gnuplot(script)) return "gnuplot failed on " + script.string() + " (see " + script.string() + ".log)";
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
