// Writing an output so that a failed run never leaves a half-written file:
// write to a temporary file in the same folder (same extension, so format
// detection by name still works), then rename it into place.
#pragma once
#include <filesystem>
#include <functional>
#include <string>
#include <utility>
#include <vector>

namespace arp {

// A temporary path beside `target`; InputError naming `target` if its folder does not exist, or if it
// names something other than a file (a device, a FIFO, a socket: a rename would replace the node). A
// symbolic link named as an output is replaced by the file, not followed (as `sed -i` does): following it
// would let a link planted in a shared folder choose what a run as root overwrites.
std::filesystem::path temp_path_beside(const std::string& target);

// Moves the finished temporary file onto `target`; on failure removes it and throws InputError.
void commit_temp_file(const std::filesystem::path& tmp, const std::string& target);

// Removes a temporary file after a failed write (never throws).
void discard_temp_file(const std::filesystem::path& tmp) noexcept;

// Writes text to a file as it is (no temporary): InputError naming `shown` with the system's reason on failure.
void write_text_file(const std::filesystem::path& file, const std::string& text, const std::string& shown);

// Calls write(temporary path) for `target`, then renames the temporary into place; a write that throws
// leaves no temporary behind (and its exception goes on).
void write_through_temp(const std::string& target, const std::function<void(const std::filesystem::path&)>& write);

// Writes text to path through a temporary file and a rename; InputError naming the path on failure.
void write_text_atomic(const std::string& path, const std::string& text);

// Several outputs of one command, every one written before any is moved into place: each is written to its
// temporary path, and commit() renames them all; those not committed are removed when the group goes. A
// failed write (a full disk) leaves none of them.
class OutputGroup {
 public:
  OutputGroup() = default;
  OutputGroup(const OutputGroup&) = delete;
  OutputGroup& operator=(const OutputGroup&) = delete;
  ~OutputGroup();
  // The temporary path to write `target` to (temp_path_beside).
  std::filesystem::path stage(const std::string& target);
  // A temporary file already made for `target` (temp_path_beside), now the group's to commit or remove.
  void adopt(const std::filesystem::path& tmp, const std::string& target);
  void commit();

 private:
  std::vector<std::pair<std::filesystem::path, std::string>> staged_;
};

}  // namespace arp
