#include "geomint/runner/checkpoint.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <functional>
#include <numeric>
#include <random>

#include "geomint/io/atomic_file.hpp"
#include "geomint/io/crc32c.hpp"
#include "geomint/io/fault_point.hpp"
#include "geomint/io/run_info.hpp"
#include "geomint/sweep/mpi.hpp"

namespace geomint {

namespace fs = std::filesystem;
using json = nlohmann::ordered_json;

namespace {

constexpr int kFormat = 4;  // of the header and the log (checkpoint.hpp)
constexpr char kMagic[8] = {'g', 'e', 'o', 'm', 'i', 'n', 't', 'L'};  // the log's first 8 bytes
constexpr std::size_t kPreamble = 16;                                // the magic and the run id
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

// The keys a study reads but those that only say when to stop and save (checkpoint.*).
std::vector<std::string> task_keys(const std::vector<std::string>& reads) {
  std::vector<std::string> keys;
  for (const auto& key : reads)
    if (!key_under(key, {"checkpoint"})) keys.push_back(key);
  return keys;
}

std::uint64_t new_run_id() {
  std::random_device device;
  return (static_cast<std::uint64_t>(device()) << 32) ^ device();
}

std::string hex16(std::uint64_t v) {
  char s[17];
  std::snprintf(s, sizeof s, "%016llx", static_cast<unsigned long long>(v));
  return s;
}

// A run id as the header writes it (16 hexadecimal digits), or nothing.
std::optional<std::uint64_t> parse_hex16(const json& j) {
  if (!j.is_string() || j.get<std::string>().size() != 16) return std::nullopt;
  std::uint64_t v = 0;
  for (const char c : j.get<std::string>()) {
    const int d = c >= '0' && c <= '9' ? c - '0' : c >= 'a' && c <= 'f' ? c - 'a' + 10 : -1;
    if (d < 0) return std::nullopt;
    v = v << 4 | static_cast<std::uint64_t>(d);
  }
  return v;
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
      n_(n),
      order_(task_order(spec, n)),
      run_id_(new_run_id()) {
  std::vector<std::uint64_t> order(order_.begin(), order_.end());
  identity_ = std::make_shared<const json>(json{{"format", kFormat},       {"experiment", ctx.experiment},
               {"study", ctx.study},      {"name", name_},
               {"scene", scene_slice(ctx.scene, spec.keys.empty() ? task_keys(ctx.reads) : spec.keys)}, {"build", build_info()},
               {"kernel", spec.kernel}, {"n", n}, {"order_crc32c", crc32c(order.data(), order.size() * sizeof(std::uint64_t))}});
  chain_ = seed();
}

namespace {
// The check of record k: the CRC-32C of its task index, count and values, seeded by the check of record k - 1
// (for record 0, by the run's seed): a record checks only in its own place of its own run's log.
std::uint32_t record_check(std::uint64_t k, const char* count_and_values, std::size_t size, std::uint32_t previous) {
  return crc32c(count_and_values, size, crc32c(&k, sizeof k, previous));
}
}  // namespace

std::uint32_t CheckpointLog::seed() const {
  const std::string id = identity_->dump();
  return crc32c(&run_id_, sizeof run_id_, crc32c(id.data(), id.size()));
}

void CheckpointLog::refuse(const fs::path& file, const std::string& why) const {
  throw SceneError("checkpoint " + file.string() + ": " + why + "; delete " +
                   (file.parent_path() / (name_ + ".checkpoint.*")).string() + " to start " + name_ +
                   " over, or run without --resume");
}

void CheckpointLog::reset() {
  for (const fs::path& f : {header_, log_})  // (the header first, as remove_checkpoints)
    if (fs::remove(f)) fault_point("remove", f);
  tasks_done_ = 0, log_bytes_ = 0, run_id_ = new_run_id(), chain_ = seed();
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

namespace {
// A path that must be a regular file (following symbolic links), or nothing there: "" if so, else what it is.
std::string not_a_file(const fs::path& p) {
  std::error_code ec;
  const fs::file_status st = fs::status(p, ec);
  if (ec && ec != std::errc::no_such_file_or_directory) return "cannot be examined (" + ec.message() + ")";
  if (!fs::exists(st) || fs::is_regular_file(st)) return "";
  return fs::is_directory(st) ? "is a directory, not a file" : "is not a regular file";
}
}  // namespace

CheckpointLog::Records CheckpointLog::load_here(bool resume) {
  Records records;
  if (const std::string what = not_a_file(header_); !what.empty()) refuse(header_, what);
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
  if (!h.contains("format")) refuse(header_, "no field format");
  if (h["format"] != (*identity_)["format"])
    refuse(header_, "format is " + shown(h["format"]) + ", this binary reads format " + std::to_string(kFormat));
  for (const char* field : {"experiment", "study", "name", "scene", "build", "kernel", "n", "order_crc32c", "run_id",
                            "tasks_done", "log_bytes", "chain_crc32c"})
    if (!h.contains(field)) refuse(header_, std::string("no field ") + field);
  for (const char* field : {"experiment", "study", "name"})
    if (h[field] != (*identity_)[field])
      refuse(header_, std::string(field) + " is " + shown(h[field]) + ", not " + shown((*identity_)[field]));
  for (const auto& [key, value] : (*identity_)["build"].items())
    if (!h["build"].is_object() || !h["build"].contains(key) || h["build"][key] != value)
      refuse(header_, "written by another binary: build." + key + " is " +
                          (h["build"].is_object() && h["build"].contains(key) ? shown(h["build"][key]) : "missing") +
                          ", this binary's " + shown(value));
  if (h["scene"] != (*identity_)["scene"] || h["kernel"] != (*identity_)["kernel"] ||
      h["order_crc32c"] != (*identity_)["order_crc32c"]) {  // nothing of it applies
    reset();
    return records;
  }
  if (h["n"] != (*identity_)["n"]) refuse(header_, "n is " + shown(h["n"]) + ", not the " + std::to_string(n_) + " tasks of " + name_);
  if (!h["tasks_done"].is_number_unsigned() || h["tasks_done"].get<std::uint64_t>() > n_)
    refuse(header_, "tasks_done is " + shown(h["tasks_done"]) + ": it must be an integer in [0, " + std::to_string(n_) +
                        "], the tasks of " + name_);
  if (!h["log_bytes"].is_number_unsigned())
    refuse(header_, "log_bytes is " + shown(h["log_bytes"]) + ": it must be a byte count");
  const auto run_id = parse_hex16(h["run_id"]);
  if (!run_id) refuse(header_, "run_id is " + shown(h["run_id"]) + ": it must be 16 hexadecimal digits");
  if (!h["chain_crc32c"].is_number_unsigned() || h["chain_crc32c"].get<std::uint64_t>() > 0xFFFFFFFFu)
    refuse(header_, "chain_crc32c is " + shown(h["chain_crc32c"]) + ": it must be a CRC-32C (an integer below 2^32)");
  const auto done = static_cast<std::size_t>(h["tasks_done"].get<std::uint64_t>());
  const auto bytes = h["log_bytes"].get<std::uint64_t>();
  if (bytes < kPreamble)
    refuse(header_, "log_bytes is " + std::to_string(bytes) + ": fewer than the log's preamble of " +
                        std::to_string(kPreamble) + " bytes");
  if (const std::string what = not_a_file(log_); !what.empty()) refuse(log_, what);
  std::error_code ec;
  const auto size = fs::exists(log_) ? fs::file_size(log_, ec) : 0;
  if (ec || size < bytes)  // (checked before anything is read: no size field is trusted beyond the file)
    refuse(log_, "holds " + std::to_string(ec ? 0 : size) + " bytes, fewer than the " + std::to_string(bytes) +
                     " (log_bytes) of the " + std::to_string(done) + " tasks " + header_.filename().string() + " counts");
  std::ifstream in(log_, std::ios::binary);
  char preamble[kPreamble];
  if (!in.read(preamble, kPreamble)) refuse(log_, "cannot be read");
  if (std::memcmp(preamble, kMagic, sizeof kMagic) != 0)
    refuse(log_, "does not begin as a checkpoint log of format " + std::to_string(kFormat) + " does");
  std::uint64_t log_run = 0;
  std::memcpy(&log_run, preamble + sizeof kMagic, 8);
  if (log_run != *run_id)
    refuse(log_, "is the log of another run (run id " + hex16(log_run) + "), not of the run " +
                     header_.filename().string() + " counts (run_id " + hex16(*run_id) + ")");
  run_id_ = *run_id;
  // The records, read one at a time: each count checked against the bytes left before its values are read,
  // each check against the chain (record_check): a record changed, swapped, dropped, duplicated or taken from
  // another run fails in its place.
  std::uint32_t chain = seed();
  std::uint64_t at = kPreamble;
  std::vector<char> record;
  for (std::size_t k = 0; k < done; ++k) {
    std::uint64_t length = 0;
    if (bytes - at < 16 || !in.read(reinterpret_cast<char*>(&length), 8) || length > (bytes - at - 16) / 8)
      refuse(header_, "log_bytes is " + std::to_string(bytes) + ": the log's first " + std::to_string(bytes) +
                          " bytes end within record " + std::to_string(k) + " of the " + std::to_string(done) +
                          " records (tasks_done)");
    record.resize(8 + length * 8);
    std::memcpy(record.data(), &length, 8);
    std::uint64_t stored = 0;
    if (!in.read(record.data() + 8, static_cast<std::streamsize>(length * 8)) || !in.read(reinterpret_cast<char*>(&stored), 8))
      refuse(log_, "cannot be read");
    chain = record_check(k, record.data(), record.size(), chain);
    if (stored != chain)
      refuse(log_, "record " + std::to_string(k) + " (task " + std::to_string(k) + ") does not match its checksum: the log "
                   "is damaged, or the record is not task " + std::to_string(k) + " of this run (moved, dropped, "
                   "repeated or taken from another log)");
    const std::size_t first = records.values.size();
    records.values.resize(first + length);
    std::memcpy(records.values.data() + first, record.data() + 8, length * 8), at += 16 + length * 8;
    for (std::size_t i = first; i < records.values.size(); ++i)
      if (!std::isfinite(records.values[i]))
        refuse(log_, "value " + std::to_string(i - first) + " of task " + std::to_string(k) + " is not finite");
    records.offsets.push_back(records.values.size());
  }
  if (at != bytes)
    refuse(header_, "log_bytes is " + std::to_string(bytes) + ", but its " + std::to_string(done) +
                        " records (tasks_done) take " + std::to_string(at));
  if (chain != h["chain_crc32c"].get<std::uint64_t>())
    refuse(log_, "its " + std::to_string(done) + " records do not end with chain_crc32c of " + header_.filename().string() +
                     ": the log is not the one the header counts");
  if (size > bytes) fs::resize_file(log_, bytes), fault_point("cut", log_);  // a round appended but not counted
  tasks_done_ = done, log_bytes_ = bytes, chain_ = chain;
  return records;
}

namespace {
double g_write_seconds = 0;
}  // namespace

double checkpoint_write_seconds() { return g_write_seconds; }

std::vector<std::size_t> task_order(const CheckpointSpec& spec, std::size_t n) {
  std::vector<std::size_t> order(n);
  std::iota(order.begin(), order.end(), std::size_t{0});
  if (spec.work.empty()) return order;
  if (spec.work.size() != n)
    throw std::logic_error("checkpoint " + spec.name + ": work for " + std::to_string(spec.work.size()) + " tasks, not " +
                           std::to_string(n));
  if (!std::ranges::all_of(spec.work, [](double w) { return std::isfinite(w); }))  // (NaN would leave no order)
    throw std::logic_error("checkpoint " + spec.name + ": the work of a task is not finite");
  std::ranges::stable_sort(order, std::ranges::greater{}, [&](std::size_t i) { return spec.work[i]; });
  return order;
}

void CheckpointLog::append(std::span<const double> values, std::span<const std::size_t> lengths) {
  if (!mpi::is_root()) {  // rank 0 alone writes; the others keep count
    tasks_done_ += lengths.size();
    return;
  }
  const auto t0 = std::chrono::steady_clock::now();
  const bool begins = log_bytes_ == 0;  // (a new log: its preamble first, over anything left there)
  std::vector<char> raw((begins ? kPreamble : 0) + lengths.size() * 16 + values.size() * 8);
  std::size_t at = 0, v = 0;
  if (begins) std::memcpy(raw.data(), kMagic, sizeof kMagic), std::memcpy(raw.data() + 8, &run_id_, 8), at = kPreamble;
  std::uint32_t chain = chain_;
  std::uint64_t k = tasks_done_;
  for (const std::size_t length : lengths) {
    const auto l = static_cast<std::uint64_t>(length);
    const std::size_t record = at;
    std::memcpy(raw.data() + at, &l, 8), at += 8;
    std::memcpy(raw.data() + at, values.data() + v, length * 8), at += length * 8, v += length;
    chain = record_check(k++, raw.data() + record, at - record, chain);
    const std::uint64_t check = chain;
    std::memcpy(raw.data() + at, &check, 8), at += 8;
  }
  const int fd = ::open(log_.c_str(), O_WRONLY | O_CREAT | O_APPEND | O_CLOEXEC | (begins ? O_TRUNC : 0), 0644);
  if (fd < 0) throw OutputError("cannot write " + log_.string() + ": " + std::strerror(errno));
  write_all(fd, raw.data(), raw.size(), log_);
  if (::fsync(fd) != 0 || ::close(fd) != 0) throw OutputError("cannot write " + log_.string() + ": " + std::strerror(errno));
  fault_point("append", log_, raw.size());
  tasks_done_ += lengths.size(), log_bytes_ += raw.size(), chain_ = chain;
  json h = *identity_;
  h["run_id"] = hex16(run_id_), h["tasks_done"] = tasks_done_, h["log_bytes"] = log_bytes_, h["chain_crc32c"] = chain_;
  write_file_atomic(header_, h.dump(1) + "\n");
  g_write_seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

void remove_checkpoints(const fs::path& dir) {
  // Every header before any log: a run killed in between leaves logs without a header (nothing to
  // resume, start over), never a header that counts bytes of a log already gone (refused, exit 2).
  for (const char* suffix : {kHeaderSuffix, kLogSuffix})
    for (const auto& e : fs::directory_iterator(dir))
      if (e.path().filename().string().ends_with(suffix)) fs::remove(e.path()), fault_point("remove", e.path());
}

}  // namespace geomint
