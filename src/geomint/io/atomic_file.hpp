#pragma once
// Output files appear whole or not at all: each is written to a temporary name
// in the same directory and renamed over the target.
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

}  // namespace geomint
