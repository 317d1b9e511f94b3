// Writing an output so that a failed run never leaves a half-written file:
// write to a temporary file in the same folder (same extension, so format
// detection by name still works), then rename it into place.
#pragma once
#include <filesystem>
#include <string>

namespace arp {

// A temporary path beside `target`; InputError naming `target` if its folder does not exist.
std::filesystem::path temp_path_beside(const std::string& target);

// Moves the finished temporary file onto `target`; on failure removes it and throws InputError.
void commit_temp_file(const std::filesystem::path& tmp, const std::string& target);

// Removes a temporary file after a failed write (never throws).
void discard_temp_file(const std::filesystem::path& tmp) noexcept;

// Writes text to path through a temporary file and a rename; InputError naming the path on failure.
void write_text_atomic(const std::string& path, const std::string& text);

}  // namespace arp
