#include "geomint/io/run_info.hpp"

#include <ctime>

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

}  // namespace geomint
