#include "geomint/io/fault_point.hpp"

#include <unistd.h>

#include <csignal>
#include <cstdlib>
#include <fstream>
#include <string>
#include <vector>

namespace geomint {

namespace {

struct Faults {
  long crash_after = 0, signal_at = 0;  // (0: never)
  bool torn = false;
  const char* count_file = nullptr;
  long writes = 0;
  std::vector<std::string> seen;  // (with count_file: what each write was)
  bool on() const { return crash_after > 0 || signal_at > 0 || count_file != nullptr; }
};

Faults& faults() {  // the variables, read once (and never destroyed: the count is written at exit)
  static Faults& f = *[] {
    auto* r = new Faults;
    const auto number = [](const char* name) { const char* v = std::getenv(name); return v ? std::atol(v) : 0L; };
    r->crash_after = number("GEOMINT_FAULT_AFTER_WRITES");
    r->signal_at = number("GEOMINT_FAULT_SIGNAL_AT_WRITE");
    r->torn = number("GEOMINT_FAULT_TORN") != 0;
    r->count_file = std::getenv("GEOMINT_FAULT_COUNT_WRITES");
    if (r->count_file)
      std::atexit([] {
        std::ofstream out(faults().count_file);
        for (std::size_t k = 0; k < faults().seen.size(); ++k) out << k + 1 << ' ' << faults().seen[k] << '\n';
      });
    return r;
  }();
  return f;
}

}  // namespace

void fault_point(const char* what, const std::filesystem::path& file, std::uintmax_t appended) {
  static Faults& f = faults();
  if (!f.on()) return;
  ++f.writes;
  if (f.count_file) f.seen.push_back(std::string(what) + " " + file.filename().string());
  if (f.writes == f.crash_after) {
    namespace fs = std::filesystem;
    std::error_code ec;
    if (f.torn && appended > 0) fs::resize_file(file, fs::file_size(file, ec) - appended / 2, ec);
    ::_exit(99);
  }
  if (f.writes == f.signal_at) std::raise(SIGTERM);
}

}  // namespace geomint
