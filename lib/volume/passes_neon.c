/* The lane passes (passes.c) compiled for NEON: the Makefile gives this
 * file that instruction set's flags. Empty on other targets. MS_LANE_ISA
 * is set before any header includes lane.h. */
#if defined(__aarch64__)
#define MS_LANE_ISA MS_LANE_ISA_NEON
#include "volume/passes.c"
#else
typedef int ms_volume_passes_neon_unused; /* ISO C: no empty file */
#endif
