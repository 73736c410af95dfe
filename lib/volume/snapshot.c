/* The SPH volume's part of a sim snapshot (snapshot.h). */
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
        (st = MS_BLOB_IO(b, "vol.wave_time", v->wave_time)))
        return st;
    size_t cells = v->wave_valid ? (size_t)v->wave_grid.nx * (size_t)v->wave_grid.ny : 0;
    if (b->reading && v->wave_valid) {
        if (v->wave_grid.nx < 1 || v->wave_grid.ny < 1 || v->wave_grid.nx > 1 << 16 ||
            v->wave_grid.ny > 1 << 16)
            return ms_fail(MS_ERR_INVALID_ARGUMENT,
                           "snapshot: a coupling wave grid of %d x %d cells", v->wave_grid.nx,
                           v->wave_grid.ny);
        if (cells > v->wave_cap) {
            float *p = ms_alloc_array(cells, sizeof(float));
            if (!p)
                return ms_fail(MS_ERR_OUT_OF_MEMORY, "volume: out of memory restoring waves");
            ms_free(v->wave_prev);
            v->wave_prev = p;
            v->wave_cap = cells;
        }
    }
    return ms_blob_io(b, "vol.wave_prev", v->wave_prev, cells * sizeof(float));
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
        if ((st = ms_volume_reserve(v, n)) != MS_OK)
            return st;
        v->n = n;
        v->counts_valid = 0;
    }
    for (size_t k = 0; k < sizeof per_particle / sizeof per_particle[0]; ++k)
        if ((st = ms_blob_io(b, per_particle[k].name, array_at(v, per_particle[k].offset),
                             (size_t)n * per_particle[k].elem)))
            return st;
    /* DFSPH's warm start (dfsph.c): the last density solve's totals by
     * particle id (ids are 0 .. n-1) and the sub-step they were solved for */
    if ((st = MS_BLOB_IO(b, "vol.df_warm_n", v->df_warm_n)) ||
        (st = MS_BLOB_IO(b, "vol.df_warm_dt", v->df_warm_dt)) ||
        (st = ms_blob_io(b, "vol.df_warm", v->df_warm, (size_t)n * sizeof(float))))
        return st;
    if ((st = MS_BLOB_IO(b, "vol.time", v->time)) || (st = MS_BLOB_IO(b, "vol.steps", v->steps)) ||
        (st = MS_BLOB_IO(b, "vol.substeps", v->substeps)) ||
        (st = MS_BLOB_IO(b, "vol.last_dt", v->last_dt)) ||
        (st = MS_BLOB_IO(b, "vol.max_dt", v->max_dt)) ||
        (st = MS_BLOB_IO(b, "vol.viscosity", v->desc.viscosity)) ||
        (st = MS_BLOB_IO(b, "vol.col_expect", v->col_expect)) ||
        (st = MS_BLOB_IO(b, "vol.col_valid", v->col_expect_valid)) ||
        (st = MS_BLOB_IO(b, "vol.col_vel", v->col_vel)) ||
        (st = MS_BLOB_IO(b, "vol.col_jump", v->col_jump)) ||
        (st = MS_BLOB_IO(b, "vol.col_end", v->col_end)))
        return st;
    int na = v->nactions;
    if ((st = ms_blob_count(b, "vol.nactions", &na, MS_VOLUME_MAX_ACTIONS)) ||
        (st = ms_blob_io(b, "vol.actions", v->actions, (size_t)na * sizeof v->actions[0])))
        return st;
    if (b->reading)
        v->nactions = na;
    if ((st = wave_io(v, b)) != MS_OK || (st = MS_BLOB_IO(b, "vol.counted", counted)))
        return st;
    if (b->reading) {
        *recount = counted != 0;
        atomic_store(&v->cancel, 0); /* a cancel left over from before the restore */
        ms_volume_publish(v);
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
