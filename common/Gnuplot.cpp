#include "Gnuplot.hpp"

#include <cstdlib>

#include "AtomicFile.hpp"

namespace arp {

std::string run_gnuplot(const std::filesystem::path& script, const std::string& text) {
  write_text_atomic(script.string(), text);
  if (std::system("command -v gnuplot >/dev/null 2>&1") != 0) return "gnuplot not found; " + script.string() + " is ready for it";
  const std::string cmd = "cd '" + script.parent_path().string() + "' && gnuplot '" + script.filename().string() + "' 2> '" +
                          script.filename().string() + ".log'";
  if (std::system(cmd.c_str()) != 0) return "gnuplot failed on " + script.string() + " (see " + script.string() + ".log)";
  return "";
}

std::string plot_columns(const std::string& file, int first_col, const std::vector<std::string>& names, const char* style) {
  std::string s;
  for (size_t i = 0; i < names.size(); ++i)
    s += (i ? ", " : "") + std::string("'") + file + "' using 1:" + std::to_string(first_col + static_cast<int>(i)) + " with " + style +
         " lw 2 title '" + names[i] + "'";
  return s;
}

}  // namespace arp
