#include "SweepRunner.hpp"

#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstring>
#include <deque>
#include <filesystem>
#include <cstdio>
#include <thread>

#include "common/AtomicFile.hpp"
#include "common/InputError.hpp"
#include "common/OutputPaths.hpp"

extern char** environ;

namespace arp::sim {

namespace fs = std::filesystem;

namespace {

pid_t spawn(const SweepCommand& c) {
  posix_spawn_file_actions_t fa;
  posix_spawn_file_actions_init(&fa);
  posix_spawn_file_actions_addopen(&fa, 0, "/dev/null", O_RDONLY, 0);
  posix_spawn_file_actions_addopen(&fa, 1, c.log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_adddup2(&fa, 1, 2);
  posix_spawn_file_actions_addclosefrom_np(&fa, 3);  // a point sees none of the sweep's other files (or its other points' pipes)
  std::vector<char*> argv;
  for (const auto& a : c.argv) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  pid_t pid = 0;
  const std::string program = c.program.empty() ? c.argv[0] : c.program;
  const int rc = posix_spawn(&pid, program.c_str(), &fa, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&fa);
  if (rc == 0) return pid;
  // Not started (the program was replaced or removed meanwhile): the point fails, the sweep goes on.
  if (FILE* log = std::fopen(c.log.c_str(), "w")) {
    std::fprintf(log, "cannot start %s: %s\n", c.argv[0].c_str(), std::strerror(rc));
    std::fclose(log);
  }
  return -1;
}

int status_of(int st) { return WIFEXITED(st) ? WEXITSTATUS(st) : -WTERMSIG(st); }

}  // namespace

SweepOutcome run_sweep_locally(const std::vector<SweepCommand>& commands, int jobs,
                               const std::function<void(double, const std::string&)>& progress,
                               const std::function<int()>& stop_when, double grace_s) {
  SweepOutcome out;
  std::deque<const SweepCommand*> exclusive, shared;
  for (const auto& c : commands) (c.exclusive ? exclusive : shared).push_back(&c);
  std::map<pid_t, const SweepCommand*> running;
  const double total = static_cast<double>(commands.size());
  auto report = [&] {
    if (!progress) return;
    std::string what;
    for (const auto& [pid, c] : running) what += (what.empty() ? "" : ", ") + c->id;
    progress(static_cast<double>(out.exit_status.size()) / total, what.empty() ? "done" : what);
  };
  auto start = [&](const SweepCommand* c) {
    const pid_t pid = spawn(*c);
    if (pid > 0) running[pid] = c;
    else out.exit_status[c->id] = 127;  // as a shell reports a program it could not run
    report();
  };
  std::chrono::steady_clock::time_point stopped_at;
  bool killed = false;
  while (!exclusive.empty() || !shared.empty() || !running.empty()) {
    if (!out.stop_signal && stop_when) {
      out.stop_signal = stop_when();
      if (out.stop_signal) {
        stopped_at = std::chrono::steady_clock::now();
        for (const auto& [pid, c] : running) kill(pid, SIGTERM);
      }
    }
    if (out.stop_signal && !killed && std::chrono::steady_clock::now() - stopped_at > std::chrono::duration<double>(grace_s)) {
      killed = true;  // a point that ignores SIGTERM does not hold the sweep
      for (const auto& [pid, c] : running) kill(pid, SIGKILL);
    }
    // Start what may start: an exclusive point only on an idle machine, and nothing beside it.
    const bool exclusive_running = [&] {
      for (const auto& [pid, c] : running)
        if (c->exclusive) return true;
      return false;
    }();
    if (!out.stop_signal && !exclusive_running) {
      if (!exclusive.empty()) {
        if (running.empty()) {
          start(exclusive.front());
          exclusive.pop_front();
        }
      } else {
        while (!shared.empty() && static_cast<int>(running.size()) < jobs) {
          start(shared.front());
          shared.pop_front();
        }
      }
    }
    if (out.stop_signal && running.empty()) break;
    bool ended = false;
    for (auto it = running.begin(); it != running.end();) {
      int st = 0;
      const pid_t w = waitpid(it->first, &st, WNOHANG);
      if (w == it->first || w < 0) {  // ended (w < 0: no such child any more, e.g. reaped elsewhere)
        out.exit_status[it->second->id] = w < 0 ? -1 : status_of(st);
        it = running.erase(it);
        ended = true;
      } else {
        ++it;
      }
    }
    if (ended) report();
    else std::this_thread::sleep_for(std::chrono::milliseconds(100));
  }
  return out;
}

void check_slurm_word(const std::string& what, const std::string& path) {
  if (path.find_first_of(" \t\n'\"$`\\") != std::string::npos)
    throw InputError(what, path, "a Slurm script names this path as it is: no whitespace, quotes, $, ` or \\ in it");
}

void check_slurm_sweep_paths(const std::string& scheduler, const std::string& script_dir, const std::string& out_dir) {
  if (scheduler != "slurm") throw InputError("--emit", scheduler, "the one scheduler known is slurm (--emit slurm DIR)");
  check_slurm_word("--emit", script_dir);
  check_slurm_word("--out", out_dir);
  check_output_folder("--emit", script_dir);
}

std::vector<std::string> write_slurm_sweep(const std::string& dir, const SlurmSweep& s) {
  fs::create_directories(dir);
  const fs::path d(dir);
  std::vector<std::string> files;
  auto write = [&](const std::string& name, const std::string& text, bool executable) {
    const std::string path = (d / name).string();
    write_text_atomic(path, text);
    if (executable) fs::permissions(path, fs::perms::owner_exec | fs::perms::group_exec | fs::perms::others_exec, fs::perm_options::add);
    files.push_back(path);
  };
  auto ids = [](const std::vector<std::string>& v) {
    std::string t;
    for (const auto& id : v) t += id + "\n";
    return t;
  };
  auto limit = [](int minutes) {  // Slurm's days-hours:minutes:seconds
    char b[48];
    std::snprintf(b, sizeof b, "#SBATCH --time=%d-%02d:%02d:00\n", minutes / 1440, minutes / 60 % 24, minutes % 60);
    return std::string(b);
  };
  auto array_script = [&](const std::string& kind, size_t n, bool exclusive) {
    std::string t = "#!/bin/bash\n# " + s.name + ": the " + kind + " points, one array task each (written by arpsim).\n";
    t += "#SBATCH --job-name=" + s.name + "-" + kind + "\n";
    t += "#SBATCH --array=0-" + std::to_string(n - 1) + "\n";
    t += "#SBATCH --cpus-per-task=" + std::to_string(s.cpus_per_task) + "\n";
    t += limit(s.task_minutes);
    if (exclusive) t += "#SBATCH --exclusive\n";
    t += "#SBATCH --output=" + s.log_dir + "/" + s.name + "-" + kind + "-%A_%a.log\n";
    t += "set -euo pipefail\n";
    t += "ID=$(sed -n \"$((SLURM_ARRAY_TASK_ID + 1))p\" \"" + fs::absolute(d / (kind + ".ids")).string() + "\")\n";
    t += "exec " + s.point_command + "\n";
    return t;
  };
  write("shared.ids", ids(s.shared_ids), false);
  write("exclusive.ids", ids(s.exclusive_ids), false);
  std::string submit = "#!/bin/bash\n# Submits the sweep: both arrays, then the merge once they ended (afterany: a failed point\n"
                       "# is reported missing by the merge, the others are kept).\nset -euo pipefail\ncd \"$(dirname \"$0\")\"\n"
                       "deps=\"\"\n";
  if (!s.shared_ids.empty()) {
    write("points-shared.sbatch", array_script("shared", s.shared_ids.size(), false), true);
    submit += "deps=\"$deps:$(sbatch --parsable points-shared.sbatch)\"\n";
  }
  if (!s.exclusive_ids.empty()) {
    write("points-exclusive.sbatch", array_script("exclusive", s.exclusive_ids.size(), true), true);
    submit += "deps=\"$deps:$(sbatch --parsable points-exclusive.sbatch)\"\n";
  }
  write("merge.sbatch",
        "#!/bin/bash\n# " + s.name + ": merges the points' results into the tables (written by arpsim).\n#SBATCH --job-name=" + s.name +
            "-merge\n#SBATCH --cpus-per-task=1\n" + limit(s.merge_minutes) + "#SBATCH --output=" + s.log_dir + "/" + s.name + "-merge-%j.log\nset -euo pipefail\nexec " +
            s.merge_command + "\n",
        true);
  submit += "sbatch --dependency=afterany${deps} merge.sbatch\n";
  write("submit.sh", submit, true);
  return files;
}

}  // namespace arp::sim
