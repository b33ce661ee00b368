// The energy-map batch kernel built for AVX2 (flags in CMakeLists.txt).
#include <immintrin.h>
#include <sleef.h>

#include "geomint/sweep/energy_map.hpp"

namespace {
void em_sincos(const double* x, double* s, double* c) {
  for (int v = 0; v < geomint::kEnergyMapBatch; v += 4) {
    const Sleef___m256d_2 r = Sleef_sincosd4_u35avx2(_mm256_load_pd(x + v));
    _mm256_store_pd(s + v, r.x), _mm256_store_pd(c + v, r.y);
  }
}
// 1/sqrt(x): AVX2 has no double estimate, so x is rounded to float for the 12-bit estimate
// vrsqrtps (relative error below 1.5 2^-12), and three Newton steps y <- y (3/2 - x/2 y^2) square
// it (2^-11.4 -> 2^-21.8 -> 2^-42.6 -> below 2^-53): mul/add only, no divider. x beyond the
// float range gives 0 (an r above 1e19) or NaN (an r below 1e-19), which the kernel treats as
// divergence; the scalar loop would find it diverged at the next step.
void em_rsqrt(const double* x, double* y) {
  const __m256d three_halves = _mm256_set1_pd(1.5), half = _mm256_set1_pd(0.5);
  for (int v = 0; v < geomint::kEnergyMapBatch; v += 4) {
    const __m256d a = _mm256_load_pd(x + v), half_a = _mm256_mul_pd(half, a);
    __m256d r = _mm256_cvtps_pd(_mm_rsqrt_ps(_mm256_cvtpd_ps(a)));
    for (int it = 0; it < 3; ++it)
      r = _mm256_mul_pd(r, _mm256_sub_pd(three_halves, _mm256_mul_pd(half_a, _mm256_mul_pd(r, r))));
    _mm256_store_pd(y + v, r);
  }
}
}  // namespace

#define GEOMINT_EM_HAS_RSQRT
#define GEOMINT_EM_KERNEL energy_map_kernel_avx2
#include "geomint/sweep/energy_map_kernel.inc"
