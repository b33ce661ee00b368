#include "geomint/runner/checkpoint.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstring>
#include <fstream>

#include "geomint/io/atomic_file.hpp"
#include "geomint/io/run_info.hpp"
#include "geomint/sweep/mpi.hpp"

namespace geomint {

namespace fs = std::filesystem;
using json = nlohmann::ordered_json;

namespace {

constexpr int kFormat = 1;  // of the header and the log (checkpoint.hpp)
const char* const kHeaderSuffix = ".checkpoint.json";
const char* const kLogSuffix = ".checkpoint.log";

// The scene values under `keys` (dotted), each under its own key.
json scene_slice(const Scene& scene, const std::vector<std::string>& keys) {
  const json all = scene.to_json();
  json slice = json::object();
  for (const auto& key : keys) {
    std::string pointer = "/" + key;
    std::replace(pointer.begin(), pointer.end(), '.', '/');
    const auto at = json::json_pointer(pointer);
    slice[key] = all.contains(at) ? all.at(at) : json(nullptr);
  }
  return slice;
}

std::string shown(const json& j) {
  const std::string s = j.dump();
  return s.size() > 80 ? s.substr(0, 77) + "..." : s;
}

void write_all(int fd, const char* data, std::size_t size, const fs::path& file) {
  for (std::size_t off = 0; off < size;) {
    const ssize_t k = ::write(fd, data + off, size - off);
    if (k < 0 && errno == EINTR) continue;
    if (k <= 0) {
      const std::string why = std::strerror(errno);
      ::close(fd);
      throw OutputError("cannot write " + file.string() + ": " + why);
    }
    off += static_cast<std::size_t>(k);
  }
}

}  // namespace

CheckpointLog::CheckpointLog(const Context& ctx, const CheckpointSpec& spec, std::size_t n)
    : name_(spec.name.empty() ? ctx.study : spec.name),
      header_(ctx.out.path() / (name_ + kHeaderSuffix)),
      log_(ctx.out.path() / (name_ + kLogSuffix)),
      n_(n) {
  identity_ = {{"format", kFormat},       {"experiment", ctx.experiment},
               {"study", ctx.study},      {"name", name_},
               {"scene", scene_slice(ctx.scene, spec.keys)}, {"build", build_info()},
               {"n", n}};
}

void CheckpointLog::refuse(const fs::path& file, const std::string& why) const {
  throw SceneError("checkpoint " + file.string() + ": " + why + "; delete " +
                   (file.parent_path() / (name_ + ".checkpoint.*")).string() + " to start " + name_ +
                   " over, or run without --resume");
}

void CheckpointLog::reset() {
  fs::remove(header_), fs::remove(log_);
  tasks_done_ = 0, log_bytes_ = 0;
}

CheckpointLog::Records CheckpointLog::load(bool resume) {
  if (mpi::size() == 1) return load_here(resume);
  Records records;  // rank 0 reads (or refuses), every rank receives
  std::exception_ptr error;
  if (mpi::is_root()) try {
      records = load_here(resume);
    } catch (...) {
      error = std::current_exception();
    }
  if (mpi::all_max(error ? 1 : 0) != 0) throw_everywhere(0, error);
  std::vector<double> offsets(records.offsets.begin(), records.offsets.end());
  mpi::broadcast(records.values), mpi::broadcast(offsets);
  records.offsets.assign(offsets.begin(), offsets.end());
  tasks_done_ = records.size();
  return records;
}

CheckpointLog::Records CheckpointLog::load_here(bool resume) {
  Records records;
  if (!resume || !fs::exists(header_)) {
    reset();
    return records;
  }
  json h;
  try {
    std::ifstream in(header_);
    h = json::parse(in);
  } catch (const json::exception& e) {
    refuse(header_, std::string("not JSON (") + e.what() + ")");
  }
  if (!h.is_object()) refuse(header_, "not a checkpoint header (not a JSON object)");
  for (const char* field : {"format", "experiment", "study", "name", "scene", "build", "n", "tasks_done", "log_bytes"})
    if (!h.contains(field)) refuse(header_, std::string("no field ") + field);
  if (h["format"] != identity_["format"])
    refuse(header_, "format is " + shown(h["format"]) + ", this binary reads format " + std::to_string(kFormat));
  for (const char* field : {"experiment", "study", "name"})
    if (h[field] != identity_[field])
      refuse(header_, std::string(field) + " is " + shown(h[field]) + ", not " + shown(identity_[field]));
  for (const auto& [key, value] : identity_["build"].items())
    if (!h["build"].is_object() || !h["build"].contains(key) || h["build"][key] != value)
      refuse(header_, "written by another binary: build." + key + " is " +
                          (h["build"].is_object() && h["build"].contains(key) ? shown(h["build"][key]) : "missing") +
                          ", this binary's " + shown(value));
  if (h["scene"] != identity_["scene"]) {  // a run of other scene values: nothing of it applies
    reset();
    return records;
  }
  if (h["n"] != identity_["n"]) refuse(header_, "n is " + shown(h["n"]) + ", not the " + std::to_string(n_) + " tasks of " + name_);
  if (!h["tasks_done"].is_number_unsigned() || h["tasks_done"].get<std::uint64_t>() > n_)
    refuse(header_, "tasks_done is " + shown(h["tasks_done"]) + ": it must be an integer in [0, " + std::to_string(n_) +
                        "], the tasks of " + name_);
  if (!h["log_bytes"].is_number_unsigned())
    refuse(header_, "log_bytes is " + shown(h["log_bytes"]) + ": it must be a byte count");
  const auto done = static_cast<std::size_t>(h["tasks_done"].get<std::uint64_t>());
  const auto bytes = h["log_bytes"].get<std::uint64_t>();
  std::error_code ec;
  const auto size = fs::exists(log_) ? fs::file_size(log_, ec) : 0;
  if (ec || size < bytes)
    refuse(log_, "holds " + std::to_string(ec ? 0 : size) + " bytes, fewer than the " + std::to_string(bytes) +
                     " (log_bytes) of the " + std::to_string(done) + " tasks " + header_.filename().string() + " counts");
  std::vector<char> raw(bytes);
  std::ifstream in(log_, std::ios::binary);
  if (!in.read(raw.data(), static_cast<std::streamsize>(bytes))) refuse(log_, "cannot be read");
  std::size_t at = 0;
  for (std::size_t k = 0; k < done; ++k) {
    std::uint64_t length = 0;
    if (bytes - at < 8)
      refuse(header_, "log_bytes is " + std::to_string(bytes) + ": the log's first " + std::to_string(bytes) +
                          " bytes end after " + std::to_string(k) + " of the " + std::to_string(done) + " records (tasks_done)");
    std::memcpy(&length, raw.data() + at, 8), at += 8;
    if (length > (bytes - at) / 8)
      refuse(header_, "log_bytes is " + std::to_string(bytes) + ": record " + std::to_string(k) + " of the log counts " +
                          std::to_string(length) + " values, beyond it");
    const std::size_t first = records.values.size();
    records.values.resize(first + length);
    std::memcpy(records.values.data() + first, raw.data() + at, length * 8), at += length * 8;
    for (std::size_t i = first; i < records.values.size(); ++i)
      if (!std::isfinite(records.values[i]))
        refuse(log_, "value " + std::to_string(i - first) + " of task " + std::to_string(k) + " is not finite");
    records.offsets.push_back(records.values.size());
  }
  if (at != bytes)
    refuse(header_, "log_bytes is " + std::to_string(bytes) + ", but its " + std::to_string(done) +
                        " records (tasks_done) take " + std::to_string(at));
  if (size > bytes) fs::resize_file(log_, bytes);  // a round appended but not counted
  tasks_done_ = done, log_bytes_ = bytes;
  return records;
}

namespace {
double g_write_seconds = 0;
}  // namespace

double checkpoint_write_seconds() { return g_write_seconds; }

void CheckpointLog::append(std::span<const double> values, std::span<const std::size_t> lengths) {
  if (!mpi::is_root()) {  // rank 0 alone writes; the others keep count
    tasks_done_ += lengths.size();
    return;
  }
  const auto t0 = std::chrono::steady_clock::now();
  std::vector<char> raw(lengths.size() * 8 + values.size() * 8);
  std::size_t at = 0, v = 0;
  for (const std::size_t length : lengths) {
    const auto l = static_cast<std::uint64_t>(length);
    std::memcpy(raw.data() + at, &l, 8), at += 8;
    std::memcpy(raw.data() + at, values.data() + v, length * 8), at += length * 8, v += length;
  }
  const int fd = ::open(log_.c_str(), O_WRONLY | O_CREAT | O_APPEND | O_CLOEXEC, 0644);
  if (fd < 0) throw OutputError("cannot write " + log_.string() + ": " + std::strerror(errno));
  write_all(fd, raw.data(), raw.size(), log_);
  if (::fsync(fd) != 0 || ::close(fd) != 0) throw OutputError("cannot write " + log_.string() + ": " + std::strerror(errno));
  tasks_done_ += lengths.size(), log_bytes_ += raw.size();
  json h = identity_;
  h["tasks_done"] = tasks_done_, h["log_bytes"] = log_bytes_;
  write_file_atomic(header_, h.dump(1) + "\n");
  g_write_seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

void remove_checkpoints(const fs::path& dir) {
  // Every header before any log: a run killed in between leaves logs without a header (nothing to
  // resume, start over), never a header that counts bytes of a log already gone (refused, exit 2).
  for (const char* suffix : {kHeaderSuffix, kLogSuffix})
    for (const auto& e : fs::directory_iterator(dir))
      if (e.path().filename().string().ends_with(suffix)) fs::remove(e.path());
}

}  // namespace geomint
