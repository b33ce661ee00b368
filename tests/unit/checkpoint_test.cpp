// runner/checkpoint.hpp: checkpointed_map keeps its finished tasks, resumes from them with the same
// results, and refuses (SceneError naming the file) a checkpoint it cannot use; runner/distributed_map.hpp:
// the records sent between the ranks come back with the same bits.
#include <gtest/gtest.h>
#include <unistd.h>

#include <array>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <limits>
#include <optional>
#include <span>
#include <sstream>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "../hard_case.hpp"
#include "geomint/io/crc32c.hpp"
#include "geomint/runner/checkpoint.hpp"
#include "temp_paths.hpp"

using namespace geomint;
namespace fs = std::filesystem;

namespace checkpoint_test {  // the file's scope (the tests build as one translation unit)

namespace {

// Task i: i % 5 + 1 values (records of different lengths).
std::vector<double> task(std::size_t i) {
  std::vector<double> v;
  for (std::size_t k = 0; k <= i % 5; ++k) v.push_back(std::sin(static_cast<double>(i) + 0.1 * static_cast<double>(k)));
  return v;
}
constexpr std::size_t kTasks = 37;

std::string read(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

// A staging directory, a scene (a = 1, checkpoint.stop_after, checkpoint.interval if >= 0) and a Context on them.
struct Fixture {
  fs::path dir = test::temp_path("geomint_checkpoint_test");
  Scene scene;
  OutputDir out;
  Context ctx;
  std::atomic<int> calls{0};

  explicit Fixture(int stop_after = 0, double a = 1.0, bool fresh = true, double interval = -1)
      : scene(load(stop_after, a, interval)), out(prepare(fresh)), ctx(scene, out, 2) {
    ctx.experiment = "unit", ctx.study = "tasks", ctx.resume = !fresh, ctx.resume_command = "unit --resume";
  }
  static Scene load(int stop_after, double a, double interval) {
    const fs::path file = test::temp_path("geomint_checkpoint_scene", ".toml");
    std::ofstream(file) << "a = " << a << "\n[checkpoint]\nstop_after = " << stop_after << "\n"
                        << (interval >= 0 ? "interval = " + std::to_string(interval) + "\n" : "");
    Schema schema;
    schema.real("a", any_finite()).integer("checkpoint.stop_after", non_negative());
    if (interval >= 0) schema.real("checkpoint.interval", non_negative());
    return Scene::load(file, {}, schema);
  }
  fs::path prepare(bool fresh) const {
    if (fresh) fs::remove_all(dir);
    return dir;
  }
  std::array<std::atomic<bool>, kTasks> called{};  // the tasks computed
  std::vector<std::vector<double>> run(std::size_t round = 5, std::vector<double> work = {}, std::string kernel = {}) {
    const CheckpointSpec spec{"", {"a"}, round, std::move(work), std::move(kernel)};
    return checkpointed_map<std::vector<double>>(ctx, spec, kTasks, [&](std::size_t i) {
      ++calls;
      called[i] = true;
      return task(i);
    });
  }
  fs::path header() const { return dir / "tasks.checkpoint.json"; }
  fs::path log() const { return dir / "tasks.checkpoint.log"; }
};

std::vector<std::vector<double>> straight() {
  std::vector<std::vector<double>> v;
  for (std::size_t i = 0; i < kTasks; ++i) v.push_back(task(i));
  return v;
}

// A run stopped after one round of 5 tasks (checkpoint.stop_after = 1).
void stop_after_one_round() {
  Fixture f(1);
  EXPECT_THROW(f.run(), Interrupted);
  EXPECT_EQ(f.calls, 5);
}

// A resumed run's refusal: a SceneError whose message names `file` and `needle`.
void expect_refused(const fs::path& file, const std::string& needle) {
  Fixture f(0, 1.0, false);
  std::optional<std::string> what = geomint::test::refusal_of<SceneError>([&] { f.run(); });
  if (what) {  // (the file named relative to the checkpoint's directory, as the report shows it)
    EXPECT_NE(what->find(file.string()), std::string::npos) << *what;
    EXPECT_EQ(what->find('\n'), std::string::npos) << *what;
    what->replace(what->find(file.parent_path().string()), file.parent_path().string().size(), "DIR");
  }
  EXPECT_TRUE(geomint::test::refusal_case("resume from a damaged " + file.filename().string(), what,
                                          {file.filename().string(), needle}));
}

nlohmann::ordered_json header_json(const fs::path& p) { return nlohmann::ordered_json::parse(read(p)); }

void write_header(const fs::path& p, const nlohmann::ordered_json& h) { std::ofstream(p) << h.dump(1); }

}  // namespace

TEST(Checkpoint, RoundTripHoldsEachTaskOnce) {
  Fixture f;
  EXPECT_EQ(f.run(), straight());
  EXPECT_EQ(f.calls, static_cast<int>(kTasks));
  const auto h = header_json(f.header());  // the finished map is kept until the run commits
  EXPECT_EQ(h["tasks_done"], kTasks);
  EXPECT_EQ(h["n"], kTasks);
  EXPECT_EQ(h["experiment"], "unit");
  EXPECT_EQ(h["study"], "tasks");
  EXPECT_EQ(h["scene"]["a"], 1.0);
  EXPECT_TRUE(h["build"].contains("git_commit"));
  std::size_t bytes = 16;                                          // the preamble, then per task
  for (const auto& r : straight()) bytes += 8 + 8 * r.size() + 8;  // a count, the values and a checksum, once
  EXPECT_EQ(h["log_bytes"], bytes);
  EXPECT_EQ(fs::file_size(f.log()), bytes);
  // Read back whole: no task computed again.
  Fixture again(0, 1.0, false);
  EXPECT_EQ(again.run(), straight());
  EXPECT_EQ(again.calls, 0);
  remove_checkpoints(f.dir);
  EXPECT_FALSE(fs::exists(f.header()));
  EXPECT_FALSE(fs::exists(f.log()));
}

TEST(Checkpoint, ResumeAfterAStopGivesTheSameResults) {
  stop_after_one_round();
  Fixture f(0, 1.0, true);  // (a fresh run: the stopped run's checkpoint is not read)
  EXPECT_EQ(f.run(), straight());
  EXPECT_EQ(f.calls, static_cast<int>(kTasks));
  stop_after_one_round();
  EXPECT_EQ(header_json(Fixture(0, 1.0, false).header())["tasks_done"], 5u);
  Fixture resumed(0, 1.0, false);
  EXPECT_EQ(resumed.run(7), straight());  // (another round size: the tasks are stored by index)
  EXPECT_EQ(resumed.calls, static_cast<int>(kTasks) - 5);
}

TEST(Checkpoint, WorkRunsTheLongestTasksFirstAndTheResultsStayByIndex) {
  std::vector<double> work(kTasks);  // task i's work: i % 5 (the largest, 4, for tasks 4, 9, 14, ...)
  for (std::size_t i = 0; i < kTasks; ++i) work[i] = static_cast<double>(i % 5);
  const auto stop = [&] {  // one round of 5: the first five of work 4, in index order
    Fixture stopped(1);
    EXPECT_THROW(stopped.run(5, work), Interrupted);
    for (std::size_t i = 0; i < kTasks; ++i) EXPECT_EQ(stopped.called[i].load(), i % 5 == 4 && i < 25) << i;
  };
  stop();
  Fixture in_index_order(0, 1.0, false);  // another order: the checkpoint does not apply, the map starts over
  EXPECT_EQ(in_index_order.run(5), straight());
  EXPECT_EQ(in_index_order.calls, static_cast<int>(kTasks));
  stop();
  Fixture resumed(0, 1.0, false);
  EXPECT_EQ(resumed.run(5, work), straight());
  EXPECT_EQ(resumed.calls, static_cast<int>(kTasks) - 5);
  EXPECT_EQ(task_order({"", {}, 0, {1, 3, 3, 2}}, 4), (std::vector<std::size_t>{1, 2, 3, 0}));
  EXPECT_EQ(task_order({}, 3), (std::vector<std::size_t>{0, 1, 2}));
  EXPECT_THROW(task_order({"", {}, 0, {1, 2}}, 3), std::logic_error);
  EXPECT_THROW(task_order({"", {}, 0, {1, std::nan(""), 2}}, 3), std::logic_error);
}

TEST(Checkpoint, StopNamesWhereAndTheResumeCommand) {
  Fixture f(2);
  try {
    f.run();
    ADD_FAILURE() << "not stopped";
  } catch (const Interrupted& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("10 of 37 tasks"), std::string::npos) << what;
    EXPECT_NE(what.find("checkpoint.stop_after = 2"), std::string::npos) << what;
    EXPECT_NE(what.find("unit --resume"), std::string::npos) << what;
  }
}

TEST(Checkpoint, OtherSceneValuesStartOver) {
  stop_after_one_round();
  Fixture f(0, 2.0, false);
  EXPECT_EQ(f.run(), straight());
  EXPECT_EQ(f.calls, static_cast<int>(kTasks));
}

TEST(Checkpoint, AnotherKernelStartsOver) {  // (the energy map's kernels each round in their own way)
  stop_after_one_round();
  Fixture f(0, 1.0, false);
  EXPECT_EQ(f.run(5, {}, "avx2"), straight());
  EXPECT_EQ(f.calls, static_cast<int>(kTasks));
}

TEST(Checkpoint, MissingHeaderStartsOver) {
  stop_after_one_round();
  fs::remove(Fixture(0, 1.0, false).header());
  Fixture f(0, 1.0, false);
  EXPECT_EQ(f.run(), straight());
  EXPECT_EQ(f.calls, static_cast<int>(kTasks));
}

// The runner removes the checkpoints of a finished run before it commits; a kill in the middle must
// not leave a header counting the bytes of a log already removed (a --resume would refuse it).
// Here every log fails to be removed (a directory that is not empty): all headers must be gone first.
TEST(Checkpoint, RemovalTakesEveryHeaderBeforeAnyLog) {
  const fs::path dir = test::temp_path("geomint_checkpoint_removal");
  fs::remove_all(dir);
  for (int k = 0; k < 16; ++k) {  // 16 pairs: in any directory order, some header would follow a log
    const std::string stem = "study" + std::to_string(k);
    fs::create_directories(dir / (stem + ".checkpoint.log") / "x");
    std::ofstream(dir / (stem + ".checkpoint.json")) << "{}";
  }
  EXPECT_THROW(remove_checkpoints(dir), fs::filesystem_error);
  for (const auto& e : fs::directory_iterator(dir))
    EXPECT_FALSE(e.path().filename().string().ends_with(".checkpoint.json")) << e.path();
  fs::remove_all(dir);
}

TEST(Checkpoint, LogLongerThanCountedIsCutBack) {  // a run stopped in the middle of an append
  stop_after_one_round();
  const fs::path log = Fixture(0, 1.0, false).log();
  std::ofstream(log, std::ios::app) << "partial record";
  Fixture f(0, 1.0, false);
  EXPECT_EQ(f.run(), straight());
  EXPECT_EQ(f.calls, static_cast<int>(kTasks) - 5);
}

TEST(Checkpoint, ResumeRefusesACorruptHeader) {
  stop_after_one_round();
  const fs::path header = Fixture(0, 1.0, false).header();
  std::ofstream(header) << "{\"format\": ";
  expect_refused(header, "not JSON");
}

TEST(Checkpoint, ResumeRefusesATruncatedLog) {
  stop_after_one_round();
  const fs::path log = Fixture(0, 1.0, false).log();
  fs::resize_file(log, fs::file_size(log) - 3);
  expect_refused(log, "log_bytes");
}

TEST(Checkpoint, ResumeRefusesTamperedHeaders) {
  const auto tampered = [](const std::string& field, const nlohmann::ordered_json& value, const std::string& needle) {
    stop_after_one_round();
    const fs::path header = Fixture(0, 1.0, false).header();
    auto h = header_json(header);
    nlohmann::ordered_json::json_pointer at("/" + field);
    h[at] = value;
    write_header(header, h);
    expect_refused(header, needle);
  };
  tampered("format", 99, "format");
  tampered("build/git_commit", "0000000", "build.git_commit");
  tampered("build/cxx_flags", "-O0", "build.cxx_flags");
  tampered("n", 36, "n is 36");
  tampered("tasks_done", -1, "tasks_done");
  tampered("log_bytes", 8, "log_bytes");   // fewer bytes than the records counted
  tampered("tasks_done", 3, "log_bytes");  // fewer records than the bytes counted
  tampered("study", "other", "study");
  tampered("run_id", "not-hex", "run_id");
  tampered("chain_crc32c", -1, "chain_crc32c");
  // a header that counts another run or other records: the log does not match it (the log named)
  for (const auto& [field, value, needle] : {std::tuple<const char*, nlohmann::ordered_json, const char*>{
                                                 "run_id", "0123456789abcdef", "another run"},
                                             {"chain_crc32c", 12345, "do not end with chain_crc32c"}}) {
    stop_after_one_round();
    const Fixture f(0, 1.0, false);
    auto h = header_json(f.header());
    h[field] = value;
    write_header(f.header(), h);
    expect_refused(f.log(), needle);
  }
}

TEST(Checkpoint, ResumeRefusesACheckpointBeyondTheTasks) {
  stop_after_one_round();
  const fs::path header = Fixture(0, 1.0, false).header();
  auto h = header_json(header);
  h["tasks_done"] = 1000000;
  write_header(header, h);
  expect_refused(header, "tasks_done");
}

// The log: a preamble of 16 bytes; record 0 (task 0: one value) its count, value and checksum (24 bytes);
// record 1 (two values, 32 bytes) from byte 40, its first value at byte 48.
constexpr std::size_t kRecord1 = 16 + 24, kRecord1Value = kRecord1 + 8, kRecord2 = kRecord1 + 32;

// The checks of the records of a log from record `from` on made again as the writer makes them (the CRC-32C
// of the task index, the count and the values, seeded by the check before): a forger's log; the last check.
std::uint32_t rechain(std::string& bytes, std::size_t from) {
  std::size_t at = 16;
  std::uint32_t chain = 0;
  for (std::uint64_t k = 0; at < bytes.size(); ++k) {
    std::uint64_t length = 0, check = 0;
    std::memcpy(&length, bytes.data() + at, 8);
    const std::size_t end = at + 8 + 8 * length;
    if (k >= from) {
      check = crc32c(bytes.data() + at, end - at, crc32c(&k, 8, chain));
      std::memcpy(bytes.data() + end, &check, 8);
    }
    std::memcpy(&check, bytes.data() + end, 8);
    chain = static_cast<std::uint32_t>(check), at = end + 8;
  }
  return chain;
}

void rewrite(const fs::path& p, const std::string& bytes) { std::ofstream(p, std::ios::binary | std::ios::trunc) << bytes; }

// The damage a log meets (a flipped bit, values zeroed with their counts kept, another run's log under the
// header) is refused, naming the log and the record or the run.
TEST(Checkpoint, ResumeRefusesADamagedLog) {
  const auto damaged = [](const std::function<void(std::string&)>& damage, const std::string& needle) {
    stop_after_one_round();
    const fs::path log = Fixture(0, 1.0, false).log();
    std::string bytes = read(log);
    damage(bytes);
    rewrite(log, bytes);
    expect_refused(log, needle);
  };
  damaged([](std::string& b) { b[kRecord1Value + 2] ^= 0x01; }, "record 1 (task 1) does not match its checksum");
  damaged([](std::string& b) { b[kRecord1Value + 7] ^= 0x40; }, "record 1 (task 1) does not match its checksum");  // an exponent bit
  damaged([](std::string& b) { std::memset(b.data() + kRecord1Value, 0, 16); }, "record 1 (task 1) does not match");
  damaged([](std::string& b) { b[kRecord1 - 1] ^= 0x01; }, "record 0 (task 0) does not match");  // its checksum
  damaged([](std::string& b) { b[8] ^= 0x01; }, "the log of another run");
  damaged([](std::string& b) { b[0] = 'G'; }, "does not begin as a checkpoint log");

  // another run's log (the same tasks, stopped the same way) under this run's header
  stop_after_one_round();
  const std::string other = read(Fixture(0, 1.0, false).log());
  stop_after_one_round();
  const fs::path log = Fixture(0, 1.0, false).log();
  ASSERT_NE(read(log), other);  // (the same records, another run id)
  rewrite(log, other);
  expect_refused(log, "the log of another run");
}

// A log forged with valid checksums still holds only finite values.
TEST(Checkpoint, ResumeRefusesAValueThatIsNotFinite) {
  stop_after_one_round();
  const Fixture f(0, 1.0, false);
  std::string bytes = read(f.log());
  const double nan = std::numeric_limits<double>::quiet_NaN();
  std::memcpy(bytes.data() + kRecord1Value, &nan, 8);  // task 1's first value, the checks and the header's made again
  const std::uint32_t chain = rechain(bytes, 1);
  rewrite(f.log(), bytes);
  auto h = header_json(f.header());
  h["chain_crc32c"] = chain;
  write_header(f.header(), h);
  expect_refused(f.log(), "task 1 is not finite");
}

// A record is checked in its place of its own run's log: two records swapped, one dropped (the header counting
// one fewer), one repeated in another's place, or a record of the same task from a run of other scene values is
// refused, naming the record; with each record's own CRC alone (format 2) these passed.
TEST(Checkpoint, ResumeRefusesRecordsOutOfTheirPlace) {
  const auto moved = [](const std::function<void(std::string&, nlohmann::ordered_json&)>& move, const std::string& needle) {
    stop_after_one_round();
    const Fixture f(0, 1.0, false);
    std::string bytes = read(f.log());
    auto h = header_json(f.header());
    move(bytes, h);
    rewrite(f.log(), bytes);
    write_header(f.header(), h);
    expect_refused(f.log(), needle);
  };
  moved([](std::string& b, auto&) {  // records 0 and 1 swapped
    b = b.substr(0, 16) + b.substr(kRecord1, 32) + b.substr(16, 24) + b.substr(kRecord2);
  }, "record 0 (task 0) does not match its checksum");
  moved([](std::string& b, auto& h) {  // record 1 dropped, the header counting what is left
    b = b.substr(0, kRecord1) + b.substr(kRecord2);
    h["tasks_done"] = h["tasks_done"].template get<int>() - 1, h["log_bytes"] = b.size();
  }, "record 1 (task 1) does not match");
  moved([](std::string& b, auto&) { b.replace(kRecord1, 24, b.substr(16, 24)); },  // record 0 repeated as record 1
        "record 1 (task 1) does not match its checksum");
  // the same task's record from a run of other scene values (a = 2: its values are the same, its place is not)
  stop_after_one_round();
  const std::string other_record = [] {
    Fixture g(1, 2.0);
    EXPECT_THROW(g.run(), Interrupted);
    return read(g.log()).substr(16, 24);
  }();
  stop_after_one_round();
  const Fixture f(0, 1.0, false);
  std::string bytes = read(f.log());
  ASSERT_EQ(bytes.substr(16, 16), other_record.substr(0, 16));  // (the same count and value)
  bytes.replace(16, 24, other_record);
  rewrite(f.log(), bytes);
  expect_refused(f.log(), "record 0 (task 0) does not match its checksum");
}

// A header that counts an absurd log (13 GiB, and a sparse log that long) is refused without reading or
// allocating it: the records are read one at a time, and the bytes beyond them are not records.
TEST(Checkpoint, ResumeRefusesAnAbsurdLogWithoutAllocatingIt) {
  stop_after_one_round();
  const Fixture f(0, 1.0, false);
  const std::uintmax_t absurd = std::uintmax_t{13} << 30;
  fs::resize_file(f.log(), absurd);
  auto h = header_json(f.header());
  h["log_bytes"] = absurd;
  write_header(f.header(), h);
  expect_refused(f.header(), "records (tasks_done) take");
  fs::remove(f.log());
}

// A header or a log that is not a regular file (a directory, a symbolic link that loops) is refused, exit 2.
TEST(Checkpoint, ResumeRefusesAHeaderThatIsNotAFile) {
  stop_after_one_round();
  const Fixture f(0, 1.0, false);
  fs::remove(f.header());
  fs::create_directory(f.header());
  expect_refused(f.header(), "is a directory");
  fs::remove(f.header());
  fs::create_symlink(f.header().filename(), f.header());  // (a link to itself)
  expect_refused(f.header(), "cannot be examined");
  fs::remove(f.header());
}

// A task whose record is not finite is not saved (nor any after it): resumed, it is computed again.
TEST(Checkpoint, RecordsThatAreNotFiniteAreNotSaved) {
  Fixture f(1);
  const auto bad = [&](std::size_t i) {
    ++f.calls;
    return i == 3 ? std::numeric_limits<double>::infinity() : static_cast<double>(i);
  };
  EXPECT_THROW(checkpointed_map<double>(f.ctx, {"", {"a"}, 5}, kTasks, bad), Interrupted);
  EXPECT_EQ(header_json(f.header())["tasks_done"], 3u);
  Fixture resumed(0, 1.0, false);
  const auto out = checkpointed_map<double>(resumed.ctx, {"", {"a"}, 5}, kTasks, bad);
  EXPECT_TRUE(std::isinf(out[3]));
  EXPECT_EQ(out[36], 36.0);
}

// checkpoint.interval = 0 saves after every round: a run that dies in its third round of 5 (a SIGKILL, here
// an exception from a task) keeps the first two on disk. With the default interval (10 s) a short run saves
// nothing before its end.
TEST(Checkpoint, IntervalZeroSavesEveryRound) {
  const auto dies_in_round_three = [](Fixture& f) {
    EXPECT_THROW(checkpointed_map<std::vector<double>>(f.ctx, {"", {"a"}, 5}, kTasks,
                                                       [](std::size_t i) {
                                                         if (i == 12) throw std::runtime_error("killed");
                                                         return task(i);
                                                       }),
                 std::runtime_error);
  };
  {
    Fixture f(0, 1.0, true, 0.0);
    dies_in_round_three(f);
    EXPECT_EQ(header_json(f.header())["tasks_done"], 10u);
    Fixture resumed(0, 1.0, false, 0.0);
    EXPECT_EQ(resumed.run(), straight());
    EXPECT_EQ(resumed.calls, static_cast<int>(kTasks) - 10);
  }
  Fixture g(0, 1.0, true);
  dies_in_round_three(g);
  EXPECT_FALSE(fs::exists(g.header()));
}

// The progress line: the count, and while not done the rate since the loop's start (tasks restored from a
// checkpoint not counted), the time elapsed and the time left at that rate; done, the count alone.
TEST(Progress, LineGivesTheRateTheElapsedTimeAndTheTimeLeft) {
  EXPECT_EQ(progress_line("map", 30, 100, "tasks", 10, 40), "  map: 30 / 100 tasks, 0.5 tasks/s, 40 s elapsed, 2 min 20 s left");
  EXPECT_EQ(progress_line("map", 0, 100, "tasks", 0, 0), "  map: 0 / 100 tasks");
  EXPECT_EQ(progress_line("map", 100, 100, "tasks", 0, 200), "  map: 100 / 100 tasks");
  EXPECT_EQ(progress_line("lj", 2, 400, "tasks", 0, 7300), "  lj: 2 / 400 tasks, 0.000274 tasks/s, 2 h 01 min elapsed, 403 h 31 min left");
}

// ---- the records distributed_map sends between the ranks -------------------------------------------
struct CodecInner {
  double x = 0;
  std::int64_t n = 0;
  auto fields() { return std::tie(x, n); }
};
struct CodecOuter {
  std::vector<CodecInner> runs;
  std::array<double, 2> pair{};
  std::vector<double> values;
  double last = 0;
  auto fields() { return std::tie(runs, pair, values, last); }
};

TEST(RecordCodec, FieldsRoundTripExactly) {
  const CodecOuter r{{{0.1, 3}, {-1e-300, -(std::int64_t{1} << 53)}}, {1.0 / 3.0, -0.0}, {}, std::nextafter(1.0, 2.0)};
  std::vector<double> v;
  RecordCodec<CodecOuter>{}.encode(r, v);
  // runs: length, then (x, n) per run; pair; values: length; last
  EXPECT_EQ(v, (std::vector<double>{2, 0.1, 3, -1e-300, -9007199254740992.0, 1.0 / 3.0, -0.0, 0, std::nextafter(1.0, 2.0)}));
  const CodecOuter back = RecordCodec<CodecOuter>{}.decode(v);
  std::vector<double> again;
  RecordCodec<CodecOuter>{}.encode(back, again);
  EXPECT_EQ(std::memcmp(v.data(), again.data(), v.size() * sizeof(double)), 0);  // the same bits (-0.0 too)
  EXPECT_EQ(back.runs[1].n, -(std::int64_t{1} << 53));
}

TEST(RecordCodec, VectorsOfArraysAndPairs) {
  const std::vector<std::array<double, 4>> path{{1, 2, 3, 4}, {5, 6, 7, 8}};
  std::vector<double> v;
  const RecordCodec<std::vector<std::array<double, 4>>> paths;
  paths.encode(path, v);
  EXPECT_EQ(v, (std::vector<double>{2, 1, 2, 3, 4, 5, 6, 7, 8}));
  EXPECT_EQ(paths.decode(v), path);
  const std::pair<double, std::int64_t> scan{0.25, -1};
  const RecordCodec<std::pair<double, std::int64_t>> scans;
  std::vector<double> w;
  scans.encode(scan, w);
  EXPECT_EQ(scans.decode(w), scan);
}

TEST(RecordCodec, RefusesRecordsOfTheWrongLength) {
  std::vector<double> v;
  RecordCodec<CodecOuter>{}.encode(CodecOuter{{{1, 2}}, {3, 4}, {5}, 6}, v);
  const RecordCodec<CodecOuter> codec;
  EXPECT_REFUSAL_OF(std::invalid_argument, "a record one value short",
                    codec.decode(std::span<const double>(v.data(), v.size() - 1)), {"record"});
  v.push_back(7);
  EXPECT_REFUSAL_OF(std::invalid_argument, "a record one value long", codec.decode(v), {"record"});
  v.pop_back(), v[0] = 1e6;  // a vector longer than the record
  EXPECT_REFUSAL_OF(std::invalid_argument, "a vector length beyond the record", codec.decode(v), {"record"});
  std::vector<double> w;
  EXPECT_REFUSAL_OF(std::out_of_range, "an integer of 2^53 + 2, not exact in a double",
                    RecordCodec<CodecInner>{}.encode(CodecInner{0, (std::int64_t{1} << 53) + 2}, w), {"2^53"});
}

TEST(DistributedMap, OneProcessIsTheParallelMap) {
  const auto out = distributed_map(5, [](std::size_t i) { return CodecInner{0.5 * static_cast<double>(i), static_cast<std::int64_t>(i * i)}; });
  ASSERT_EQ(out.size(), 5u);
  EXPECT_EQ(out[4].n, 16);
  EXPECT_THROW(distributed_map(4, [](std::size_t i) { return i == 2 ? throw std::runtime_error("task 2") : 1.0; }),
               std::runtime_error);
}

// A round: n/32 tasks, but at least 4 per worker while 8 rounds remain (the fine map on 1024 cores: 4096 batches,
// not 1252, of which 256 ranks x 4 threads would run 5 per rank, 2 deep on 4 threads: 61 % busy); a whole
// number per worker (Fig. 6's 50 batches on 2 threads: rounds of 6, not 7, of which the 7th task ran alone),
// and never fewer than the workers (8 batches on 2 threads ran one at a time).
TEST(Checkpoint, DefaultRoundKeepsEveryWorkerBusy) {
  EXPECT_EQ(default_round(632, 2), 20u);       // the paper map on one machine: n/32
  EXPECT_EQ(default_round(40051, 1024), 4096u);
  EXPECT_EQ(default_round(50, 2), 6u);         // Fig. 6's ensemble: 50 batches of 8 trajectories
  EXPECT_EQ(default_round(8, 2), 2u);
  EXPECT_EQ(default_round(3, 4), 3u);
  EXPECT_EQ(default_round(40051, 65536), 40051u);  // every task at once: one task's time, as 8 rounds of n/8 would take 8
  EXPECT_EQ(default_round(9, 2), 2u);
  EXPECT_EQ(default_round(0, 4), 1u);
}

}  // namespace checkpoint_test
