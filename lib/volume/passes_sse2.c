/* The lane passes (passes.c) compiled for SSE2: the Makefile gives this
 * file that instruction set's flags. Empty on other targets. MS_LANE_ISA
 * is set before any header includes lane.h. */
#if defined(__x86_64__)
#define MS_LANE_ISA MS_LANE_ISA_SSE2
#include "volume/passes.c"
#else
typedef int ms_volume_passes_sse2_unused; /* ISO C: no empty file */
#endif
