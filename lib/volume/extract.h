/* The free-surface extraction (extract.c, eqs. 16-18) in two phases, for
 * the two-core pipeline of lib/sim (paper Fig. 8). Internal, not MS_API.
 *
 * Phase A (ms_volume_extract_snap) needs the volume's neighbour lists and
 * runs where the volume is stepped: it marks the surface particles and
 * their neighbours and copies what the columns need into a snapshot (the
 * marked particles' positions in the stable particle order, E_kin / mass
 * for eq. 18 and the constants). Phase B (ms_extract_field) is a pure
 * function of the snapshot and its own scratch and may run on any thread:
 * the column search (eqs. 16, 17) and the eq. 18 smoothing.
 * ms_volume_extract_height is A then B; any split gives the same bytes.
 */
#ifndef MS_VOLUME_EXTRACT_H
#define MS_VOLUME_EXTRACT_H

#include <stddef.h>

#include "modesplit/volume.h"

typedef struct ms_vpool ms_vpool;

typedef struct ms_extract_snap {
    int empty;           /* the volume held no particle: the field is 0 */
    int m, cap;          /* marked particles, capacity of x, y, z */
    int n_all;           /* all the particles: x, y, z hold the m marked ones
                            (stable order of the volume), then the others */
    float *x, *y, *z;    /* m */
    double e;            /* J/kg, E_kin / total mass about the mean velocity (eq. 18) */
    float iso;           /* T, the iso-level of phi (eq. 16) */
    float R;             /* m, iso-radius = h */
    float spacing;       /* m */
    float lo[3], hi[3];  /* m, the domain */
    int smooth_steps;    /* eq. 18 */
    float smooth_energy; /* J/kg, eq. 18 */
    int isa;             /* MS_VOLUME_ISA_*: phase B's gather (any gives the same bytes) */
    int reference;       /* 1: the root search of 663cc3c (bracket to 1/256 of a spacing),
                          * the yardstick of bench_extract and test_volume; 0: secant */
    float *cells;        /* phase A's scratch: 2 floats a cell of the volume's grid */
    size_t cells_cap;
} ms_extract_snap;

/* Phase B's scratch (one per thread that runs it). */
typedef struct ms_extract_work {
    int *start, *list;
    size_t start_cap, list_cap;
    float *buf, *cell; /* cell: ms_extract_cell's rectangle */
    size_t buf_cap, cell_cap;
    /* the columns searched again over every particle (extract.c) */
    float *vtop, *vbuf;
    int *vstart, *vlist;
    size_t vtop_cap, vbuf_cap, vstart_cap, vlist_cap;
} ms_extract_work;

/* Phase A: the snapshot of v at its current positions (rebuilds the
 * neighbour counts if the positions moved since the last density pass). */
ms_status ms_volume_extract_snap(ms_volume *v, ms_extract_snap *s);
/* Phase A's first part alone: the neighbour pass (grid, boundary terms,
 * lists, counts and density) at the current positions if they moved since
 * the last, as ms_volume_extract_snap would run it. *for_step: 1 if it ran
 * and the next ms_volume_step may start from it (its first sub-step's own
 * pass, ms_volume_take_counted_pass: no collider jumped), so the sim times
 * it with the SPH step, where it would run without the extraction. */
ms_status ms_volume_extract_counts(ms_volume *v, int *for_step);
/* Phase B: the nx x ny height field of s into out (m above lo[2]); the
 * columns are split over pool's threads (NULL: the calling thread). */
ms_status ms_extract_field(const ms_extract_snap *s, ms_extract_work *w, ms_vpool *pool, int nx,
                           int ny, float *out);
/* Cell (i, j) of that field alone, bit for bit the same value: only the
 * columns within the smoothing passes of it. */
ms_status ms_extract_cell(const ms_extract_snap *s, ms_extract_work *w, int nx, int ny, int i,
                          int j, float *out);
/* The volume's worker threads, for phase B while the volume rests. */
ms_vpool *ms_volume_extract_pool(ms_volume *v);
/* Work sharing: a volume of one thread (threads 1, NULL pool)
 * gets a shared pool of MS_VPOOL_SHARED_PARTS chunks per loop and no
 * threads of its own; another thread helps with the chunks while it has nothing else to do:
 * ms_vpool_help runs chunks as they come until ms_vpool_help_close (the
 * thread that runs the volume opens and closes). The same bytes as one
 * thread. With the engine's tasks (ms_volume_set_tasks) each loop also
 * enqueues one engine task that claims chunks the same way. */
ms_status ms_volume_share_loops(ms_volume *v);
#define MS_VPOOL_SHARED_PARTS 8  /* pool.c: claimed from both ends */
#define MS_VPOOL_SHARED_MIN 1024 /* shorter loops run on the calling thread */
void ms_vpool_help_open(ms_vpool *p);
void ms_vpool_help(ms_vpool *p);
void ms_vpool_help_close(ms_vpool *p);
/* The particles' positions and velocities (m, m/s) in the stable order
 * (particle k at index k, as ms_volume_get_particles), one array an axis:
 * pos[a] and vel[a] each hold the volume's count. The sim's copies take
 * them from here in one pass, with no interleaved block between. */
void ms_volume_copy_particles(const ms_volume *v, float *const pos[3], float *const vel[3]);
void ms_extract_snap_free(ms_extract_snap *s);
void ms_extract_work_free(ms_extract_work *w);
size_t ms_extract_snap_bytes(const ms_extract_snap *s);
size_t ms_extract_work_bytes(const ms_extract_work *w);

#endif /* MS_VOLUME_EXTRACT_H */
