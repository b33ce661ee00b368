// The energy-map batch kernel built for SSE2, the portable fallback (flags in CMakeLists.txt).
#include <emmintrin.h>
#include <sleef.h>

#include "geomint/sweep/energy_map.hpp"

namespace {
void em_sincos(const double* x, double* s, double* c) {
  for (int v = 0; v < geomint::kEnergyMapBatch; v += 2) {
    const Sleef___m128d_2 r = Sleef_sincosd2_u35sse2(_mm_load_pd(x + v));
    _mm_store_pd(s + v, r.x), _mm_store_pd(c + v, r.y);
  }
}
}  // namespace

#define GEOMINT_EM_KERNEL energy_map_kernel_sse2
#include "geomint/sweep/energy_map_kernel.inc"
