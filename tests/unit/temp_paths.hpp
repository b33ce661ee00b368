#pragma once
// Paths of a test's scratch files and directories under the system's temporary directory, unique to
// the test process and removed when it exits (ctest runs every test in a process of its own).
#include <filesystem>
#include <string>
#include <vector>

#include <unistd.h>

namespace geomint::test {

// <tmp>/<stem>_<pid><suffix>, removed (with everything under it) at exit.
inline std::filesystem::path temp_path(const std::string& stem, const std::string& suffix = "") {
  struct RemovedAtExit {
    std::vector<std::filesystem::path> paths;
    ~RemovedAtExit() {
      std::error_code ignored;
      for (const auto& p : paths) std::filesystem::remove_all(p, ignored);
    }
  };
  static RemovedAtExit registry;
  const auto p = std::filesystem::temp_directory_path() / (stem + "_" + std::to_string(::getpid()) + suffix);
  registry.paths.push_back(p);
  return p;
}

}  // namespace geomint::test
