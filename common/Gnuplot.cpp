#include "Gnuplot.hpp"

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>

#include "AtomicFile.hpp"

extern char** environ;

namespace arp {

namespace {

// gnuplot on `script` in the script's folder, its standard error into SCRIPT.log: "" when it exits 0, else
// what went wrong. Spawned without a shell: the folder is a user's --out-dir, and a quote in it ran the rest
// as commands.
std::string spawn_gnuplot(const std::filesystem::path& script) {
  const std::string dir = script.has_parent_path() ? script.parent_path().string() : std::string(".");
  const std::string name = "./" + script.filename().string();  // (never read as an option)
  const std::string log = name + ".log";
  const std::string failed = "gnuplot failed on " + script.string() + " (see " + script.string() + ".log)";
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

}  // namespace

std::string run_gnuplot(const std::filesystem::path& script, const std::string& text) {
  write_text_atomic(script.string(), text);
  if (std::system("command -v gnuplot >/dev/null 2>&1") != 0) return "gnuplot not found; " + script.string() + " is ready for it";
  return spawn_gnuplot(script);
}

std::string plot_columns(const std::string& file, int first_col, const std::vector<std::string>& names, const char* style) {
  std::string s;
  for (size_t i = 0; i < names.size(); ++i)
    s += (i ? ", " : "") + std::string("'") + file + "' using 1:" + std::to_string(first_col + static_cast<int>(i)) + " with " + style +
         " lw 2 title '" + names[i] + "'";
  return s;
}

}  // namespace arp
