#include "geomint/sweep/ensemble_kernels.hpp"

#include <type_traits>
#include <utility>

#include "geomint/sweep/arithmetic_counts.hpp"
#include "geomint/sweep/lanes_cap.hpp"

namespace geomint {

#define GEOMINT_DECLARE_LANES(isa)                                                                             \
  namespace isa {                                                                                              \
  template <class Sys>                                                                                         \
  void simplified_ti_steps(const Sys&, double, double, LanesOf<Sys>&, std::int64_t);                          \
  void reciprocals(const double* u, double* out, std::size_t n);                                               \
  }
GEOMINT_DECLARE_LANES(sse2)
GEOMINT_DECLARE_LANES(avx2)
GEOMINT_DECLARE_LANES(avx512)
#undef GEOMINT_DECLARE_LANES

template <class Sys>
std::vector<LanesKernel<Sys>> simplified_ti_lanes_kernels() {
  __builtin_cpu_init();
  std::vector<LanesKernel<Sys>> k;
  constexpr bool counted = std::is_same_v<Sys, LennardJones<9>>;  // (the Henon-Heiles lanes are not counted)
  if (__builtin_cpu_supports("avx512f"))
    k.push_back({"avx512", "AVX-512", avx512::simplified_ti_steps<Sys>, avx512::reciprocals,
                 counted ? KernelArithmetic{&kLennardJonesAvx512, issue_mix_avx512} : KernelArithmetic{}});
  if (__builtin_cpu_supports("avx2"))
    k.push_back({"avx2", "AVX2", avx2::simplified_ti_steps<Sys>, avx2::reciprocals,
                 counted ? KernelArithmetic{&kLennardJonesAvx2, issue_mix_avx2} : KernelArithmetic{}});
  k.push_back({"sse2", "SSE2", sse2::simplified_ti_steps<Sys>, sse2::reciprocals, {}});
  return within_lanes_cap(std::move(k));
}

template <class Sys>
std::vector<typename Sys::State> simplified_ti_lanes(const Sys& sys, LanesSteps<Sys> steps,
                                                    std::span<const typename Sys::State> starts, double h,
                                                    std::int64_t n, std::int64_t every, const LanesObserver<Sys>& observe) {
  const auto method = simplified_ti_method(sys, false);
  constexpr int L = kLanes<Sys>;
  const int used = static_cast<int>(std::min<std::size_t>(starts.size(), L));
  LanesOf<Sys> lanes;
  for (int i = 0; i < L; ++i) lanes.set(i, method.pre(starts[i < used ? i : 0], h));
  const auto observe_all = [&](std::int64_t j) {
    for (int i = 0; i < used; ++i) observe(i, j, lanes.get(i).z);
  };
  observe_all(0);
  for (std::int64_t j = 0; j < n;) {
    const std::int64_t next = std::min(n, (j / every + 1) * every);
    steps(sys, h, takahashi_imada_alpha, lanes, next - j);
    j = next;
    if (j % every == 0) observe_all(j);
  }
  std::vector<typename Sys::State> out;
  for (int i = 0; i < used; ++i) out.push_back(lanes.get(i).z);
  return out;
}

#define GEOMINT_LANES_ON(Sys)                                                                                  \
  template std::vector<LanesKernel<Sys>> simplified_ti_lanes_kernels();                                       \
  template std::vector<Sys::State> simplified_ti_lanes(const Sys&, LanesSteps<Sys>, std::span<const Sys::State>, \
                                                       double, std::int64_t, std::int64_t, const LanesObserver<Sys>&);
GEOMINT_LANES_ON(LennardJones<9>)
GEOMINT_LANES_ON(HenonHeilesT<true>)
GEOMINT_LANES_ON(HenonHeilesT<false>)
#undef GEOMINT_LANES_ON

}  // namespace geomint
