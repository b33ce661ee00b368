#include "geomint/io/atomic_file.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>

#include <nlohmann/json.hpp>

namespace geomint {

namespace fs = std::filesystem;

void write_file_atomic(const fs::path& path, std::string_view content) {
  const fs::path tmp = path.parent_path() / ("." + path.filename().string() + ".tmp-" + std::to_string(::getpid()));
  const int fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd < 0) throw OutputError("cannot write " + path.string() + ": " + std::strerror(errno));
  const char* data = content.data();
  std::size_t left = content.size();
  while (left > 0) {
    const ssize_t n = ::write(fd, data, left);
    if (n < 0) {
      if (errno == EINTR) continue;
      const std::string why = std::strerror(errno);
      ::close(fd);
      ::unlink(tmp.c_str());
      throw OutputError("cannot write " + path.string() + ": " + why);
    }
    data += n;
    left -= static_cast<std::size_t>(n);
  }
  if (::fsync(fd) != 0 || ::close(fd) != 0 || std::rename(tmp.c_str(), path.c_str()) != 0) {
    const std::string why = std::strerror(errno);
    ::unlink(tmp.c_str());
    throw OutputError("cannot write " + path.string() + ": " + why);
  }
}

OutputDir::OutputDir(fs::path dir) : dir_(std::move(dir)) {
  std::error_code ec;
  fs::create_directories(dir_, ec);
  if (ec || !fs::is_directory(dir_)) {
    throw OutputError("--out " + dir_.string() + ": cannot create the directory (" +
                      (ec ? ec.message() : std::string("not a directory")) + "); give a writable directory");
  }
  // Probe: create and remove a file, so a read-only directory fails now, not after the run.
  const fs::path probe = dir_ / (".write-probe-" + std::to_string(::getpid()));
  const int fd = ::open(probe.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0644);
  if (fd < 0) {
    throw OutputError("--out " + dir_.string() + ": directory is not writable (" + std::strerror(errno) +
                      "); give a writable directory");
  }
  ::close(fd);
  ::unlink(probe.c_str());
}

void OutputDir::write(const std::string& name, std::string_view content) {
  write_file_atomic(dir_ / name, content);
  if (std::find(written_.begin(), written_.end(), name) == written_.end()) written_.push_back(name);
}

namespace {

constexpr const char* kStagingMarker = ".geomint-staging";

// The experiment a results directory belongs to: run.json's "experiment", or the staging marker's
// content; "" if it has neither.
std::string owner_of(const fs::path& dir) {
  std::ifstream marker(dir / kStagingMarker);
  std::string name;
  if (marker && std::getline(marker, name)) return name;
  std::ifstream run(dir / "run.json");
  if (!run) return "";
  const auto j = nlohmann::json::parse(run, nullptr, /*allow_exceptions=*/false);
  return j.is_object() && j.contains("experiment") && j["experiment"].is_string() ? j["experiment"].get<std::string>()
                                                                                 : "";
}

// Refuses an existing `dir` that is not an (empty) directory or a results directory of `experiment`.
void check_replaceable(const fs::path& dir, const std::string& experiment, const std::string& what) {
  std::error_code ec;
  if (!fs::exists(dir, ec)) return;
  if (!fs::is_directory(dir, ec))
    throw OutputError("--out: " + what + " " + dir.string() + " exists and is not a directory; give another --out");
  if (fs::is_empty(dir, ec)) return;
  const std::string owner = owner_of(dir);
  if (owner != experiment)
    throw OutputError("--out: " + what + " " + dir.string() + " exists and is not a results directory of " +
                      experiment + (owner.empty() ? " (no run.json)" : " (its run.json names " + owner + ")") +
                      "; it is never replaced: give a new or empty directory, or remove it");
}

// Removes the temporaries (".<name>.tmp-<pid>") a killed writer left in `dir`.
void remove_temporaries(const fs::path& dir) {
  for (const auto& e : fs::directory_iterator(dir)) {
    const std::string f = e.path().filename().string();
    if (f.size() > 1 && f[0] == '.' && f.find(".tmp-") != std::string::npos) fs::remove(e.path());
  }
}

}  // namespace

ResultsDir::ResultsDir(const fs::path& dir, const std::string& experiment, bool resume) : experiment_(experiment) {
  fs::path d = fs::absolute(dir).lexically_normal();
  if (!d.has_filename()) d = d.parent_path();  // "DIR/"
  if (d == d.root_path()) throw OutputError("--out " + dir.string() + ": the root directory is never a results directory");
  final_ = d;
  staging_ = d.parent_path() / (d.filename().string() + ".partial");
  check_replaceable(final_, experiment, "the directory");
  check_replaceable(staging_, experiment, "the staging directory");
  std::error_code ec;
  resumed_ = resume && fs::is_directory(staging_, ec) && !fs::is_empty(staging_, ec);
  if (resumed_) {
    remove_temporaries(staging_);
  } else {
    fs::remove_all(staging_, ec);
    if (ec) throw OutputError("--out: cannot empty " + staging_.string() + " (" + ec.message() + ")");
  }
  OutputDir probe(staging_);  // creates it and checks that it is writable
  write_file_atomic(staging_ / kStagingMarker, experiment + "\n");
}

void ResultsDir::commit(const std::vector<std::string>& files) {
  std::vector<fs::path> other;  // (collected first: nothing is removed while the directory is read)
  for (const auto& e : fs::directory_iterator(staging_)) {
    const std::string f = e.path().filename().string();
    if (f != kStagingMarker && std::find(files.begin(), files.end(), f) == files.end()) other.push_back(e.path());
  }
  for (const auto& p : other) fs::remove_all(p);
  fs::remove(staging_ / kStagingMarker);  // last: until here a kill leaves a staging directory --resume knows
  std::error_code ec;
  if (!fs::exists(final_, ec)) {
    if (std::rename(staging_.c_str(), final_.c_str()) != 0)
      throw OutputError("cannot move " + staging_.string() + " to " + final_.string() + ": " + std::strerror(errno));
    return;
  }
  // Swap the two directories in one step, then remove the old results (now at the staging path).
  if (::renameat2(AT_FDCWD, staging_.c_str(), AT_FDCWD, final_.c_str(), RENAME_EXCHANGE) != 0)
    throw OutputError("cannot replace " + final_.string() + " by " + staging_.string() + ": " + std::strerror(errno));
  fs::remove_all(staging_, ec);
}

void ResultsDir::discard() {
  std::error_code ec;
  fs::remove_all(staging_, ec);
}

}  // namespace geomint
