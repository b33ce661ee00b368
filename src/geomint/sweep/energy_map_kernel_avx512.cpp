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
}  // namespace

#define GEOMINT_EM_KERNEL energy_map_kernel_avx512
#include "geomint/sweep/energy_map_kernel.inc"
