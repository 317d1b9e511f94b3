// The golden reference must be independent of the arithmetic it checks: its
// sources may include only the configuration structs and the display
// memory's storage, never a datapath stage.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <set>

TEST(GoldenReference, IncludesNoDatapathArithmetic) {
  const std::set<std::string> allowed{"rtl_model/datapath/ArpConfig.hpp", "rtl_model/datapath/DisplayMemoryBank.hpp",
                                      "rtl_model/datapath/FixedPoint.hpp"};  // FixedPoint: ArpConfig's Rounding enum
  const std::filesystem::path dir = std::filesystem::path(ARPSIM_SOURCE_DIR) / "reference/golden";
  int files = 0, model_includes = 0;
  for (const auto& e : std::filesystem::directory_iterator(dir)) {
    std::ifstream in(e.path());
    std::string line;
    ++files;
    while (std::getline(in, line)) {
      const auto pos = line.find("#include \"");
      if (pos != std::string::npos) {
        const auto start = pos + 10, stop = line.find('"', start);
        const std::string h = line.substr(start, stop - start);
        if (h.rfind("rtl_model/", 0) == 0) {
          ++model_includes;
          EXPECT_TRUE(allowed.count(h)) << e.path() << " includes " << h;
        }
      }
    }
  }
  EXPECT_GE(files, 2);
  EXPECT_GE(model_includes, 2);  // the scan does see the configuration and memory includes
}
