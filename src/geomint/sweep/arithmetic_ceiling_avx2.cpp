// arithmetic_ceiling.inc for AVX2 (compiled with -mavx2 -mfma: CMakeLists.txt).
#include <immintrin.h>

namespace geomint {
namespace {
using V = __m256d;
constexpr int kChains = 10;  // more than the FMA latency (4) times the two FMA ports; with the constants, 15 registers
inline V op_fma(V a, V half, V one) { return _mm256_fmadd_pd(a, half, one); }
inline V op_minmax(V a, V zero) { return _mm256_max_pd(a, zero); }
inline V op_logic(V a, V ones) { return _mm256_and_pd(a, ones); }
inline V op_estimate(V a) { return _mm256_cvtps_pd(_mm_rsqrt_ps(_mm256_cvtpd_ps(a))); }  // as the kernel: via single precision
}  // namespace
}  // namespace geomint

#define GEOMINT_ISSUE_FN issue_mix_avx2
#define GEOMINT_MIXES kAvx2Mixes
#include "geomint/sweep/arithmetic_ceiling.inc"
