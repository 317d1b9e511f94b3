// Where arpsim finds a file of its own that it runs or loads at run time (the
// model-import helper, the image module): named by an environment variable,
// else beside the running program, else where the build put it.
#pragma once
#include <string>

namespace arp {

// The first of: $env_var (when set and not empty), `file_name` beside
// /proc/self/exe, `built_path` (when it exists). Empty when none is found.
std::string companion_file(const char* env_var, const char* file_name, const char* built_path);

}  // namespace arp
