// Plots through gnuplot (Debian gnuplot-nox): a script is written beside its
// data and run there, so a user gets the picture from the command that made
// the data, and can edit and re-run the script.
#pragma once
#include <filesystem>
#include <string>
#include <vector>

namespace arp {

// Writes `script` (atomically) and runs gnuplot on it in its folder, its
// warnings going to SCRIPT.log. The picture it names (its one `set output`)
// is drawn to a temporary file, checked whole and renamed into place:
// InputError naming the picture when it was cut short (a full disk). Returns
// a note for the user when gnuplot is missing or fails (empty when the plot
// was made).
std::string run_gnuplot(const std::filesystem::path& script, const std::string& text);

// "'FILE' using 1:C with STYLE lw 2 title 'NAME', ..." for columns first_col, first_col+1, ... (CSV with a header).
std::string plot_columns(const std::string& file, int first_col, const std::vector<std::string>& names,
                         const char* style = "lines");

}  // namespace arp
