// A sweep's points as separate processes: locally on the machine's cores
// (points that measure speed run alone, the others side by side), or written
// out as a Slurm job array and a merge job that waits for it, so an overnight
// sweep runs on a cluster unchanged. Generic: a point is a command line.
#pragma once
#include <functional>
#include <map>
#include <string>
#include <vector>

namespace arp::sim {

struct SweepCommand {
  std::string id;
  std::vector<std::string> argv;  // argv[0]: the program's path
  std::string log;                // stdout and stderr go here
  bool exclusive = false;         // runs with nothing beside it (it measures speed)
  std::string program;            // the file executed, if not argv[0] (e.g. /proc/self/exe)
};

struct SweepOutcome {
  std::map<std::string, int> exit_status;  // by id; -signal for a point killed by a signal
  int stop_signal = 0;                     // the signal that stopped the sweep early (points then not started are absent)
};

// Runs the commands, `jobs` at a time (exclusive ones first, one by one);
// `progress` (fraction done, what runs) after each start and end; `stop_when`
// polled: non-zero stops starting points, sends SIGTERM to the running ones
// (SIGKILL to any still running `grace_s` later) and returns once they ended.
// A command that cannot start fails with status 127 and the reason in its log.
SweepOutcome run_sweep_locally(const std::vector<SweepCommand>& commands, int jobs,
                               const std::function<void(double, const std::string&)>& progress,
                               const std::function<int()>& stop_when, double grace_s = 10.0);

struct SlurmSweep {
  std::string name;                      // the job name
  std::vector<std::string> shared_ids;   // array tasks that share nodes
  std::vector<std::string> exclusive_ids;  // array tasks given a node each (--exclusive)
  std::string point_command;             // a shell command line with $ID for the point
  std::string merge_command;             // the command the merge job runs
  std::string log_dir;                   // where Slurm writes the tasks' output
  int cpus_per_task = 2;
  // Wall-clock limits (#SBATCH --time): a cluster's default limit may be shorter than a point.
  int task_minutes = 60;   // each array task: one point
  int merge_minutes = 10;  // the merge
};

// InputError unless `scheduler` is "slurm" and both folders can be named in a
// Slurm script as they are (no whitespace, quotes, $, backquote or backslash)
// and the script folder can be made.
void check_slurm_sweep_paths(const std::string& scheduler, const std::string& script_dir, const std::string& out_dir);
// InputError naming `what` unless `path` can stand in a Slurm script as it is.
void check_slurm_word(const std::string& what, const std::string& path);

// Writes DIR/shared.ids, exclusive.ids, points-shared.sbatch, points-exclusive.sbatch,
// merge.sbatch and submit.sh (submits the arrays, then the merge with
// --dependency=afterany on both); returns the files written.
std::vector<std::string> write_slurm_sweep(const std::string& dir, const SlurmSweep& s);

}  // namespace arp::sim
