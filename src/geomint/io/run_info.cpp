#include "geomint/io/run_info.hpp"

#include <cstdlib>
#include <ctime>
#include <fstream>
#include <string>
#include <thread>

#include "geomint_build_info.hpp"
#include "geomint_git_info.hpp"

namespace geomint {

std::string utc_iso8601(std::chrono::system_clock::time_point t) {
  const std::time_t tt = std::chrono::system_clock::to_time_t(t);
  std::tm tm{};
  gmtime_r(&tt, &tm);
  char buf[32];
  std::strftime(buf, sizeof buf, "%Y-%m-%dT%H:%M:%SZ", &tm);
  return buf;
}

nlohmann::ordered_json build_info() {
  return {{"git_commit", GEOMINT_GIT_COMMIT},
          {"git_dirty", GEOMINT_GIT_DIRTY},
          {"version", GEOMINT_VERSION},
          {"compiler", GEOMINT_COMPILER},
          {"build_type", GEOMINT_BUILD_TYPE},
          {"cxx_flags", GEOMINT_CXX_FLAGS}};
}

nlohmann::ordered_json machine_info() {
  std::string model = "unknown";
  std::ifstream cpuinfo("/proc/cpuinfo");
  for (std::string line; std::getline(cpuinfo, line);)
    if (line.rfind("model name", 0) == 0 && line.find(':') != std::string::npos) {
      model = line.substr(line.find(':') + 1);
      model.erase(0, model.find_first_not_of(' '));
      break;
    }
  return {{"cpu", model}, {"logical_cores", std::thread::hardware_concurrency()}};
}

nlohmann::ordered_json load_average() {
  double load[3];
  if (::getloadavg(load, 3) != 3) return nullptr;
  return {load[0], load[1], load[2]};
}

}  // namespace geomint
