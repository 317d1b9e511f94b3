// A command's files checked before any work starts: every output can be
// written (its folder exists, it is not a folder, a file can be created
// there), no two outputs are one file, and no output is one of the inputs --
// so an hour of simulation is never lost to a typo in --report, and
// `--out x.png` never overwrites the `--cross x.png` it reads.
#pragma once
#include <functional>
#include <string>
#include <vector>

namespace arp {

// A file and what named it on the command line ("--report", "--trace").
struct NamedPath {
  std::string option, path;
  bool folder_made_later = false;  // an output whose folder the command creates: checked as check_output_folder does
};

// Why `name` cannot name an output (`what`: "file" or "folder"), or "" when it can: it is empty, or it is "-",
// standard input's name to every reader (an output of that name was written as a file called "-").
std::string output_name_fault(const std::string& name, const std::string& what = "file");

// InputError naming the option and the file on the first fault; empty paths are skipped, "-" (standard
// input's name to every reader) is refused as an output.
void check_output_paths(const std::vector<NamedPath>& outputs, const std::vector<NamedPath>& inputs);

// Checks an output folder could be made and written without making it (its
// nearest existing ancestor is a writable folder): for the checks before a
// run, which must leave nothing behind if a later input is refused.
void check_output_folder(const std::string& option, const std::string& dir);
// Creates an output folder (and its parents) and checks a file can be
// written in it; InputError naming the option and the folder otherwise.
void make_output_folder(const std::string& option, const std::string& dir);

// InputError when one of `files` would be overwritten by a file the command writes into the folder `dir`
// (named by `dir_option`): `written_as(name)` says what the command writes there under that name ("frame 3's
// image"), or "" for a name it does not write. A file is taken by its name as given and by where it leads
// (symbolic links followed), so a link to a file the command writes is that file. Empty paths and "-" are skipped.
void check_out_dir_files(const std::string& dir_option, const std::string& dir, const std::vector<NamedPath>& files,
                         const std::function<std::string(const std::string& name)>& written_as);

// True when a and b name the same folder ("" and "." alike, "o/" and "o" alike).
bool same_folder(const std::string& a, const std::string& b);

// True when a and b name the same file (the same inode if both exist, else the same normalised path).
bool same_file(const std::string& a, const std::string& b);

}  // namespace arp
