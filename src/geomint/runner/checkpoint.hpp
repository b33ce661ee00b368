#pragma once
// Checkpoints of a long study's independent tasks (issue 16, item 5): checkpointed_map computes
// out[i] = f(i), i < n, in rounds and keeps the finished tasks in the staging directory, so that a
// stopped run (a signal, or the scene's checkpoint.stop_after; Interrupted, exit 3) continues with
// --resume where it stopped, with the same results as a run straight through, for any thread count.
//
// Files (in ctx.out.path(), the staging directory DIR.partial; removed when the run commits):
//   <name>.checkpoint.log   a preamble of 16 bytes (the magic "geomintL" and the run's id, a random
//                           uint64), then the finished tasks' records in task order, appended round by
//                           round: per record a uint64 count L, L doubles and a uint64 holding its check,
//                           the CRC-32C (io/crc32c.hpp) of its task index, L and the values, seeded by the
//                           check of the record before (the machine's byte order). Record 0 is seeded by
//                           the run's seed, the CRC-32C of the header's identity (format, experiment, study,
//                           name, scene keys, binary, kernel, n) and the run id: a record checks only in its own
//                           place of its own run's log;
//   <name>.checkpoint.json  the header, written atomically after each append: format, experiment,
//                           study, name, the scene keys the tasks depend on, the binary (build_info), the
//                           kernel (CheckpointSpec::kernel), n, order_crc32c (the CRC-32C of the order the tasks run in, task_order, as
//                           uint64s), run_id, tasks_done, log_bytes (the part of the log that holds them in
//                           full) and chain_crc32c (the check of the last of them; the seed if none).
// On --resume a header that is missing means nothing to resume, one of other scene values, another kernel or
// another task order is discarded (start over); one that cannot be used (not JSON, another format, another binary,
// tasks_done beyond n, a log shorter than log_bytes, the log of another run, a record that fails its
// check (damaged, moved, dropped, repeated, or from another run's log), records that do not end with
// chain_crc32c, a value that is not finite, a header or log that is not a regular file) is refused with
// a SceneError naming the file and the field or record (exit 2). No size field is trusted beyond the
// file: the log is read record by record, each count checked against the bytes left. A log
// longer than log_bytes (a run stopped in the middle of an append) is cut back. Every write costs
// what is new: O(work) in all.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <exception>
#include <filesystem>
#include <memory>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "geomint/runner/distributed_map.hpp"
#include "geomint/runner/experiment.hpp"
#include "geomint/sweep/mpi.hpp"

namespace geomint {

struct CheckpointSpec {
  std::string name;               // the files' stem: the study's name, or "<study>.<part>" for a study's second loop
  // The scene keys (dotted; sections or values) the tasks depend on; empty: every key the study reads
  // (Context::reads) but checkpoint.* (task_keys).
  std::vector<std::string> keys = {};
  std::size_t round = 0;          // tasks per round (0: default_round)
  // The tasks' relative work (e.g. steps times force evaluations per step), if known: they run in decreasing order
  // of it (ties in index order), so that a round's tasks take alike and the long ones do not each leave threads idle
  // beside short ones at the round's end; empty: in index order. The results are by index either way.
  std::vector<double> work = {};
  // The kernel the tasks run, where their results depend on which (the energy map's instruction set,
  // sweep/energy_map.hpp); a checkpoint of another kernel, like one of other scene values, is discarded.
  std::string kernel = {};
};

// The header and log of one checkpointed map (the part that does not depend on the record type).
class CheckpointLog {
 public:
  CheckpointLog(const Context& ctx, const CheckpointSpec& spec, std::size_t n);
  // The order the tasks run in (task_order): the log's k-th record is task order()[k]. A checkpoint of another
  // order is one of other scene values: nothing of it applies.
  const std::vector<std::size_t>& order() const { return order_; }

  struct Records {
    std::vector<double> values;
    std::vector<std::size_t> offsets{0};  // record k: values[offsets[k], offsets[k + 1])
    std::size_t size() const { return offsets.size() - 1; }
    std::span<const double> operator[](std::size_t k) const {
      return {values.data() + offsets[k], offsets[k + 1] - offsets[k]};
    }
  };
  // With `resume`, the records of the tasks the checkpoint holds (validated; the log cut back to
  // them); otherwise, or for a checkpoint of other scene values, none (its files removed).
  // Under MPI rank 0 reads, every rank receives.
  Records load(bool resume);
  // Appends the records (values, split by `lengths`) of the tasks after tasks_done(), synced, then
  // writes the header: tasks_done() + lengths.size() tasks. (Under MPI rank 0 writes; the others count.)
  void append(std::span<const double> values, std::span<const std::size_t> lengths);
  std::size_t tasks_done() const { return tasks_done_; }
  const std::string& name() const { return name_; }
  [[noreturn]] void refuse_log(const std::string& why) const { refuse(log_, why); }

 private:
  [[noreturn]] void refuse(const std::filesystem::path& file, const std::string& why) const;
  Records load_here(bool resume);
  void reset();

  std::string name_;
  std::filesystem::path header_, log_;
  std::shared_ptr<const nlohmann::ordered_json> identity_;  // the header less tasks_done and log_bytes
  std::size_t n_, tasks_done_ = 0;
  std::vector<std::size_t> order_;
  std::uint64_t log_bytes_ = 0;
  std::uint64_t run_id_ = 0;   // of the run that began the log (a resumed run continues it)
  std::uint32_t chain_ = 0;    // the check of the last record (the seed if none)
  std::uint32_t seed() const;  // the CRC-32C of the identity and the run id: record 0's seed
};

// The tasks of a round of checkpointed_map for n tasks on `workers` threads (all ranks together):
// n/32 (a stop point every 3 % of the work), but at least 4 per worker as long as that leaves 8
// rounds, so that the uneven end of a round (tasks are whole) idles few workers of a large job;
// then a whole number of tasks per worker, and never fewer tasks than workers (a round of fewer
// takes as long as a round of `workers` tasks: more rounds, no earlier stop point).
inline std::size_t default_round(std::size_t n, std::size_t workers) {
  const std::size_t r = std::max((n + 31) / 32, std::min(4 * workers, (n + 7) / 8));
  return std::max<std::size_t>(1, r >= workers ? r - r % workers : std::min(workers, n));
}

// The wall time this process spent writing checkpoints (appends and headers, synced), for run.json.
double checkpoint_write_seconds();

// Removes every checkpoint in `dir`, the headers (*.checkpoint.json) before the logs (*.checkpoint.log):
// the runner, before it commits.
void remove_checkpoints(const std::filesystem::path& dir);

// A checkpoint is written after a round when the scene's checkpoint.interval (seconds; without the
// key, kCheckpointInterval) has passed since the last one, at the end, and before every stop.
inline constexpr std::chrono::seconds kCheckpointInterval{10};

// The order checkpointed_map runs n tasks in: by decreasing spec.work where it is given (ties in index order).
std::vector<std::size_t> task_order(const CheckpointSpec& spec, std::size_t n);

// out[i] = f(i) for i < n, computed in rounds of distributed_map (results stored by index, so they
// do not depend on the thread count or on the order of spec.work; reductions come after, in the study). After a round, if
// checkpoint.interval has passed since the last save, the map is done, or a stop is requested
// (SIGINT/SIGTERM/SIGUSR1, stop_requested(); or the scene's checkpoint.stop_after rounds), the finished
// tasks not yet saved are appended to the log. A record with a value that is not finite is not
// saved (nor any after it): a resumed run recomputes it and the study's own check reports it. On a
// stop, Interrupted names where it stopped and the command that resumes (a signal during the last round, or
// its save, stops there too: with every task saved, the study's own end is left to --resume). With ctx.resume the
// tasks the checkpoint holds are read back instead of computed. Each round is a distributed_map:
// under MPI its tasks are split across the ranks.
template <class R, class F, class Codec = RecordCodec<R>>
std::vector<R> checkpointed_map(Context& ctx, const CheckpointSpec& spec, std::size_t n, const F& f,
                                const Codec& codec = {}) {
  CheckpointLog log(ctx, spec, n);
  const std::vector<std::size_t>& order = log.order();
  std::vector<std::optional<R>> slots(n);  // by place in the order
  std::size_t done = 0;
  {
    const CheckpointLog::Records restored = log.load(ctx.resume);
    for (; done < restored.size(); ++done) try {
        slots[done].emplace(codec.decode(restored[done]));
      } catch (const std::invalid_argument& e) {
        log.refuse_log("task " + std::to_string(done) + ": " + e.what());
      }
  }
  if (done > 0) ctx.progress("resuming " + log.name() + " after " + std::to_string(done) + " of " + std::to_string(n) + " tasks");
  const std::int64_t stop_after = ctx.scene.has("checkpoint.stop_after") ? ctx.scene.integer("checkpoint.stop_after") : 0;
  const std::chrono::duration<double> interval(
      ctx.scene.has("checkpoint.interval") ? ctx.scene.real("checkpoint.interval") : kCheckpointInterval.count());
  const std::size_t round = spec.round > 0 ? spec.round : default_round(n, static_cast<std::size_t>(ctx.threads * mpi::size()));
  std::vector<double> values;
  std::vector<std::size_t> lengths;
  bool blocked = false;  // a record that is not finite: nothing from it on is saved
  auto saved_at = std::chrono::steady_clock::now();
  const auto save = [&] {
    values.clear(), lengths.clear();
    for (std::size_t i = log.tasks_done(); i < done && !blocked; ++i) {
      const std::size_t before = values.size();
      codec.encode(*slots[i], values);
      blocked = !std::all_of(values.begin() + static_cast<std::ptrdiff_t>(before), values.end(),
                             [](double v) { return std::isfinite(v); });
      if (blocked) values.resize(before);
      else lengths.push_back(values.size() - before);
    }
    if (!lengths.empty()) log.append(values, lengths);
    saved_at = std::chrono::steady_clock::now();
  };
  const StopPoint stop_point;  // SIGINT/SIGTERM: stop at the next checkpoint
  ctx.progress(log.name(), static_cast<double>(done), static_cast<double>(n), "tasks");  // (where the rate starts)
  for (std::int64_t rounds = 0;; ++rounds) {
    const bool by_count = done < n && stop_after > 0 && rounds == stop_after;
    bool stop = by_count || mpi::all_max(stop_requested()) != 0;  // (any rank's signal; in the last round too)
    if (done > log.tasks_done() && !blocked &&
        (stop || done == n || std::chrono::steady_clock::now() - saved_at >= interval))
      save();
    if (done == n && !stop) stop = mpi::all_max(stop_requested()) != 0;  // (a signal during the last save)
    if (stop)
      throw Interrupted(log.name() + " after " + std::to_string(done) + " of " + std::to_string(n) + " tasks (" +
                        (by_count ? "checkpoint.stop_after = " + std::to_string(stop_after) : std::string("signal")) +
                        "); continue with: " + ctx.resume_command);
    if (done == n) break;
    const std::size_t first = done, count = std::min(round, n - done);
    auto results = distributed_map(count, [&](std::size_t i) { return f(order[first + i]); }, codec);
    for (std::size_t i = 0; i < count; ++i) slots[first + i].emplace(std::move(results[i]));
    done += count;
    ctx.progress(log.name(), static_cast<double>(done), static_cast<double>(n), "tasks");
  }
  std::vector<std::optional<R>> by_task(n);
  for (std::size_t k = 0; k < n; ++k) by_task[order[k]] = std::move(slots[k]);
  std::vector<R> out;
  out.reserve(n);
  for (auto& s : by_task) out.push_back(std::move(*s));
  return out;
}

}  // namespace geomint
