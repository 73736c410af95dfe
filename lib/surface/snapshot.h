/* The wave field's part of a sim snapshot (lib/surface/snapshot.c).
 * Internal: lib/sim/snapshot.c calls it. */
#ifndef MS_SURFACE_SNAPSHOT_H
#define MS_SURFACE_SNAPSHOT_H

#include "core/blob.h"
#include "modesplit/surface.h"

/* Write (b->reading = 0) or restore every piece of state a step reads:
 * the padded fields f^n and f^n - f^{n-1} (ghosts included: Mur's
 * absorbing boundary keeps state there), the stepped speeds and their
 * cached coefficients, the maps set at run time (speed, damping, obstacle
 * mask), the disturbers with their paths, the rain and its RNG, time and
 * counters. */
ms_status ms_surface_snapshot_io(ms_surface *s, ms_blob *b);
/* What makes two surfaces step alike (grid, speed, damping, boundary, model). */
uint64_t ms_surface_snapshot_hash(const ms_surface *s, uint64_t h);

#endif /* MS_SURFACE_SNAPSHOT_H */
