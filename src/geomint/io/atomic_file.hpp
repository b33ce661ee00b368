#pragma once
// Output files appear whole or not at all: each is written to a temporary name
// in the same directory and renamed over the target; and a results directory is
// replaced as a whole, only when its run succeeds.
#include <filesystem>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace geomint {

struct OutputError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

void write_file_atomic(const std::filesystem::path& path, std::string_view content);

// The output directory of one experiment run. The constructor creates it and
// checks that it is writable (throws OutputError, before any work is done).
class OutputDir {
 public:
  explicit OutputDir(std::filesystem::path dir);
  const std::filesystem::path& path() const { return dir_; }
  void write(const std::string& name, std::string_view content);  // atomic
  const std::vector<std::string>& written() const { return written_; }

 private:
  std::filesystem::path dir_;
  std::vector<std::string> written_;
};

// The results directory DIR of one run of `experiment`. The run writes into the
// staging directory DIR.partial (a sibling, so that the final rename stays on one
// file system); commit() then replaces DIR by it in one rename, so a failed or
// killed run leaves the previous DIR exactly as it was. The constructor refuses
// (OutputError, before any work) a DIR, or a DIR.partial, that exists, is not
// empty and is not a results directory of this experiment (a run.json naming it,
// or the staging marker), so that --out can never replace a user's files. With
// `resume`, the staging directory of an interrupted run is kept (its checkpoint
// is what --resume continues from); otherwise it is emptied.
// Before that, the path is checked (not empty, not a symbolic link, its parent an existing writable
// directory, names short enough for DIR.partial) and the run takes an exclusive lock on DIR.lock
// (flock: the kernel releases it when the process ends, however it ends), so that a second run on
// the same DIR is refused at once, naming the process that holds it, and never touches its
// DIR.partial. The lock file is removed when the ResultsDir goes (a killed run's is reused).
class DirLock {
 public:
  DirLock() = default;
  explicit DirLock(const std::filesystem::path& file);  // throws OutputError if another process holds it
  DirLock(DirLock&& o) noexcept : file_(std::move(o.file_)), fd_(o.fd_) { o.fd_ = -1; }
  DirLock& operator=(DirLock&& o) noexcept;
  ~DirLock();

 private:
  void release() noexcept;  // removes and unlocks the file, if held
  std::filesystem::path file_;
  int fd_ = -1;
};

class ResultsDir {
 public:
  ResultsDir(const std::filesystem::path& dir, const std::string& experiment, bool resume);
  const std::filesystem::path& final_path() const { return final_; }
  const std::filesystem::path& staging_path() const { return staging_; }
  bool resumed() const { return resumed_; }  // the staging directory of an earlier run was kept
  // DIR := the staging directory, holding exactly `files` (the run's OutputDir::written()): anything
  // else a resumed run's staging directory still holds (the files of studies this run did not
  // run, perhaps of other scene values; a killed writer's temporaries) is removed first.
  void commit(const std::vector<std::string>& files);
  void discard();  // removes the staging directory (DIR is untouched)

 private:
  std::filesystem::path final_, staging_;
  std::string experiment_;
  bool resumed_ = false;
  DirLock lock_;
};

}  // namespace geomint
