// arithmetic_ceiling.inc for AVX-512 (compiled with -mavx512f -mfma: CMakeLists.txt).
#include <immintrin.h>

namespace geomint {
namespace {
using V = __m512d;
constexpr int kChains = 16;  // twice the FMA latency (4) times the two FMA ports: no chain waits
inline V op_fma(V a, V half, V one) { return _mm512_fmadd_pd(a, half, one); }
inline V op_minmax(V a, V zero) { return _mm512_maskz_max_pd(0xFF, a, zero); }  // (maskz: no undefined source)
inline V op_logic(V a, V ones) { return _mm512_castsi512_pd(_mm512_and_epi64(_mm512_castpd_si512(a), _mm512_castpd_si512(ones))); }
inline V op_estimate(V a) { return _mm512_maskz_rsqrt14_pd(0xFF, a); }
}  // namespace
}  // namespace geomint

#define GEOMINT_ISSUE_FN issue_mix_avx512
#define GEOMINT_MIXES kAvx512Mixes
#include "geomint/sweep/arithmetic_ceiling.inc"
