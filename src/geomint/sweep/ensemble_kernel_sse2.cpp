// The ensemble lane kernels built for SSE2 (flags in CMakeLists.txt).
#define GEOMINT_LANES_ISA sse2
#define GEOMINT_LANES_WIDTH 2
#include "geomint/sweep/ensemble_kernel.inc"
