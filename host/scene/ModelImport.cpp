#include "ModelImport.hpp"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <charconv>
#include <chrono>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <thread>

#include "MeshWire.hpp"
#include "ModelPrecheck.hpp"
#include "common/CompanionFile.hpp"
#include "common/InputError.hpp"
#include "common/PrintfText.hpp"
#include "common/WholeNumber.hpp"

extern char** environ;

namespace arp::host {

namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

std::string env_or(const char* name, const std::string& fallback) {
  const char* v = std::getenv(name);
  return v && *v ? v : fallback;
}

// The helper: named by ARPSIM_IMPORT_HELPER, else beside the running
// program, else where this build put it.
std::string helper_path() {
#ifdef ARPSIM_IMPORT_HELPER_BUILT
  return companion_file("ARPSIM_IMPORT_HELPER", "arpsim-import", ARPSIM_IMPORT_HELPER_BUILT);
#else
  return companion_file("ARPSIM_IMPORT_HELPER", "arpsim-import", nullptr);
#endif
}

// Resident memory of a process, bytes (0 once it is gone).
uint64_t resident_bytes(pid_t pid) {
  std::ifstream statm("/proc/" + std::to_string(pid) + "/statm");
  uint64_t pages = 0, resident = 0;
  if (!(statm >> pages >> resident)) return 0;
  return resident * static_cast<uint64_t>(::sysconf(_SC_PAGESIZE));
}

struct Pipe {
  int fd[2] = {-1, -1};
  Pipe() {
    if (::pipe2(fd, O_CLOEXEC) != 0) throw std::runtime_error("cannot create a pipe for the model importer");
  }
  ~Pipe() {
    for (int f : fd)
      if (f >= 0) ::close(f);
  }
  void close_end(int i) {
    ::close(fd[i]);
    fd[i] = -1;
  }
};

enum class Drained { some, nothing_yet, closed };

// Reads what is ready on fd into out, keeping at most `keep` bytes (the rest is read and dropped).
Drained drain(int fd, std::string& out, size_t keep = SIZE_MAX) {
  char buf[65536];
  const ssize_t n = ::read(fd, buf, sizeof buf);
  if (n > 0) {
    if (out.size() < keep) out.append(buf, std::min(static_cast<size_t>(n), keep - out.size()));
    return Drained::some;
  }
  return n < 0 && (errno == EAGAIN || errno == EINTR) ? Drained::nothing_yet : Drained::closed;
}

}  // namespace

ImportLimits ImportLimits::from_environment() {
  ImportLimits l;
  // Each read strictly and named: "inf" or 1e300 seconds overflowed the deadline (and the message said
  // "longer than -2147483648 s"), "-1" MiB wrapped; an empty value is the default.
  const std::string seconds = env_or("ARPSIM_IMPORT_SECONDS", ""), mb = env_or("ARPSIM_IMPORT_MAX_MB", "");
  if (!seconds.empty()) {
    double v = 0;
    const auto [end, ec] = std::from_chars(seconds.data(), seconds.data() + seconds.size(), v);
    if (ec != std::errc() || end != seconds.data() + seconds.size() || !(v >= 0.001 && v <= 1e6))
      throw InputError("ARPSIM_IMPORT_SECONDS", seconds,
                       "must be a number of seconds from 0.001 to 1e6 (the model importer's time limit; default 60)");
    l.seconds = v;
  }
  if (!mb.empty()) {
    const auto v = whole_number(mb);
    if (!v || *v < 1 || *v > (int64_t{1} << 24))
      throw InputError("ARPSIM_IMPORT_MAX_MB", mb,
                       "must be a whole number of MiB from 1 to 16777216 (the model importer's memory limit; default 3072)");
    l.max_bytes = static_cast<uint64_t>(*v) << 20;
  }
  return l;
}

Mesh import_model(const std::string& path, const ImportLimits& limits) {
  precheck_model(path);
  const std::string helper = helper_path();
  if (helper.empty())
    throw InputError(path, "", "cannot import: the model importer arpsim-import is not beside this program (set ARPSIM_IMPORT_HELPER)");
  Pipe out, err;
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_adddup2(&actions, out.fd[1], STDOUT_FILENO);
  posix_spawn_file_actions_adddup2(&actions, err.fd[1], STDERR_FILENO);
  const std::string abs = fs::absolute(path).string();
  char* argv[] = {const_cast<char*>(helper.c_str()), const_cast<char*>(abs.c_str()), nullptr};
  pid_t pid = 0;
  const int rc = ::posix_spawn(&pid, helper.c_str(), &actions, nullptr, argv, environ);
  posix_spawn_file_actions_destroy(&actions);
  if (rc != 0) throw InputError(path, "", "cannot start the model importer " + helper + ": " + std::strerror(rc));
  out.close_end(1);
  err.close_end(1);
  ::fcntl(out.fd[0], F_SETFL, O_NONBLOCK);
  ::fcntl(err.fd[0], F_SETFL, O_NONBLOCK);

  // Watch it: its output, its memory, the time; kill it past a limit.
  std::string mesh_bytes, message, killed;
  const auto deadline = Clock::now() + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(limits.seconds));
  bool out_open = true, err_open = true;
  int status = 0;
  for (;;) {
    pollfd fds[2] = {{out.fd[0], POLLIN, 0}, {err.fd[0], POLLIN, 0}};
    ::poll(fds, 2, 20);
    if (out_open && (fds[0].revents & (POLLIN | POLLHUP))) out_open = drain(out.fd[0], mesh_bytes) != Drained::closed;
    if (err_open && (fds[1].revents & (POLLIN | POLLHUP))) err_open = drain(err.fd[0], message, 4096) != Drained::closed;
    if (killed.empty() && resident_bytes(pid) > limits.max_bytes)
      killed = "needed more than " + std::to_string(limits.max_bytes >> 20) + " MB of memory";
    // Its output lands in this process: bounded like its memory.
    if (killed.empty() && mesh_bytes.size() > limits.max_bytes)
      killed = "wrote more than " + std::to_string(limits.max_bytes >> 20) + " MB";
    if (killed.empty() && Clock::now() > deadline) killed = "took longer than " + printf_text("%g", limits.seconds) + " s";
    if (!killed.empty()) ::kill(pid, SIGKILL);
    if (::waitpid(pid, &status, WNOHANG) == pid) break;
  }
  // What it wrote before it ended (bytes still in the pipes; stops at the first empty read).
  while (out_open && killed.empty() && drain(out.fd[0], mesh_bytes) == Drained::some) {
  }
  while (err_open && drain(err.fd[0], message, 4096) == Drained::some) {
  }
  if (!killed.empty()) throw InputError(path, "", "the model importer " + killed + " and was stopped (the file is broken or too large)");
  if (WIFSIGNALED(status))
    throw InputError(path, "", std::string("the model importer crashed on this file (") + strsignal(WTERMSIG(status)) + ")");
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
    while (!message.empty() && (message.back() == '\n' || message.back() == '\r')) message.pop_back();
    // The helper reports an input error as "arpsim-import: error: <source>: <place>: <reason>".
    const std::string prefix = "arpsim-import: error: " + abs + ": ";
    const auto p = message.rfind(prefix);
    throw InputError(path, "", quoted(p == std::string::npos ? message : message.substr(p + prefix.size())));
  }
  Mesh m = decode_mesh(mesh_bytes, path);
  check_mesh(m, path);
  compute_vertex_normals(m);
  return m;
}

}  // namespace arp::host
