#include "CompanionFile.hpp"

#include <cstdlib>
#include <filesystem>
#include <system_error>

namespace arp {

std::string companion_file(const char* env_var, const char* file_name, const char* built_path) {
  namespace fs = std::filesystem;
  if (const char* e = std::getenv(env_var); e && *e) return e;
  std::error_code ec;
  const fs::path beside = fs::read_symlink("/proc/self/exe", ec).parent_path() / file_name;
  if (!ec && fs::exists(beside, ec)) return beside.string();
  if (built_path && *built_path && fs::exists(built_path, ec)) return built_path;
  return "";
}

}  // namespace arp
