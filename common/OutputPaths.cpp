#include "OutputPaths.hpp"

#include <filesystem>
#include <cerrno>
#include <cstdio>
#include <cstring>

#include <stdlib.h>
#include <unistd.h>

#include "AtomicFile.hpp"
#include "InputError.hpp"

namespace arp {

namespace fs = std::filesystem;

namespace {
// Where a path that may not exist yet leads: absolute first (weakly_canonical resolves only the part that
// exists, so "w.vcd" and "./w.vcd" came out as "w.vcd" and "/here/w.vcd", and two names of one new file were
// taken for two files), then its links resolved; lexically normalised where the file system cannot say.
fs::path where_leads(const std::string& p) {
  std::error_code ec;
  const fs::path abs = fs::absolute(p, ec);
  if (ec) return fs::path(p).lexically_normal();
  const fs::path c = fs::weakly_canonical(abs, ec);
  return ec ? abs.lexically_normal() : c;
}
}  // namespace

bool same_file(const std::string& a, const std::string& b) {
  std::error_code ec;
  if (fs::exists(a, ec) && fs::exists(b, ec)) return fs::equivalent(a, b, ec) && !ec;
  return where_leads(a) == where_leads(b);
}

namespace {

// A folder's path for comparing with another's: "." for "", no trailing separator ("o/" is "o"). Not
// normalised as text: "S/.." is where the link S leads's parent, which same_file finds and the text does not.
std::string folder_key(const std::string& dir) {
  std::string p = dir.empty() ? "." : dir;
  while (p.size() > 1 && p.back() == '/') p.pop_back();
  return p;
}

// Creates and removes the temporary file the output will be written through.
void check_writable(const NamedPath& o) {
  std::error_code ec;
  if (fs::is_directory(o.path, ec)) throw InputError(o.option, o.path, "is a folder, not a file");
  const fs::path tmp = temp_path_beside(o.path);  // InputError if the folder does not exist
  // The name itself, which the temporary file's (shortened where it must be) does not test: a name the file
  // system cannot hold failed only at the end, when the finished file was moved into place.
  const fs::path dir = fs::path(o.path).has_parent_path() ? fs::path(o.path).parent_path() : fs::path(".");
  const long name_max = ::pathconf(dir.c_str(), _PC_NAME_MAX);
  const size_t name = fs::path(o.path).filename().string().size();
  if (name_max > 0 && name > static_cast<size_t>(name_max))
    throw InputError(o.option, o.path, "cannot write there: the name is " + std::to_string(name) + " bytes, longer than the " +
                                           std::to_string(name_max) + " the file system holds");
  std::FILE* probe = std::fopen(tmp.c_str(), "wb");
  if (!probe) {
    const int err = errno;
    throw InputError(o.option, o.path,
                     err == ENAMETOOLONG ? std::string("cannot write there: the name is too long for the file system")
                                         : std::string("cannot write there: ") + std::strerror(err));
  }
  std::fclose(probe);
  discard_temp_file(tmp);
}

}  // namespace

void check_output_folder(const std::string& option, const std::string& dir) {
  std::error_code ec;
  fs::path p = fs::absolute(dir, ec);
  while (!fs::exists(p, ec) && p.has_parent_path() && p != p.parent_path()) p = p.parent_path();
  if (!fs::is_directory(p, ec)) throw InputError(option, dir, p.string() + " is not a folder");
  // A folder made and removed again where the first missing one would go: permissions, read-only or virtual file systems.
  std::string probe = (p / ".arpsim-probe-XXXXXX").string();
  if (!::mkdtemp(probe.data())) throw InputError(option, dir, "cannot create the folder: nothing can be written in " + p.string());
  fs::remove(probe, ec);
}

void make_output_folder(const std::string& option, const std::string& dir) {
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec || !fs::is_directory(dir, ec))
    throw InputError(option, dir, "cannot create the folder" + (ec ? ": " + ec.message() : std::string(": a file of that name exists")));
  check_writable({option, (fs::path(dir) / ".arpsim-write-probe").string()});
}

void check_output_paths(const std::vector<NamedPath>& outputs, const std::vector<NamedPath>& inputs) {
  for (size_t i = 0; i < outputs.size(); ++i) {
    const NamedPath& o = outputs[i];
    if (o.path.empty()) continue;
    if (o.path == "-") throw InputError(o.option, o.path, output_name_fault(o.path));
    for (const NamedPath& in : inputs)
      if (!in.path.empty() && in.path != "-" && same_file(o.path, in.path))
        throw InputError(o.option, o.path, "is the " + in.option + " input; it would be overwritten");
    for (size_t j = 0; j < i; ++j)
      if (!outputs[j].path.empty() && same_file(o.path, outputs[j].path))
        throw InputError(o.option, o.path, "is also the " + outputs[j].option + " output");
    if (o.folder_made_later) {
      std::error_code ec;
      if (fs::is_directory(o.path, ec)) throw InputError(o.option, o.path, "is a folder, not a file");
      check_output_folder(o.option, fs::path(o.path).has_parent_path() ? fs::path(o.path).parent_path().string() : ".");
    } else {
      check_writable(o);
    }
  }
}

std::string output_name_fault(const std::string& name, const std::string& what) {
  if (name.empty()) return "is empty: name the " + what + " to write";
  if (name == "-") return "names standard input, and outputs go to " + what + "s: name one (./- for a " + what + " called '-')";
  return "";
}

bool same_folder(const std::string& a, const std::string& b) { return same_file(folder_key(a), folder_key(b)); }

void check_out_dir_files(const std::string& dir_option, const std::string& dir, const std::vector<NamedPath>& files,
                         const std::function<std::string(const std::string& name)>& written_as) {
  const std::string folder = folder_key(dir);
  for (const NamedPath& f : files) {
    if (f.path.empty() || f.path == "-") continue;
    std::error_code ec;
    const fs::path given(f.path), resolved = fs::weakly_canonical(given, ec);
    for (const fs::path& p : {given, ec ? given : resolved}) {
      if (p.filename().empty()) continue;  // a folder ("o/")
      if (!same_file(p.has_parent_path() ? p.parent_path().string() : ".", folder)) continue;
      const std::string what = written_as(p.filename().string());
      if (!what.empty()) throw InputError(f.option, f.path, "is where " + dir_option + " puts " + what + "; it would be overwritten");
    }
  }
}

}  // namespace arp
