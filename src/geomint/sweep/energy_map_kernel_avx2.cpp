// The energy-map batch kernel built for avx2 (flags in CMakeLists.txt).
#define GEOMINT_EM_KERNEL energy_map_kernel_avx2
#include "geomint/sweep/energy_map_kernel.inc"
