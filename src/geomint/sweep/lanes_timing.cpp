#include "geomint/sweep/lanes_timing.hpp"

#include <span>

#include "geomint/sweep/ensemble_kernels.hpp"

namespace geomint {

template <class Sys>
LanesTiming time_lanes(const Sys& sys, const std::vector<typename Sys::State>& starts, double h, std::int64_t n,
                       int repeats) {
  using Z = typename Sys::State;
  const auto method = simplified_ti_method(sys, false);
  InterleavedTiming timing(repeats);  // the scalar method and each kernel, interleaved
  timing.add([&] {
    for (const Z& z : starts) do_not_optimize(integrate_inlined(method, z, h, n));
  });
  const auto kernels = simplified_ti_lanes_kernels<Sys>();
  for (const auto& k : kernels)
    timing.add([&] {
      do_not_optimize(simplified_ti_lanes(sys, k.steps, std::span<const Z>(starts), h, n, n, [](int, std::int64_t, const Z&) {}));
    });
  const std::vector<RunTime> t = timing.run();
  LanesTiming out{t.front(), {}};
  for (std::size_t i = 0; i < kernels.size(); ++i) out.kernels.push_back({kernels[i].name, t[i + 1]});
  return out;
}

template LanesTiming time_lanes(const LennardJones<9>&, const std::vector<LennardJones<9>::State>&, double, std::int64_t, int);
template LanesTiming time_lanes(const HenonHeilesT<true>&, const std::vector<HenonHeilesT<true>::State>&, double,
                                std::int64_t, int);
template LanesTiming time_lanes(const HenonHeilesT<false>&, const std::vector<HenonHeilesT<false>::State>&, double,
                                std::int64_t, int);

}  // namespace geomint
