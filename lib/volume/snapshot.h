/* The SPH volume's part of a sim snapshot (lib/volume/snapshot.c).
 * Internal: lib/sim/snapshot.c calls it. */
#ifndef MS_VOLUME_SNAPSHOT_H
#define MS_VOLUME_SNAPSHOT_H

#include "core/blob.h"
#include "modesplit/volume.h"
#include "volume/extract.h"

/* Write (b->reading = 0) or restore the state a step reads: the particles
 * in the solver's own (cell) order, which the next counting sort starts
 * from, the last sub-step's bound (the DFSPH divergence solve uses it),
 * the colliders' expected poses (eq. 15 sweeps), the wave field of the
 * coupling, pending drags, time and counters. Derived arrays (densities,
 * neighbour lists, the grid) are rebuilt by the next pass from the same
 * positions in the same order: the same bits. */
ms_status ms_volume_snapshot_io(ms_volume *v, ms_blob *b, int *recount);
/* A restored extraction snapshot (phase A of a pipeline slot, extract.h)
 * against this volume: its marked particles finite and near the domain,
 * its constants this volume's own (or, with fresh = a sim before its
 * first step, the zeros of a slot never filled). */
ms_status ms_volume_snapshot_check_extract(const ms_volume *v, const ms_extract_snap *s, int fresh);
/* After a restore that set *recount, once the colliders are where they
 * were at the snapshot: the neighbour counts the snapshot's volume held
 * (the surface particles the wave coupling moves, 3.5), rebuilt from the
 * same positions, order and colliders: the same bits. */
ms_status ms_volume_snapshot_recount(ms_volume *v);
/* What makes two volumes step alike (the desc but for threads, limits and
 * the viscosity, which a run may change and the snapshot stores). */
uint64_t ms_volume_snapshot_hash(const ms_volume *v, uint64_t h);
/* The desc's max_particles (bounds a snapshot's particle counts). */
int ms_volume_snapshot_max_particles(const ms_volume *v);

#endif /* MS_VOLUME_SNAPSHOT_H */
