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
}  // namespace

#define GEOMINT_EM_KERNEL energy_map_kernel_avx2
#include "geomint/sweep/energy_map_kernel.inc"
