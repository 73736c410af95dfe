/* The wave field's part of a sim snapshot (snapshot.h): every
 * piece of state the leapfrog step of eq. 2 reads, so that a restored
 * surface steps to the same bytes as one never stopped. */
#include <limits.h>
#include <math.h>
#include <stdatomic.h>
#include <string.h>

#include "surface/snapshot.h"
#include "surface/surface_internal.h"

/* A padded field that may be absent (a map never set): 0 bytes. */
static ms_status opt_plane(ms_blob *b, const char *name, void **field, size_t bytes)
{
    size_t have = *field ? bytes : 0;
    ms_status st = ms_blob_peek(b, name, &have);
    if (st != MS_OK)
        return st;
    if (b->reading && have == 0) {
        ms_free(*field);
        *field = NULL;
    } else if (b->reading && !*field && have == bytes && !(*field = ms_malloc(bytes))) {
        return ms_fail(MS_ERR_OUT_OF_MEMORY, "surface: out of memory restoring '%s'", name);
    }
    return ms_blob_io(b, name, *field, have);
}

static ms_status disturbers_io(ms_surface *s, ms_blob *b)
{
    int n = s->ndist;
    ms_status st = ms_blob_count(b, "sf.ndist", &n, 1 << 20);
    if (st != MS_OK)
        return st;
    /* each disturber is 7 records of at least a 24-byte head: a count the
     * blob cannot hold is refused before it is allocated */
    if (b->reading && (size_t)n * 7 * 24 > b->len - b->pos)
        return ms_fail(MS_ERR_INVALID_ARGUMENT,
                       "snapshot: record 'sf.ndist' is %d disturbers, more than the %zu bytes "
                       "left in the blob hold",
                       n, b->len - b->pos);
    if (b->reading && n > s->cap_dist) {
        disturber *nd = ms_realloc(s->dist, (size_t)n * sizeof *nd);
        if (!nd)
            return ms_fail(MS_ERR_OUT_OF_MEMORY, "surface: out of memory restoring %d disturbers",
                           n);
        memset(nd + s->cap_dist, 0, (size_t)(n - s->cap_dist) * sizeof *nd);
        s->dist = nd;
        s->cap_dist = n;
    }
    if (b->reading) {
        for (int i = n; i < s->ndist; ++i) {
            ms_free(s->dist[i].path);
            s->dist[i].path = NULL;
        }
        for (int i = s->ndist; i < n; ++i)
            memset(&s->dist[i], 0, sizeof s->dist[i]);
        s->ndist = n;
    }
    for (int i = 0; st == MS_OK && i < n; ++i) {
        disturber *d = &s->dist[i];
        int np = d->npath;
        if ((st = MS_BLOB_IO(b, "sf.d.id", d->id)) || (st = MS_BLOB_IO(b, "sf.d.desc", d->d)) ||
            (st = MS_BLOB_IO(b, "sf.d.loop", d->loop)) ||
            (st = MS_BLOB_IO(b, "sf.d.speed", d->path_speed)) ||
            (st = MS_BLOB_IO(b, "sf.d.s", d->path_s)) ||
            (st = ms_blob_count(b, "sf.d.npath", &np, 1 << 20)))
            break;
        if (b->reading) {
            /* the ranges ms_surface_add_disturber and _set_disturber_path
             * check (disturber.c) */
            if ((st = ms_blob_check_int("sf.d.id", d->id, 0, INT_MAX)) ||
                (d->id != 0 && (st = ms_surface_check_disturber(s, &d->d))) ||
                (st = ms_blob_check_floats("sf.d.speed", &d->path_speed, 1, 0, 1e4, "m/s")) ||
                (st = ms_blob_expect(b, "sf.d.path", (size_t)np * 2 * sizeof(float))))
                break;
            if (!isfinite(d->path_s) || d->path_s < 0) {
                st = ms_fail(MS_ERR_INVALID_ARGUMENT,
                             "snapshot: record 'sf.d.s' is %g m along a path; it must be finite "
                             "and >= 0",
                             d->path_s);
                break;
            }
        }
        if (b->reading && np != d->npath) {
            ms_free(d->path);
            d->path = np ? ms_malloc((size_t)np * 2 * sizeof(float)) : NULL;
            d->npath = d->path ? np : 0;
            d->path_cap = d->npath;
            if (np && !d->path)
                return ms_fail(MS_ERR_OUT_OF_MEMORY, "surface: out of memory restoring a path");
        }
        st = ms_blob_floats(b, "sf.d.path", d->path, (size_t)np * 2, -INFINITY, INFINITY, "m");
    }
    return st;
}

ms_status ms_surface_snapshot_io(ms_surface *s, ms_blob *b)
{
    int dims[3] = {s->nx, s->ny, s->stride};
    const size_t fb = s->plane * sizeof(float);
    ms_status st;
    if ((st = ms_blob_io(b, "sf.dims", dims, sizeof dims)))
        return st;
    if (b->reading && (dims[0] != s->nx || dims[1] != s->ny || dims[2] != s->stride))
        return ms_fail(MS_ERR_INVALID_ARGUMENT,
                       "snapshot: a wave grid of %d x %d (row stride %d), this sim's is %d x %d "
                       "(%d)",
                       dims[0], dims[1], dims[2], s->nx, s->ny, s->stride);
    /* the fields and the coefficients as stepped (a, delta belong to coef_dt) */
    const size_t nf = s->plane;
    if ((st = ms_blob_floats(b, "sf.h", s->h, nf, -INFINITY, INFINITY, "m")) ||
        (st = ms_blob_floats(b, "sf.v", s->v, nf, -INFINITY, INFINITY, "m")) ||
        (st = ms_blob_floats(b, "sf.speed", s->speed, nf, 0, INFINITY, "m/s")) ||
        (st = ms_blob_floats(b, "sf.a", s->a, nf, -INFINITY, INFINITY, "")) ||
        (st = ms_blob_floats(b, "sf.delta", s->delta, nf, -INFINITY, INFINITY, "")))
        return st;
    /* maps set at run time */
    if ((st = opt_plane(b, "sf.speed_map", (void **)&s->speed_map, fb)) ||
        (st = opt_plane(b, "sf.damp_map", (void **)&s->damp_map, fb)) ||
        (st = opt_plane(b, "sf.solid", (void **)&s->solid, s->plane)))
        return st;
    /* the maps' ranges (ms_surface_set_speed_map, _set_damping_map; the
     * padding holds zeros) */
    if (b->reading &&
        ((s->speed_map &&
          (st = ms_blob_check_floats("sf.speed_map", s->speed_map, nf, 0, INFINITY, "m/s"))) ||
         (s->damp_map && (st = ms_blob_check_floats("sf.damp_map", s->damp_map, nf, 0, 1, "")))))
        return st;
    ms_rain rain = s->rain;
    if ((st = ms_blob_floats(b, "sf.coef_dt", &s->coef_dt, 1, 0, 10, "s")) ||
        (st = ms_blob_floats(b, "sf.max_speed", &s->max_speed, 1, 0, INFINITY, "m/s")) ||
        (st = ms_blob_floats(b, "sf.v_dt", &s->v_dt, 1, 0, 10, "s")) ||
        (st = ms_blob_double(b, "sf.time", &s->time, 0, 1e12, "s")) ||
        (st = MS_BLOB_IO(b, "sf.substeps", s->substeps)) ||
        (st = MS_BLOB_IO(b, "sf.drops", s->drops)) || (st = MS_BLOB_IO(b, "sf.rng", s->rng)) ||
        (st = MS_BLOB_IO(b, "sf.rain", rain)) || (st = MS_BLOB_IO(b, "sf.next_id", s->next_id)))
        return st;
    if (b->reading) {
        /* rain bounds the drops a step draws: the checks and the cap of
         * ms_surface_set_rain; rate 0 is no rain */
        if ((st = ms_blob_check_int("sf.substeps", s->substeps, 0, LONG_MAX)) ||
            (st = ms_blob_check_int("sf.drops", s->drops, 0, LONG_MAX)) ||
            (st = ms_blob_check_int("sf.next_id", s->next_id, 0, INT_MAX)) ||
            (rain.rate != 0 && (st = ms_surface_check_rain(s, &rain))))
            return st;
    }
    s->rain = rain;
    s->uniform = -1; /* a and delta as read: wave.c looks again */
    /* the dispersive model's bands follow the speeds as read; its symbols
     * are rebuilt at the next step */
    if (b->reading && s->disp && (st = ms_surface_dispersive_bands(s)))
        return st;
    if ((st = disturbers_io(s, b)))
        return st;
    if (b->reading) {
        s->view_dirty = 1;
        atomic_store(&s->cancel, 0); /* a cancel left over from before the restore */
    }
    return MS_OK;
}

uint64_t ms_surface_snapshot_hash(const ms_surface *s, uint64_t h)
{
    const ms_surface_desc *d = &s->desc;
    h = ms_blob_hash(h, &d->nx, sizeof d->nx);
    h = ms_blob_hash(h, &d->ny, sizeof d->ny);
    h = ms_blob_hash(h, &d->dx, sizeof d->dx);
    h = ms_blob_hash(h, &d->wave_speed, sizeof d->wave_speed);
    h = ms_blob_hash(h, &d->damping, sizeof d->damping);
    h = ms_blob_hash(h, &d->boundary, sizeof d->boundary);
    if (d->model != MS_SURFACE_MODEL_WAVE) { /* eq. 2's snapshots keep their hash */
        h = ms_blob_hash(h, &d->model, sizeof d->model);
        h = ms_blob_hash(h, &d->gravity, sizeof d->gravity);
        h = ms_blob_hash(h, &d->surface_tension, sizeof d->surface_tension);
    }
    return h;
}
