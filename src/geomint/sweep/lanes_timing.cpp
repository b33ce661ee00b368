#include "geomint/sweep/lanes_timing.hpp"

#include <span>

#include "geomint/sweep/ensemble_kernels.hpp"

namespace geomint {

template <class Sys>
LanesTiming time_lanes(const Sys& sys, const std::vector<typename Sys::State>& starts, double h, std::int64_t n,
                       int repeats) {
  using Z = typename Sys::State;
  const auto method = simplified_ti_method(sys, false);
  LanesTiming out{time_runs(repeats, [&] {
                    for (const Z& z : starts) do_not_optimize(integrate_inlined(method, z, h, n));
                  }),
                  {}};
  for (const auto& k : simplified_ti_lanes_kernels<Sys>())
    out.kernels.push_back({k.name, time_runs(repeats, [&] {
                             do_not_optimize(simplified_ti_lanes(sys, k.steps, std::span<const Z>(starts), h, n, n,
                                                                 [](int, std::int64_t, const Z&) {}));
                           })});
  return out;
}

template LanesTiming time_lanes(const LennardJones<9>&, const std::vector<LennardJones<9>::State>&, double, std::int64_t, int);
template LanesTiming time_lanes(const HenonHeilesT<true>&, const std::vector<HenonHeilesT<true>::State>&, double,
                                std::int64_t, int);
template LanesTiming time_lanes(const HenonHeilesT<false>&, const std::vector<HenonHeilesT<false>::State>&, double,
                                std::int64_t, int);

}  // namespace geomint
