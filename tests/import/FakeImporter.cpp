// A stand-in for arpsim-import that misbehaves on purpose, so the guard in
// host/scene/ModelImport is tested without depending on which broken file
// makes assimp hang or abort: ARP_FAKE_IMPORTER=hang|hog|abort|garbage|refuse|flood|stream.
#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <thread>
#include <vector>

int main(int, char** argv) {
  const char* mode = std::getenv("ARP_FAKE_IMPORTER");
  const std::string m = mode ? mode : "";
  if (m == "hang") std::this_thread::sleep_for(std::chrono::hours(1));
  if (m == "hog") {
    std::vector<char*> blocks;
    for (;;) {  // touch every page: resident memory grows until the guard stops it
      char* b = static_cast<char*>(std::malloc(64 << 20));
      std::memset(b, 1, 64 << 20);
      blocks.push_back(b);
      std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
  }
  if (m == "abort") std::abort();
  if (m == "garbage") {
    std::fputs("not a mesh at all", stdout);
    return 0;
  }
  if (m == "stream") {  // output without end, at pipe speed
    const std::string block(1 << 20, 'x');
    for (;;)
      if (std::fwrite(block.data(), 1, block.size(), stdout) != block.size()) return 3;
  }
  if (m == "flood") {
    for (int i = 0; i < 100000; ++i) std::fprintf(stderr, "warning %d: a very long message from a noisy importer\n", i);
    return 2;
  }
  std::fprintf(stderr, "arpsim-import: error: %s: the importer refused it\n", argv[1]);
  return 2;
}
