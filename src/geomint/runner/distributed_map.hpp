#pragma once
// Independent tasks split across the processes of an MPI job (issue 17): distributed_map computes
// out[i] = f(i), i < n, with task i on rank i mod N (a cyclic split, so that the costly tasks of a
// sweep are spread), each rank's share in parallel on its OpenMP threads (parallel_map), and gives
// every rank every result: encoded by the record's codec as doubles (exact), gathered in task order.
// The results are therefore the same bytes on every rank, for any number of ranks and threads, and
// what a study computes from them afterwards (serially, in index order) is the same everywhere.
// Without MPI, or run without mpirun, it is parallel_map.
#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <concepts>
#include <cstddef>
#include <cstdint>
#include <exception>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <tuple>
#include <type_traits>
#include <utility>
#include <vector>

#include "geomint/sweep/mpi.hpp"
#include "geomint/sweep/parallel_map.hpp"

namespace geomint {

// A task's record as doubles: encode(x, out) appends x; decode(values) gives it back and throws
// std::invalid_argument for values of the wrong length. A study may pass its own codec.
template <class R>
struct RecordCodec;

template <>
struct RecordCodec<double> {
  void encode(double x, std::vector<double>& out) const { out.push_back(x); }
  double decode(std::span<const double> v) const {
    if (v.size() != 1) throw std::invalid_argument("a record of " + std::to_string(v.size()) + " values, not 1");
    return v[0];
  }
};

template <>
struct RecordCodec<std::vector<double>> {
  void encode(const std::vector<double>& x, std::vector<double>& out) const { out.insert(out.end(), x.begin(), x.end()); }
  std::vector<double> decode(std::span<const double> v) const { return {v.begin(), v.end()}; }
};

// A record struct names its members once: `auto fields() { return std::tie(a, b, c); }`, of
// doubles, integers (|i| <= 2^53: exact as doubles), std::vector (its length first), std::array,
// std::pair and std::tuple of those, or of such structs; each of these has a RecordCodec.
template <class R>
concept Fields = requires(R& r) { r.fields(); };

namespace record {

template <class T>
concept Resizable = requires(T& v) { v.resize(0); };  // std::vector (a std::array has a fixed length)

inline constexpr double kExactInteger = 9007199254740992.0;  // 2^53

template <class T>
void put(const T& x, std::vector<double>& out) {
  if constexpr (std::is_floating_point_v<T>) {
    out.push_back(static_cast<double>(x));
  } else if constexpr (std::is_integral_v<T>) {
    if (std::abs(static_cast<double>(x)) > kExactInteger) throw std::out_of_range("an integer beyond 2^53 in a record");
    out.push_back(static_cast<double>(x));
  } else if constexpr (Fields<T>) {
    // (fields() ties references; reading through them leaves x as it is)
    std::apply([&](const auto&... f) { (put(f, out), ...); }, const_cast<T&>(x).fields());
  } else if constexpr (Resizable<T>) {
    out.push_back(static_cast<double>(x.size()));
    for (const auto& e : x) put(e, out);
  } else {  // std::array, std::pair, std::tuple
    std::apply([&](const auto&... e) { (put(e, out), ...); }, x);
  }
}

template <class T>
void get(T& x, std::span<const double>& in) {
  const auto next = [&] {
    if (in.empty()) throw std::invalid_argument("a record shorter than its fields");
    const double v = in.front();
    in = in.subspan(1);
    return v;
  };
  if constexpr (std::is_arithmetic_v<T>) {
    x = static_cast<T>(next());
  } else if constexpr (Fields<T>) {
    std::apply([&](auto&... f) { (get(f, in), ...); }, x.fields());
  } else if constexpr (Resizable<T>) {
    const double n = next();
    if (!(n >= 0 && n <= static_cast<double>(in.size()) && n == std::floor(n)))
      throw std::invalid_argument("a record with a vector of impossible length");
    x.resize(static_cast<std::size_t>(n));
    for (auto& e : x) get(e, in);
  } else {
    std::apply([&](auto&... e) { (get(e, in), ...); }, x);
  }
}

// The codec of a record type that put and get know.
template <class R>
struct Codec {
  void encode(const R& x, std::vector<double>& out) const { put(x, out); }
  R decode(std::span<const double> v) const {
    R x{};
    get(x, v);
    if (!v.empty()) throw std::invalid_argument("a record longer than its fields");
    return x;
  }
};
}  // namespace record

template <Fields R>
struct RecordCodec<R> : record::Codec<R> {};

template <class T>
struct RecordCodec<std::vector<T>> : record::Codec<std::vector<T>> {};  // (but std::vector<double>, above)
template <class T, std::size_t N>
struct RecordCodec<std::array<T, N>> : record::Codec<std::array<T, N>> {};
template <class A, class B>
struct RecordCodec<std::pair<A, B>> : record::Codec<std::pair<A, B>> {};
template <class... T>
struct RecordCodec<std::tuple<T...>> : record::Codec<std::tuple<T...>> {};

// The exception `error` of rank `owner` (null on the others), thrown on every rank of an MPI job: its
// kind (SceneError, NumericalFailure, OutputError, Interrupted; another: std::runtime_error) and
// message sent from the owner, so that every rank ends the same way.
[[noreturn]] void throw_everywhere(int owner, std::exception_ptr error);

// out[i] = f(i), i < n, as described at the top. A task that throws: the exception of the lowest
// such task, on every rank (as parallel_map does in one process). The time spent on this rank's
// share counts towards run.json's rank_busy_s, the exchange after it towards rank_exchange_s.
template <class F, class R = std::invoke_result_t<const F&, std::size_t>, class Codec = RecordCodec<R>>
std::vector<R> distributed_map(std::size_t n, const F& f, const Codec& codec = {}) {
  const auto t0 = std::chrono::steady_clock::now();
  const auto busy = [&] { mpi::count_busy(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count()); };
  if (mpi::size() == 1) {
    auto out = parallel_map(n, f);
    busy();
    return out;
  }
  const auto r = static_cast<std::size_t>(mpi::rank()), p = static_cast<std::size_t>(mpi::size());
  const auto share = [&](std::size_t q) { return n > q ? (n - q + p - 1) / p : 0; };  // tasks of rank q
  std::vector<char> threw(share(r), 0);
  std::vector<double> mine;  // per task: its record's length, then the record
  std::exception_ptr error;
  std::int64_t failed = INT64_MAX;
  try {
    const auto results = parallel_map(share(r), [&](std::size_t k) {
      try {
        return f(r + k * p);
      } catch (...) {
        threw[k] = 1;
        throw;
      }
    });
    for (const R& x : results) {
      const std::size_t at = mine.size();
      mine.push_back(0), codec.encode(x, mine);
      mine[at] = static_cast<double>(mine.size() - at - 1);
    }
  } catch (...) {
    error = std::current_exception();
    const auto k = static_cast<std::size_t>(std::find(threw.begin(), threw.end(), 1) - threw.begin());
    failed = static_cast<std::int64_t>(r + k * p);
  }
  busy();
  const auto t1 = std::chrono::steady_clock::now();
  if (const std::int64_t lowest = mpi::all_min(failed); lowest != INT64_MAX)
    throw_everywhere(static_cast<int>(static_cast<std::size_t>(lowest) % p), error);
  const std::vector<double> all = mpi::all_gather(mine);
  std::vector<std::optional<R>> slots(n);
  std::size_t at = 0;
  for (std::size_t q = 0; q < p; ++q)
    for (std::size_t k = 0; k < share(q); ++k) {
      const auto length = static_cast<std::size_t>(all[at]);
      slots[q + k * p].emplace(codec.decode(std::span<const double>(all.data() + at + 1, length)));
      at += 1 + length;
    }
  mpi::count_exchange(std::chrono::duration<double>(std::chrono::steady_clock::now() - t1).count());
  std::vector<R> out;
  out.reserve(n);
  for (auto& s : slots) out.push_back(std::move(*s));
  return out;
}

}  // namespace geomint
