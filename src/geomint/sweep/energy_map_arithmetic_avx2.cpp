// energy_map_arithmetic.inc for AVX2 (compiled with -mavx2 -mfma: CMakeLists.txt).
#include <immintrin.h>

#include <cstdint>

namespace geomint {
namespace {
using V = __m256d;
constexpr int kChains = 10;  // more than the FMA latency (4) times the two FMA ports; with C and a temporary, 15 registers
struct C { V half, one, zero, ones; };
inline C constants() {
  C c{_mm256_set1_pd(0.5), _mm256_set1_pd(1.0), _mm256_setzero_pd(), _mm256_castsi256_pd(_mm256_set1_epi64x(-1))};
  asm volatile("" : "+v"(c.half), "+v"(c.one), "+v"(c.zero), "+v"(c.ones));
  return c;
}
inline V start(double x) { return _mm256_set1_pd(x); }
inline double first_lane(V a) { return _mm256_cvtsd_f64(a); }
inline V op_fma(V a, const C& c) { return _mm256_fmadd_pd(a, c.half, c.one); }
inline V op_add(V a, const C& c) { return _mm256_add_pd(a, c.zero); }
inline V op_minmax(V a, const C& c) { return _mm256_max_pd(a, c.zero); }
inline V op_logic(V a, const C& c) { return _mm256_and_pd(a, c.ones); }
inline V op_rsqrt(V a, const C&) { return _mm256_cvtps_pd(_mm_rsqrt_ps(_mm256_cvtpd_ps(a))); }
inline V op_div(V a, const C& c) { return _mm256_div_pd(c.one, a); }
}  // namespace
}  // namespace geomint

#define GEOMINT_ARITHMETIC_FN energy_map_arithmetic_avx2
#define GEOMINT_MIX_CARTESIAN kAvx2Cartesian
#define GEOMINT_MIX_POLAR kAvx2Polar
#include "geomint/sweep/energy_map_arithmetic.inc"
