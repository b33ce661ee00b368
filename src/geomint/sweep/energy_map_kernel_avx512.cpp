// The energy-map batch kernel built for avx512 (flags in CMakeLists.txt).
#define GEOMINT_EM_KERNEL energy_map_kernel_avx512
#include "geomint/sweep/energy_map_kernel.inc"
