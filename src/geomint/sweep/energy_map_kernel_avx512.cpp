// The energy-map batch kernel built for AVX-512 (flags in CMakeLists.txt).
#include <immintrin.h>
#include <sleef.h>

#include "geomint/sweep/energy_map.hpp"

namespace {
void em_sincos(const double* x, double* s, double* c) {
  for (int v = 0; v < geomint::kEnergyMapBatch; v += 8) {
    const Sleef___m512d_2 r = Sleef_sincosd8_u35avx512f(_mm512_load_pd(x + v));
    _mm512_store_pd(s + v, r.x), _mm512_store_pd(c + v, r.y);
  }
}
// 1/sqrt(x): the 14-bit estimate vrsqrt14pd and two Newton steps y <- y (3/2 - x/2 y^2),
// which square the relative error (2^-14 -> 2^-27 -> 2^-53): mul/add only, no divider.
// x = 0 gives NaN (the estimate is inf), which the kernel treats as divergence.
void em_rsqrt(const double* x, double* y) {
  const __m512d three_halves = _mm512_set1_pd(1.5), half = _mm512_set1_pd(0.5);
  for (int v = 0; v < geomint::kEnergyMapBatch; v += 8) {
    const __m512d a = _mm512_load_pd(x + v), half_a = _mm512_mul_pd(half, a);
    __m512d r = _mm512_maskz_rsqrt14_pd(0xFF, a);  // (maskz: no undefined source operand)
    for (int it = 0; it < 2; ++it)
      r = _mm512_mul_pd(r, _mm512_sub_pd(three_halves, _mm512_mul_pd(half_a, _mm512_mul_pd(r, r))));
    _mm512_store_pd(y + v, r);
  }
}
}  // namespace

#define GEOMINT_EM_HAS_RSQRT
#define GEOMINT_EM_KERNEL energy_map_kernel_avx512
#include "geomint/sweep/energy_map_kernel.inc"
