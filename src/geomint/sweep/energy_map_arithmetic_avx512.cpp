// energy_map_arithmetic.inc for AVX-512 (compiled with -mavx512f -mfma: CMakeLists.txt).
#include <immintrin.h>

#include <cstdint>

namespace geomint {
namespace {
using V = __m512d;
constexpr int kChains = 16;  // twice the FMA latency (4) times the two FMA ports: no chain waits
struct C { V half, one, zero; __m512i ones; };
inline C constants() {
  C c{_mm512_set1_pd(0.5), _mm512_set1_pd(1.0), _mm512_setzero_pd(), _mm512_set1_epi64(-1)};
  asm volatile("" : "+v"(c.half), "+v"(c.one), "+v"(c.zero), "+v"(c.ones));
  return c;
}
inline V start(double x) { return _mm512_set1_pd(x); }
inline double first_lane(V a) { return _mm512_cvtsd_f64(a); }
inline V op_fma(V a, const C& c) { return _mm512_fmadd_pd(a, c.half, c.one); }
inline V op_add(V a, const C& c) { return _mm512_add_pd(a, c.zero); }
inline V op_minmax(V a, const C& c) { return _mm512_maskz_max_pd(0xFF, a, c.zero); }  // (maskz: see op_rsqrt)
inline V op_logic(V a, const C& c) { return _mm512_castsi512_pd(_mm512_and_epi64(_mm512_castpd_si512(a), c.ones)); }
inline V op_rsqrt(V a, const C&) { return _mm512_maskz_rsqrt14_pd(0xFF, a); }  // (maskz: no undefined source)
inline V op_div(V a, const C& c) { return _mm512_div_pd(c.one, a); }
}  // namespace
}  // namespace geomint

#define GEOMINT_ARITHMETIC_FN energy_map_arithmetic_avx512
#define GEOMINT_MIX_CARTESIAN kAvx512Cartesian
#define GEOMINT_MIX_POLAR kAvx512Polar
#include "geomint/sweep/energy_map_arithmetic.inc"
