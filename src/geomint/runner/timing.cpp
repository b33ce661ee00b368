// The timing protocol of runner/timing.hpp.
#include "geomint/runner/timing.hpp"

#include <algorithm>
#include <atomic>
#include <barrier>
#include <chrono>
#include <cmath>
#include <exception>
#include <fstream>
#include <map>
#include <mutex>
#include <sstream>
#include <stdexcept>
#include <thread>

#include "geomint/io/atomic_file.hpp"
#include "geomint/io/csv.hpp"
#include "geomint/runner/clock.hpp"

namespace geomint {
namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// The wall time of `inner` calls of f.
double timed_run(const std::function<void()>& f, std::int64_t inner) {
  const auto start = Clock::now();
  for (std::int64_t i = 0; i < inner; ++i) f();
  return seconds_since(start);
}

// The calls that last `seconds`, where `calls` took took_s (at least one).
std::int64_t calls_for(double seconds, std::int64_t calls, double took_s) {
  const double c = std::ceil(static_cast<double>(calls) * seconds / std::max(took_s, 1e-9));
  return std::max<std::int64_t>(1, static_cast<std::int64_t>(c));
}

// Calls per run for a run of f of kTimingMargin times floor_s: after an untimed warm-up call, from a
// probe run of at least floor_s / 8 (a call of at least floor_s: one call per run).
std::int64_t calibrated_calls(const std::function<void()>& f, double floor_s) {
  const double once = timed_run(f, 1);  // the warm-up
  if (once >= floor_s) return 1;
  const double probe_s = floor_s / 8;
  std::int64_t k = static_cast<std::int64_t>(std::ceil(probe_s / std::max(once, 1e-9)));
  double t = timed_run(f, k);
  for (; t < probe_s; t = timed_run(f, k)) k = std::max(2 * k, calls_for(probe_s, k, t));
  return calls_for(kTimingMargin * floor_s, k, t);
}

}  // namespace

RunTime RunTime::scaled(double factor) const {
  RunTime r = *this;
  for (double* x : {&r.min_s, &r.q1_s, &r.median_s, &r.q3_s, &r.max_s}) *x *= factor;
  return r;
}

Value to_value(const RunTime& t) {
  return {{"median_s", t.median_s}, {"q1_s", t.q1_s}, {"q3_s", t.q3_s}, {"min_s", t.min_s}, {"max_s", t.max_s},
          {"spread", t.spread()}, {"repeats", t.repeats}, {"inner", t.inner}, {"drift", t.drift}};
}

double sorted_quantile(const std::vector<double>& v, double q) {
  if (v.empty()) throw std::invalid_argument("sorted_quantile: no values");
  const double at = q * static_cast<double>(v.size() - 1);
  const auto lo = static_cast<std::size_t>(std::floor(at));
  const std::size_t hi = std::min(lo + 1, v.size() - 1);
  return v[lo] + (at - static_cast<double>(lo)) * (v[hi] - v[lo]);
}

RunTime run_time_of(std::vector<double> per_call, std::int64_t inner) {
  std::sort(per_call.begin(), per_call.end());
  RunTime r;
  r.repeats = static_cast<int>(per_call.size()), r.inner = inner;
  r.min_s = per_call.front(), r.max_s = per_call.back();
  r.q1_s = sorted_quantile(per_call, 0.25), r.median_s = sorted_quantile(per_call, 0.5);
  r.q3_s = sorted_quantile(per_call, 0.75);
  return r;
}

std::size_t InterleavedTiming::add(std::function<void()> f) {
  configs_.push_back(std::move(f));
  return configs_.size() - 1;
}

namespace {

// workers - 1 threads besides the calling one, kept for a whole measurement (a thread started for each
// round may begin on a busy core and be moved only later): run(job) calls job(0) here and job(w) on
// thread w, all starting together, and returns when every one has ended, rethrowing the first exception.
class Pool {
 public:
  explicit Pool(int workers) : workers_(std::max(workers, 1)), start_(workers_), done_(workers_) {
    for (int w = 1; w < workers_; ++w)
      threads_.emplace_back([this, w] {
        for (start_.arrive_and_wait(); !stop_; start_.arrive_and_wait()) call(w), done_.arrive_and_wait();
      });
  }
  ~Pool() {
    stop_ = true;
    if (workers_ > 1) start_.arrive_and_wait();
  }
  void run(const std::function<void(int)>& job) {
    job_ = &job, error_ = nullptr;
    if (workers_ > 1) start_.arrive_and_wait();
    call(0);
    if (workers_ > 1) done_.arrive_and_wait();
    if (error_) std::rethrow_exception(error_);
  }

 private:
  void call(int w) {
    try {
      (*job_)(w);
    } catch (...) {
      const std::lock_guard<std::mutex> lock(error_mutex_);
      if (!error_) error_ = std::current_exception();
    }
  }
  int workers_;
  std::barrier<> start_, done_;
  std::atomic<bool> stop_{false};
  const std::function<void(int)>* job_ = nullptr;
  std::exception_ptr error_;
  std::mutex error_mutex_;
  std::vector<std::jthread> threads_;  // (last: joined before the barriers go)
};

// f(0), ..., f(count - 1) on the pool's threads, each index once, in increasing order of start.
void parallel_for(Pool& pool, std::size_t count, const std::function<void(std::size_t)>& f) {
  std::atomic<std::size_t> next{0};
  pool.run([&](int) {
    for (std::size_t k = next++; k < count; k = next++) f(k);
  });
}

// The protocol on `workers` cores at a time (the caller has checked that they time alike).
std::vector<RunTime> run_rounds(const std::vector<std::function<void()>>& configs, int repeats, double floor_s,
                                int workers) {
  const std::size_t n = configs.size();
  Pool pool(std::min<int>(workers, static_cast<int>(n)));
  std::vector<std::int64_t> inner(n);
  parallel_for(pool, n, [&](std::size_t c) { inner[c] = calibrated_calls(configs[c], floor_s); });
  std::vector<std::vector<double>> per_call(n);
  for (int round = 0; round < repeats; ++round)
    parallel_for(pool, n, [&](std::size_t k) {  // (rotated by one per round)
      const std::size_t c = (k + static_cast<std::size_t>(round)) % n;
      double t = timed_run(configs[c], inner[c]);
      for (; t < floor_s; t = timed_run(configs[c], inner[c]))  // (never a run below the floor: a faster
        inner[c] = calls_for(kTimingMargin * floor_s, inner[c], t);  // machine lengthens it and runs it again)
      per_call[c].push_back(t / static_cast<double>(inner[c]));
    });
  std::vector<RunTime> out;
  for (std::size_t c = 0; c < n; ++c) out.push_back(run_time_of(std::move(per_call[c]), inner[c]));
  return out;
}

// Bound by the throughput of the multiply and add units, not by their latency: 32 independent chains of
// x = a x + b (16 of two doubles where the compiler pairs them), more than latency times units.
void fp_throughput_loop() {
  double x[32];
  for (int k = 0; k < 32; ++k) x[k] = k;
  for (int i = 0; i < 1 << 12; ++i)
    for (double& v : x) v = 0.999999 * v + 1e-7;
  for (const double& v : x) do_not_optimize(v);
}

std::mutex concurrency_mutex;
struct ConcurrencyUsed {
  TimingConcurrency c;
  std::string from;  // "this run" or the file it was read from
};
std::map<int, ConcurrencyUsed> concurrency_used;  // by requested workers
std::string concurrency_file;                     // share_timing_concurrency

// The measurements in a shared file, by requested workers (none where the file does not exist).
std::map<int, TimingConcurrency> read_shared_concurrency(const std::string& path) {
  std::map<int, TimingConcurrency> out;
  std::ifstream in(path);
  std::string line;
  for (int n = 1; std::getline(in, line); ++n) {
    std::istringstream fields(line);
    int requested = 0;
    TimingConcurrency c;
    std::string more;
    if (!(fields >> requested >> c.workers >> c.slowdown) || fields >> more || requested < 2 ||
        (c.workers != 1 && c.workers != requested) || !(c.slowdown > 0))
      throw std::runtime_error("--timing-concurrency " + path + ", line " + std::to_string(n) + ": \"" + line +
                               "\" is not \"requested workers slowdown\" (requested >= 2, workers 1 or requested, slowdown > 0)");
    out[requested] = c;
  }
  return out;
}

void write_shared_concurrency(const std::string& path, const std::map<int, TimingConcurrency>& all) {
  std::string text;
  for (const auto& [requested, c] : all)
    text += std::to_string(requested) + " " + std::to_string(c.workers) + " " + format_double(c.slowdown) + "\n";
  write_file_atomic(path, text);
}

std::mutex control_mutex;
Value control_measured = Value::list();  // timing_control_record

// The control's time per call, alone under the protocol (kControlRepeats runs).
double control_seconds(double floor_s) {
  return run_rounds({fp_throughput_loop}, kControlRepeats, floor_s, 1).front().seconds();
}

}  // namespace

TimingConcurrency timing_concurrency(int workers, int repeats) {
  if (workers <= 1) return {};
  const std::lock_guard<std::mutex> lock(concurrency_mutex);
  if (const auto it = concurrency_used.find(workers); it != concurrency_used.end()) return it->second.c;
  std::map<int, TimingConcurrency> shared;
  if (!concurrency_file.empty()) {
    shared = read_shared_concurrency(concurrency_file);
    if (const auto it = shared.find(workers); it != shared.end())
      return (concurrency_used[workers] = {it->second, concurrency_file}).c;
  }
  // Per round, one run of the loop alone (the other threads waiting), then one on every thread at once
  // (the slowest counts), each of at least the floor.
  Pool pool(workers);
  const std::int64_t inner = calibrated_calls(fp_throughput_loop, kTimingFloorS);
  std::vector<double> alone, beside, each(static_cast<std::size_t>(workers));
  for (int round = 0; round < std::max(repeats, kTimingRepeats); ++round) {
    alone.push_back(timed_run(fp_throughput_loop, inner));
    pool.run([&](int w) { each[static_cast<std::size_t>(w)] = timed_run(fp_throughput_loop, inner); });
    beside.push_back(*std::max_element(each.begin(), each.end()));
  }
  TimingConcurrency c;
  c.slowdown = run_time_of(beside, inner).seconds() / run_time_of(alone, inner).seconds();
  c.workers = c.slowdown <= kConcurrentSlowdown ? workers : 1;
  if (!concurrency_file.empty()) shared[workers] = c, write_shared_concurrency(concurrency_file, shared);
  return (concurrency_used[workers] = {c, "this run"}).c;
}

void share_timing_concurrency(const std::string& file) {
  const std::lock_guard<std::mutex> lock(concurrency_mutex);
  read_shared_concurrency(file);  // (a file of another form is refused before any work)
  concurrency_file = file;
}

Value to_value(const TimingConcurrency& c) { return {{"workers", c.workers}, {"slowdown", c.slowdown}}; }

Value timing_concurrency_record() {
  const std::lock_guard<std::mutex> lock(concurrency_mutex);
  if (concurrency_used.empty()) return nullptr;
  Value out = Value::list();
  for (const auto& [requested, used] : concurrency_used) {
    Value m = to_value(used.c);
    m["requested"] = requested;
    m["from"] = used.from;
    out.push_back(m);
  }
  return out;
}

Value timing_protocol_record() {
  return {{"floor_ms", kTimingFloorS * 1000}, {"margin", kTimingMargin}, {"min_repeats", kTimingRepeats},
          {"control_repeats", kControlRepeats}};
}

Value timing_control_record() {
  const std::lock_guard<std::mutex> lock(control_mutex);
  if (control_measured.size() == 0) return nullptr;
  return control_measured;
}

std::vector<RunTime> InterleavedTiming::run() const {
  const int workers = workers_ > 1 && configs_.size() > 1 ? timing_concurrency(workers_, repeats_).workers : 1;
  if (configs_.size() < 2) return run_rounds(configs_, std::max(repeats_, 1), floor_s_, workers);
  const double before = control_seconds(floor_s_);  // (the drift of a measurement whose ratios are compared)
  std::vector<RunTime> out = run_rounds(configs_, std::max(repeats_, 1), floor_s_, workers);
  const double after = control_seconds(floor_s_);
  const double drift = std::abs(after / before - 1);
  for (RunTime& t : out) t.drift = drift;
  const std::lock_guard<std::mutex> lock(control_mutex);
  control_measured.push_back({{"configurations", static_cast<double>(configs_.size())}, {"before_s", before},
                              {"after_s", after}, {"drift", drift}});
  return out;
}

RunTime time_runs(int repeats, const std::function<void()>& f, double floor_s) {
  InterleavedTiming t(repeats, floor_s);
  t.add(f);
  return t.run().front();
}

void dependent_additions(std::int64_t n) {
  std::uint64_t x = 0;
  const std::uint64_t one = 1;
  for (std::int64_t i = 0; i < n; i += 8) {
#if defined(__x86_64__)
    // Register operands, not immediates: Intel cores since Golden Cove (Sapphire Rapids) fold chains of
    // additions of immediates in the renamer, several per cycle, and the clock came out four times too fast.
    asm volatile("add %1, %0\n\tadd %1, %0\n\tadd %1, %0\n\tadd %1, %0\n\t"
                 "add %1, %0\n\tadd %1, %0\n\tadd %1, %0\n\tadd %1, %0"
                 : "+r"(x)
                 : "r"(one));  // (each addition waits for the previous one)
#else
    x += 8;
#endif
  }
  do_not_optimize(x);
}

double ns_per_cycle(int repeats) {
#if defined(__x86_64__)
  constexpr std::int64_t kAdds = 1 << 16;
  const RunTime t = time_runs(repeats, [] { dependent_additions(kAdds); });
  return 1e9 * t.seconds() / static_cast<double>(kAdds);
#else
  (void)repeats;
  return std::nan("");
#endif
}

namespace {
// The interval [lo, hi], widened by the drift, holds 1.
bool holds_one(double lo, double hi, double drift) { return !(hi * (1 + drift) < 1 || lo / (1 + drift) > 1); }
}  // namespace

TimeRatio time_ratio(const RunTime& a, const RunTime& b) {
  TimeRatio r;
  r.median = a.median_s / b.median_s;
  r.lo = a.q1_s / b.q3_s, r.hi = a.q3_s / b.q1_s;
  r.drift = std::max(a.drift, b.drift);
  r.indistinguishable = holds_one(r.lo, r.hi, r.drift);
  return r;
}

TimeRatio carried_over(const TimeRatio& timed, double ratio) {
  TimeRatio r = timed;
  r.median = ratio, r.lo = ratio * timed.lo / timed.median, r.hi = ratio * timed.hi / timed.median;
  r.indistinguishable = holds_one(r.lo, r.hi, r.drift);
  return r;
}

Value to_value(const TimeRatio& r) {
  return {{"median", r.median}, {"lo", r.lo}, {"hi", r.hi}, {"drift", r.drift}, {"indistinguishable", r.indistinguishable}};
}

std::string timing_verdict(const TimeRatio& a_over_b, double work_a, double work_b) {
  if (a_over_b.indistinguishable) return "indistinguishable";
  const bool faster = a_over_b.hi * (1 + a_over_b.drift) < 1;
  if ((faster && work_a > work_b) || (!faster && work_a < work_b)) return "contradicts the work";
  return faster ? "faster" : "slower";
}

Value relative_timings(const std::vector<std::string>& labels, const std::vector<RunTime>& times,
                       const std::vector<double>& work, std::size_t ref) {
  if (labels.empty() || times.size() != labels.size() || work.size() != labels.size())
    throw std::invalid_argument("relative_timings: labels, times and work differ in length");
  if (ref >= labels.size()) throw std::invalid_argument("relative_timings: no reference " + std::to_string(ref));
  Value out = {{"reference", labels[ref]}, {"by_method", Value::record()}};
  for (std::size_t k = 0; k < labels.size(); ++k) {
    const TimeRatio r = time_ratio(times[k], times[ref]);
    out["by_method"][labels[k]] = {{"ratio", r.median},
                                   {"interval", {{"min", r.lo}, {"max", r.hi}}},
                                   {"verdict", k == ref ? std::string("reference") : timing_verdict(r, work[k], work[ref])}};
  }
  return out;
}

}  // namespace geomint
