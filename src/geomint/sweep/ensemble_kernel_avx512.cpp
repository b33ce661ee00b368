// The ensemble lane kernels built for AVX-512 (flags in CMakeLists.txt).
#define GEOMINT_LANES_ISA avx512
#define GEOMINT_LANES_WIDTH 8
#include "geomint/sweep/ensemble_kernel.inc"
