#include "geomint/sweep/ensemble_kernels.hpp"

namespace geomint {

#define GEOMINT_DECLARE_LANES(isa)                                                                             \
  namespace isa {                                                                                              \
  template <class Sys>                                                                                         \
  void simplified_ti_steps(const Sys&, double, double, KickLanes<Sys::State::dof>&, std::int64_t);            \
  }
GEOMINT_DECLARE_LANES(sse2)
GEOMINT_DECLARE_LANES(avx2)
GEOMINT_DECLARE_LANES(avx512)
#undef GEOMINT_DECLARE_LANES

template <class Sys>
std::vector<LanesKernel<Sys>> simplified_ti_lanes_kernels() {
  __builtin_cpu_init();
  std::vector<LanesKernel<Sys>> k;
  if (__builtin_cpu_supports("avx512f")) k.push_back({"avx512", "AVX-512", avx512::simplified_ti_steps<Sys>});
  if (__builtin_cpu_supports("avx2")) k.push_back({"avx2", "AVX2", avx2::simplified_ti_steps<Sys>});
  k.push_back({"sse2", "SSE2", sse2::simplified_ti_steps<Sys>});
  return k;
}

template std::vector<LanesKernel<LennardJones<9>>> simplified_ti_lanes_kernels();
template std::vector<LanesKernel<HenonHeilesT<true>>> simplified_ti_lanes_kernels();
template std::vector<LanesKernel<HenonHeilesT<false>>> simplified_ti_lanes_kernels();

}  // namespace geomint
