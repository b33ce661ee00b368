#include "geomint/io/atomic_file.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <climits>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>

#include <nlohmann/json.hpp>

#include "geomint/io/fault_point.hpp"
#include "geomint/io/printable.hpp"

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
  const bool written = ::fsync(fd) == 0 && ::close(fd) == 0;
  if (written) fault_point("write", tmp);
  if (!written || std::rename(tmp.c_str(), path.c_str()) != 0) {
    const std::string why = std::strerror(errno);
    ::unlink(tmp.c_str());
    throw OutputError("cannot write " + path.string() + ": " + why);
  }
  fault_point("rename", path);
}

OutputDir::OutputDir(fs::path dir) : dir_(std::move(dir)) {
  std::error_code ec;
  if (fs::create_directories(dir_, ec)) fault_point("mkdir", dir_);
  if (ec || !fs::is_directory(dir_)) {
    throw OutputError("--out " + dir_.string() + ": cannot create the directory (" +
                      (ec ? ec.message() : std::string("not a directory")) + "); give a writable directory");
  }
  // Probe: create and remove a file, so a read-only directory fails now, not after the run (named as a
  // temporary, which a run killed in between leaves to the next one to remove).
  const fs::path probe = dir_ / (".write-probe.tmp-" + std::to_string(::getpid()));
  const int fd = ::open(probe.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0644);
  if (fd < 0) {
    throw OutputError("--out " + dir_.string() + ": directory is not writable (" + std::strerror(errno) +
                      "); give a writable directory");
  }
  ::close(fd);
  fault_point("probe", probe);
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

bool is_temporary(const fs::path& p) {  // ".<name>.tmp-<pid>": write_file_atomic's, and OutputDir's probe
  const std::string f = p.filename().string();
  return f.size() > 1 && f[0] == '.' && f.find(".tmp-") != std::string::npos;
}

// Removes the temporaries a killed writer left in `dir`.
void remove_temporaries(const fs::path& dir) {
  for (const auto& e : fs::directory_iterator(dir))
    if (is_temporary(e.path())) fs::remove(e.path());
}

// A staging directory that holds nothing but a killed writer's temporaries (a run killed before it wrote its
// marker) is emptied: under the lock no other run writes there, and nothing else would tell whose it is.
void clear_if_only_temporaries(const fs::path& dir) {
  std::error_code ec;
  if (!fs::is_directory(dir, ec) || fs::is_empty(dir, ec)) return;
  for (const auto& e : fs::directory_iterator(dir))
    if (!is_temporary(e.path())) return;
  remove_temporaries(dir);
}

// Removes a results or staging directory, what marks it as one (run.json, the staging marker) last: a run
// stopped midway leaves a directory the next one still knows as one (check_replaceable), or an empty one.
// The first error stops it (in ec).
void remove_results_dir(const fs::path& dir, std::error_code& ec) {
  ec.clear();
  if (std::error_code absent; !fs::is_directory(dir, absent)) return;
  std::vector<fs::path> rest, marks;  // (collected first: nothing is removed while the directory is read)
  for (const auto& e : fs::directory_iterator(dir, ec)) {
    const std::string f = e.path().filename().string();
    (f == "run.json" || f == kStagingMarker ? marks : rest).push_back(e.path());
  }
  rest.insert(rest.end(), marks.begin(), marks.end());
  rest.push_back(dir);
  for (const auto& p : rest) {
    if (ec) return;
    fs::remove_all(p, ec);
    if (!ec) fault_point("remove", p);
  }
}

// A results directory (run.json, or a staging marker) at `dir`.
bool is_results_dir(const fs::path& dir) {
  std::error_code ec;
  return fs::is_regular_file(dir / "run.json", ec) || fs::is_regular_file(dir / kStagingMarker, ec);
}

// Refuses a --out inside another results directory (replacing that one would delete it), and a --out whose
// results directory holds another one (replacing it would delete the other).
void check_not_nested(const fs::path& d) {
  for (fs::path p = d.parent_path(); p != p.root_path() && !p.empty(); p = p.parent_path())
    if (is_results_dir(p))
      throw OutputError("--out " + printable(d.string()) + " lies inside the results directory " + printable(p.string()) +
                        ", which a run of its experiment replaces as a whole; give a directory outside it");
  std::error_code ec;
  if (!fs::is_directory(d, ec)) return;
  for (const auto& e : fs::directory_iterator(d, ec))
    if (e.is_directory(ec) && is_results_dir(e.path()))
      throw OutputError("--out " + printable(d.string()) + " holds the results directory " + printable(e.path().string()) +
                        ", which replacing it would delete; move that one out first");
}

// Refuses a --out path that cannot become a results directory, before any work: a symbolic link (the
// final rename would replace the link, not what it names), a parent that is not a writable directory,
// a name too long for DIR.partial and DIR.lock, a path the system cannot resolve.
void check_out_path(const fs::path& d, const std::string& given) {
  const std::string out = "--out " + printable(given) + ": ";
  if (d.filename().string().size() + std::string_view(".partial").size() > NAME_MAX)
    throw OutputError(out + "the name " + d.filename().string().substr(0, 40) + "... is " +
                      std::to_string(d.filename().string().size()) + " bytes; with .partial it would exceed the " +
                      std::to_string(NAME_MAX) + " a name may have");
  if (d.string().size() + 8 >= PATH_MAX)
    throw OutputError(out + "the path is " + std::to_string(d.string().size()) + " bytes, beyond PATH_MAX (" +
                      std::to_string(PATH_MAX) + ") with .partial");
  struct stat st {};
  if (::lstat(d.c_str(), &st) == 0) {
    if (S_ISLNK(st.st_mode))
      throw OutputError(out + "is a symbolic link; give the directory itself (the results replace DIR as a whole)");
  } else if (errno != ENOENT) {
    throw OutputError(out + std::strerror(errno));
  }
  fs::path parent = d.parent_path();  // (the nearest that exists: the others are created)
  while (::stat(parent.c_str(), &st) != 0 && errno == ENOENT && parent != parent.root_path()) parent = parent.parent_path();
  if (::stat(parent.c_str(), &st) != 0)
    throw OutputError(out + "its parent directory " + parent.string() + ": " + std::strerror(errno));
  if (!S_ISDIR(st.st_mode)) throw OutputError(out + parent.string() + " is not a directory");
  if (::access(parent.c_str(), W_OK | X_OK) != 0)
    throw OutputError(out + "the directory " + parent.string() + " is not writable (" + std::strerror(errno) + ")");
  std::error_code ec;
  fs::create_directories(d.parent_path(), ec);
  if (ec) throw OutputError(out + "cannot create " + d.parent_path().string() + " (" + ec.message() + ")");
}

// The process id a lock file names ("?" if none).
std::string holder_of(int fd) {
  char buf[32] = {};
  const ssize_t n = ::pread(fd, buf, sizeof buf - 1, 0);
  std::string pid(buf, n > 0 ? static_cast<std::size_t>(n) : 0);
  while (!pid.empty() && (pid.back() == '\n' || pid.back() == ' ')) pid.pop_back();
  return pid.empty() ? "?" : pid;
}

}  // namespace

DirLock::DirLock(const fs::path& file) : file_(file) {
  for (;;) {  // (until the lock is held on the file that is at the path: another run may remove it meanwhile)
    fd_ = ::open(file_.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
    if (fd_ < 0) throw OutputError("--out: cannot create the lock " + file_.string() + ": " + std::strerror(errno));
    if (::flock(fd_, LOCK_EX | LOCK_NB) != 0) {
      const std::string holder = holder_of(fd_);
      ::close(fd_), fd_ = -1;
      throw OutputError("--out: another run (process " + holder + ") is writing " +
                        file_.parent_path().string() + "/" + file_.stem().string() + " (it holds " + file_.string() +
                        "); wait for it to end, or give another --out");
    }
    struct stat held {}, at_path {};
    if (::fstat(fd_, &held) == 0 && ::stat(file_.c_str(), &at_path) == 0 && held.st_ino == at_path.st_ino &&
        held.st_dev == at_path.st_dev)
      break;
    ::close(fd_), fd_ = -1;
  }
  const std::string pid = std::to_string(::getpid()) + "\n";
  if (::ftruncate(fd_, 0) != 0 || ::pwrite(fd_, pid.data(), pid.size(), 0) < 0) {}  // (the holder's id: for messages only)
  fault_point("lock", file_);
}

DirLock& DirLock::operator=(DirLock&& o) noexcept {
  if (this != &o) {
    release();
    file_ = std::move(o.file_), fd_ = o.fd_, o.fd_ = -1;
  }
  return *this;
}

DirLock::~DirLock() { release(); }

void DirLock::release() noexcept {
  if (fd_ < 0) return;
  ::unlink(file_.c_str());  // (while held: a run that opened it before checks the path and takes the new one)
  fault_point("remove", file_);
  ::close(fd_);
  fd_ = -1;
}

ResultsDir::ResultsDir(const fs::path& dir, const std::string& experiment, bool resume) : experiment_(experiment) {
  if (dir.empty()) throw OutputError("--out: an empty path; give the results directory");
  std::error_code ec0;
  fs::path d = fs::absolute(dir, ec0).lexically_normal();
  if (ec0) throw OutputError("--out " + dir.string() + ": " + ec0.message());
  if (!d.has_filename()) d = d.parent_path();  // "DIR/"
  if (d == d.root_path()) throw OutputError("--out " + dir.string() + ": the root directory is never a results directory");
  final_ = d;
  staging_ = d.parent_path() / (d.filename().string() + ".partial");
  check_out_path(final_, dir.string());
  lock_ = DirLock(d.parent_path() / (d.filename().string() + ".lock"));
  check_not_nested(final_);
  clear_if_only_temporaries(staging_);
  check_replaceable(final_, experiment, "the directory");
  check_replaceable(staging_, experiment, "the staging directory");
  std::error_code ec;
  resumed_ = resume && fs::is_directory(staging_, ec) && !fs::is_empty(staging_, ec);
  if (resumed_) {
    remove_temporaries(staging_);
  } else {
    remove_results_dir(staging_, ec);
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
  for (const auto& p : other) fs::remove_all(p), fault_point("remove", p);
  fs::remove(staging_ / kStagingMarker);  // last: until here a kill leaves a staging directory --resume knows
  fault_point("remove", staging_ / kStagingMarker);
  std::error_code ec;
  if (!fs::exists(final_, ec)) {
    if (std::rename(staging_.c_str(), final_.c_str()) != 0)
      throw OutputError("cannot move " + staging_.string() + " to " + final_.string() + ": " + std::strerror(errno));
    fault_point("rename", final_);
    return;
  }
  // Swap the two directories in one step, then remove the old results (now at the staging path).
  if (::renameat2(AT_FDCWD, staging_.c_str(), AT_FDCWD, final_.c_str(), RENAME_EXCHANGE) != 0)
    throw OutputError("cannot replace " + final_.string() + " by " + staging_.string() + ": " + std::strerror(errno));
  fault_point("exchange", final_);
  remove_results_dir(staging_, ec);
}

void ResultsDir::discard() {
  std::error_code ec;
  remove_results_dir(staging_, ec);
}

}  // namespace geomint
