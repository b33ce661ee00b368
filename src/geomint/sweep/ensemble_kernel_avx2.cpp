// The ensemble lane kernels built for AVX2 (flags in CMakeLists.txt).
#define GEOMINT_LANES_ISA avx2
#define GEOMINT_LANES_WIDTH 4
#include "geomint/sweep/ensemble_kernel.inc"
