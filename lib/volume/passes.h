/* The SPH passes written once over the lane type (lane.h), in passes.c,
 * and compiled once per instruction set: passes.c itself is the plain-C
 * instance, passes_sse2.c, passes_avx2.c, passes_avx512.c and
 * passes_neon.c include it again under their own compiler flags
 * (Makefile). A volume runs the table of its v->isa (ms_volume_passes_of);
 * every table gives the same bytes. */
#ifndef MS_VOLUME_PASSES_H
#define MS_VOLUME_PASSES_H

#include "volume/volume_internal.h"

/* What density.c's pass gathers from its parts (one slot a part). */
typedef struct ms_density_ctx {
    ms_volume *v;
    int coincident[MS_VOLUME_MAX_THREADS];
    int surface[MS_VOLUME_MAX_THREADS];
    float max_err[MS_VOLUME_MAX_THREADS];
    double pairs[MS_VOLUME_MAX_THREADS];
} ms_density_ctx;

struct ms_dfsph_ctx;

typedef struct ms_volume_passes {
    /* Particles [b, e) of part `part`: their neighbour lists, density
     * (eq. 9), 1/rho and pressure, and the part's counts in ctx. */
    void (*density)(ms_density_ctx *ctx, int part, int b, int e);
    /* Particles [b, e) of part `part`: their accelerations (eqs. 13, 14,
     * the boundary field and gravity) and viscous rates. */
    void (*forces)(ms_volume *v, int part, int b, int e);
    /* Particles [b, e) of part `part`: one DFSPH pass of ctx->kind
     * (dfsph_pass.h). */
    void (*dfsph)(struct ms_dfsph_ctx *ctx, int part, int b, int e);
} ms_volume_passes;

/* The table of instruction set isa (MS_VOLUME_ISA_*), NULL when this
 * build has none. */
const ms_volume_passes *ms_volume_passes_of(int isa);

extern const ms_volume_passes ms_volume_passes_c;
extern const ms_volume_passes ms_volume_passes_sse2;
extern const ms_volume_passes ms_volume_passes_avx2;
extern const ms_volume_passes ms_volume_passes_avx512;
extern const ms_volume_passes ms_volume_passes_neon;

#endif
