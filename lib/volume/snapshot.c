/* The SPH volume's part of a sim snapshot (snapshot.h). */
#include <limits.h>
#include <math.h>
#include <stddef.h>
#include <stdatomic.h>
#include <string.h>

#include "volume/snapshot.h"
#include "volume/volume_internal.h"

/* Per-particle state carried from one sub-step to the next, in cell order:
 * a new array (a solver's warm start) is one line here. */
static const struct {
    const char *name;
    size_t offset; /* of the array's pointer in ms_volume */
    size_t elem;   /* bytes per particle */
} per_particle[] = {
    {"vol.x", offsetof(ms_volume, x), sizeof(float)},
    {"vol.y", offsetof(ms_volume, y), sizeof(float)},
    {"vol.z", offsetof(ms_volume, z), sizeof(float)},
    {"vol.vx", offsetof(ms_volume, vx), sizeof(float)},
    {"vol.vy", offsetof(ms_volume, vy), sizeof(float)},
    {"vol.vz", offsetof(ms_volume, vz), sizeof(float)},
    {"vol.id", offsetof(ms_volume, id), sizeof(int)},
};

static void *array_at(ms_volume *v, size_t offset)
{
    void *p;
    memcpy(&p, (char *)v + offset, sizeof p);
    return p;
}

static ms_status wave_io(ms_volume *v, ms_blob *b)
{
    ms_status st;
    if ((st = MS_BLOB_IO(b, "vol.wave_valid", v->wave_valid)) ||
        (st = MS_BLOB_IO(b, "vol.wave_grid", v->wave_grid)) ||
        (st = ms_blob_double(b, "vol.wave_time", &v->wave_time, 0.0, 1e12, "s")))
        return st;
    if (b->reading && (st = ms_blob_check_int("vol.wave_valid", v->wave_valid, 0, 1)))
        return st;
    size_t cells = v->wave_valid ? (size_t)v->wave_grid.nx * (size_t)v->wave_grid.ny : 0;
    if (b->reading && v->wave_valid) {
        const ms_grid *g = &v->wave_grid;
        if (g->nx < 1 || g->ny < 1 || g->nx > 1 << 16 || g->ny > 1 << 16)
            return ms_fail(MS_ERR_INVALID_ARGUMENT,
                           "snapshot: a coupling wave grid of %d x %d cells, outside [1, %d] "
                           "each way",
                           g->nx, g->ny, 1 << 16);
        if (!(g->dx > 0) || !(g->dy > 0) || !isfinite(g->dx) || !isfinite(g->dy) ||
            !isfinite(g->origin[0]) || !isfinite(g->origin[1]))
            return ms_fail(MS_ERR_INVALID_ARGUMENT,
                           "snapshot: a coupling wave grid of cells %g x %g m at (%g, %g) m; "
                           "cells must be finite and > 0, the origin finite",
                           (double)g->dx, (double)g->dy, (double)g->origin[0],
                           (double)g->origin[1]);
        /* the count must be backed by the record before it is allocated */
        if ((st = ms_blob_expect(b, "vol.wave_prev", cells * sizeof(float))))
            return st;
        if (cells > v->wave_cap) {
            float *p = ms_alloc_array(cells, sizeof(float));
            if (!p)
                return ms_fail(MS_ERR_OUT_OF_MEMORY, "volume: out of memory restoring waves");
            ms_free(v->wave_prev);
            v->wave_prev = p;
            v->wave_cap = cells;
        }
    }
    return ms_blob_floats(b, "vol.wave_prev", v->wave_prev, cells, -INFINITY, INFINITY, "");
}

/* The particles' ids must be a permutation of 0 .. n-1: the copy to the
 * published arrays (ms_volume_copy_particles) and the warm start write
 * through them. A refused set is replaced by 0 .. n-1, so that nothing
 * that still reads the volume writes out of bounds. */
static ms_status check_ids(ms_volume *v)
{
    const int n = v->n;
    unsigned char *seen = ms_alloc_array((size_t)n + 1, 1);
    if (!seen)
        return ms_fail(MS_ERR_OUT_OF_MEMORY, "volume: out of memory checking %d particle ids", n);
    ms_status st = MS_OK;
    for (int i = 0; i < n && st == MS_OK; ++i) {
        const int k = v->id[i];
        if (k < 0 || k >= n)
            st = ms_fail(MS_ERR_INVALID_ARGUMENT,
                         "snapshot: particle %d has id %d, outside [0, %d] (ids number the %d "
                         "particles)",
                         i, k, n - 1, n);
        else if (seen[k]++)
            st = ms_fail(MS_ERR_INVALID_ARGUMENT,
                         "snapshot: particle %d has id %d, which another particle has too (ids "
                         "must be 0 .. %d once each)",
                         i, k, n - 1);
    }
    ms_free(seen);
    if (st != MS_OK)
        for (int i = 0; i < n; ++i)
            v->id[i] = i;
    return st;
}

/* Particle positions in the domain widened by its own extent each way:
 * the walls keep particles inside it (collide.c), and the neighbour grid
 * and the extraction turn positions into cell numbers. */
static ms_status check_positions(const ms_volume *v, const char *const names[3],
                                 const float *const xyz[3], size_t n)
{
    ms_status st = MS_OK;
    for (int a = 0; a < 3 && st == MS_OK; ++a) {
        const double lo = v->desc.domain_min[a], hi = v->desc.domain_max[a], ext = hi - lo;
        st = ms_blob_check_floats(names[a], xyz[a], n, lo - ext, hi + ext, "m");
    }
    return st;
}

static ms_status check_actions(const ms_action *a, int n)
{
    for (int i = 0; i < n; ++i) {
        ms_status st;
        if ((st = ms_blob_check_int("vol.actions kind", a[i].kind, MS_ACTION_DRAG,
                                    MS_ACTION_PUSH)) ||
            (st = ms_blob_check_floats("vol.actions centre", a[i].centre, 3, -INFINITY, INFINITY,
                                       "m")) ||
            (st =
                 ms_blob_check_floats("vol.actions radius", &a[i].radius, 1, 0.0, INFINITY, "m")) ||
            (st = ms_blob_check_floats("vol.actions vec", a[i].vec, 3, -INFINITY, INFINITY, "")) ||
            (st = ms_blob_check_floats("vol.actions strength", &a[i].strength, 1, -INFINITY,
                                       INFINITY, "1/s")))
            return st;
    }
    return MS_OK;
}

ms_status ms_volume_snapshot_io(ms_volume *v, ms_blob *b, int *recount)
{
    int n = v->n, ncol = v->ncolliders, counted = v->counts_valid;
    ms_status st;
    if ((st = ms_blob_count(b, "vol.n", &n, v->desc.max_particles)) ||
        (st = ms_blob_count(b, "vol.ncolliders", &ncol, MS_VOLUME_MAX_COLLIDERS)))
        return st;
    if (b->reading && ncol != v->ncolliders)
        return ms_fail(MS_ERR_INVALID_ARGUMENT,
                       "snapshot: a volume with %d colliders, this sim's has %d", ncol,
                       v->ncolliders);
    if (b->reading) {
        if ((st = ms_blob_expect(b, per_particle[0].name, (size_t)n * per_particle[0].elem)) ||
            (st = ms_volume_reserve(v, n)) != MS_OK)
            return st;
        v->n = n;
        v->counts_valid = 0;
    }
    for (size_t k = 0; k < sizeof per_particle / sizeof per_particle[0]; ++k)
        if ((st = ms_blob_io(b, per_particle[k].name, array_at(v, per_particle[k].offset),
                             (size_t)n * per_particle[k].elem)))
            return st;
    if (b->reading) {
        static const char *const pn[3] = {"vol.x", "vol.y", "vol.z"};
        const float *const pos[3] = {v->x, v->y, v->z};
        if ((st = check_ids(v)) || (st = check_positions(v, pn, pos, (size_t)n)) ||
            (st = ms_blob_check_floats("vol.vx", v->vx, (size_t)n, -INFINITY, INFINITY, "m/s")) ||
            (st = ms_blob_check_floats("vol.vy", v->vy, (size_t)n, -INFINITY, INFINITY, "m/s")) ||
            (st = ms_blob_check_floats("vol.vz", v->vz, (size_t)n, -INFINITY, INFINITY, "m/s")))
            return st;
    }
    /* DFSPH's warm start (dfsph.c): the last density solve's totals by
     * particle id (ids are 0 .. n-1) and the sub-step they were solved for */
    if ((st = MS_BLOB_IO(b, "vol.df_warm_n", v->df_warm_n)) ||
        (st = MS_BLOB_FINITE(b, "vol.df_warm_dt", v->df_warm_dt)) ||
        (st = ms_blob_floats(b, "vol.df_warm", v->df_warm, (size_t)n, -INFINITY, INFINITY, "")))
        return st;
    long steps = v->steps, substeps = v->substeps;
    if ((st = ms_blob_double(b, "vol.time", &v->time, 0.0, 1e12, "s")) ||
        (st = MS_BLOB_IO(b, "vol.steps", steps)) ||
        (st = MS_BLOB_IO(b, "vol.substeps", substeps)) ||
        (st = ms_blob_floats(b, "vol.last_dt", &v->last_dt, 1, 0.0, 1e6, "s")) ||
        (st = ms_blob_floats(b, "vol.max_dt", &v->max_dt, 1, 0.0, 1e6, "s")) ||
        /* the range ms_volume_set_viscosity and the desc allow */
        (st = ms_blob_floats(b, "vol.viscosity", &v->desc.viscosity, 1, 0.0, 1e6, "Pa s")) ||
        (st = MS_BLOB_FINITE(b, "vol.col_expect", v->col_expect)) ||
        (st = MS_BLOB_IO(b, "vol.col_valid", v->col_expect_valid)) ||
        (st = MS_BLOB_FINITE(b, "vol.col_vel", v->col_vel)) ||
        (st = MS_BLOB_FINITE(b, "vol.col_jump", v->col_jump)) ||
        (st = MS_BLOB_FINITE(b, "vol.col_end", v->col_end)))
        return st;
    if (b->reading) {
        if ((st = ms_blob_check_int("vol.df_warm_n", v->df_warm_n, -1, n)) ||
            (st = ms_blob_check_int("vol.steps", steps, 0, LONG_MAX)) ||
            (st = ms_blob_check_int("vol.substeps", substeps, 0, LONG_MAX)))
            return st;
        v->steps = steps;
        v->substeps = substeps;
        for (int c = 0; c < MS_VOLUME_MAX_COLLIDERS; ++c)
            if ((st = ms_blob_check_int("vol.col_valid", v->col_expect_valid[c], 0, 1)))
                return st;
    }
    int na = v->nactions;
    if ((st = ms_blob_count(b, "vol.nactions", &na, MS_VOLUME_MAX_ACTIONS)) ||
        (st = ms_blob_io(b, "vol.actions", v->actions, (size_t)na * sizeof v->actions[0])))
        return st;
    if (b->reading) {
        if ((st = check_actions(v->actions, na)))
            return st;
        v->nactions = na;
    }
    if ((st = wave_io(v, b)) != MS_OK || (st = MS_BLOB_IO(b, "vol.counted", counted)))
        return st;
    if (b->reading) {
        *recount = counted != 0;
        atomic_store(&v->cancel, 0); /* a cancel left over from before the restore */
        ms_volume_publish(v);
    }
    return MS_OK;
}

ms_status ms_volume_snapshot_check_extract(const ms_volume *v, const ms_extract_snap *s, int fresh)
{
    /* before the first step no slot is filled: they hold zeros (the first
     * step fills both before either is extracted, and phase B must never
     * see a zero domain or radius) */
    const int unfilled = fresh && s->m == 0 && s->n_all == 0 && s->R == 0.0f &&
                         s->spacing == 0.0f && s->smooth_steps == 0 && s->smooth_energy == 0.0f &&
                         s->iso == 0.0f;
    ms_status st;
    if ((st = ms_blob_check_int("sim.x.empty", s->empty, 0, 1)) ||
        (st = ms_blob_check_int("sim.x.m", s->m, 0, v->desc.max_particles)) ||
        (st = ms_blob_check_int("sim.x.n", s->n_all, s->m, v->desc.max_particles)))
        return st;
    if (!isfinite(s->e) || s->e < 0)
        return ms_fail(MS_ERR_INVALID_ARGUMENT,
                       "snapshot: record 'sim.x.e' is %g J/kg; a kinetic energy is finite and "
                       ">= 0",
                       s->e);
    static const char *const pn[3] = {"sim.x.x", "sim.x.y", "sim.x.z"};
    const float *const pos[3] = {s->x, s->y, s->z};
    if ((st = check_positions(v, pn, pos, (size_t)s->n_all)))
        return st;
    if (unfilled)
        return MS_OK;
    /* The constants the extraction runs with (its radius, spacing,
     * smoothing passes bound its work) are this volume's, as
     * ms_volume_extract_snap copies them: the snapshot's hash says the
     * desc is the same, so any other value is forged. */
    const struct {
        const char *what;
        double have, want;
        const char *unit;
    } c[] = {
        {"extraction radius R", s->R, v->K.h, "m"},
        {"extraction spacing", s->spacing, v->desc.spacing, "m"},
        {"extraction smoothing passes", s->smooth_steps, v->desc.smooth_steps, ""},
        {"extraction smoothing energy", s->smooth_energy, v->desc.smooth_energy, "J/kg"},
        {"extraction iso-level", s->iso, v->iso_level, ""},
        {"extraction domain min x", s->lo[0], v->desc.domain_min[0], "m"},
        {"extraction domain min y", s->lo[1], v->desc.domain_min[1], "m"},
        {"extraction domain min z", s->lo[2], v->desc.domain_min[2], "m"},
        {"extraction domain max x", s->hi[0], v->desc.domain_max[0], "m"},
        {"extraction domain max y", s->hi[1], v->desc.domain_max[1], "m"},
        {"extraction domain max z", s->hi[2], v->desc.domain_max[2], "m"},
    };
    for (size_t i = 0; i < sizeof c / sizeof c[0]; ++i)
        if (memcmp(&c[i].have, &c[i].want, sizeof(double)) != 0) {
            /* a count of passes is printed as the integer it is */
            const int whole = c[i].have == floor(c[i].have) && fabs(c[i].have) < 1e15;
            return ms_fail(MS_ERR_INVALID_ARGUMENT,
                           whole ? "snapshot: %s %.0f%s%s, this sim's volume has %g%s%s (a "
                                   "forged or damaged snapshot)"
                                 : "snapshot: %s %g%s%s, this sim's volume has %g%s%s (a "
                                   "forged or damaged snapshot)",
                           c[i].what, c[i].have, *c[i].unit ? " " : "", c[i].unit, c[i].want,
                           *c[i].unit ? " " : "", c[i].unit);
        }
    return MS_OK;
}

ms_status ms_volume_snapshot_recount(ms_volume *v)
{
    ms_volume_grid_build(v); /* a stable sort of particles already in cell order */
    return ms_volume_count_neighbours(v);
}

uint64_t ms_volume_snapshot_hash(const ms_volume *v, uint64_t h)
{
    ms_volume_desc d = v->desc;
    d.viscosity = 0.0f; /* state, not identity: ms_volume_set_viscosity */
    d.threads = 0;      /* any count gives the same bytes */
    d.max_substeps = 0;
    d.max_particles = 0;
    return ms_blob_hash(h, &d, sizeof d);
}

int ms_volume_snapshot_max_particles(const ms_volume *v)
{
    return v->desc.max_particles;
}
