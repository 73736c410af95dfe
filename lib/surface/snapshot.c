/* The wave field's part of a sim snapshot (snapshot.h): every
 * piece of state the leapfrog step of eq. 2 reads, so that a restored
 * surface steps to the same bytes as one never stopped. */
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
            (st = ms_blob_count(b, "sf.d.npath", &np, 1 << 24)))
            break;
        if (b->reading && np != d->npath) {
            ms_free(d->path);
            d->path = np ? ms_malloc((size_t)np * 2 * sizeof(float)) : NULL;
            d->npath = d->path ? np : 0;
            if (np && !d->path)
                return ms_fail(MS_ERR_OUT_OF_MEMORY, "surface: out of memory restoring a path");
        }
        st = ms_blob_io(b, "sf.d.path", d->path, (size_t)np * 2 * sizeof(float));
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
    if ((st = ms_blob_io(b, "sf.h", s->h, fb)) || (st = ms_blob_io(b, "sf.v", s->v, fb)) ||
        (st = ms_blob_io(b, "sf.speed", s->speed, fb)) || (st = ms_blob_io(b, "sf.a", s->a, fb)) ||
        (st = ms_blob_io(b, "sf.delta", s->delta, fb)))
        return st;
    /* maps set at run time */
    if ((st = opt_plane(b, "sf.speed_map", (void **)&s->speed_map, fb)) ||
        (st = opt_plane(b, "sf.damp_map", (void **)&s->damp_map, fb)) ||
        (st = opt_plane(b, "sf.solid", (void **)&s->solid, s->plane)))
        return st;
    if ((st = MS_BLOB_IO(b, "sf.coef_dt", s->coef_dt)) ||
        (st = MS_BLOB_IO(b, "sf.max_speed", s->max_speed)) ||
        (st = MS_BLOB_IO(b, "sf.v_dt", s->v_dt)) || (st = MS_BLOB_IO(b, "sf.time", s->time)) ||
        (st = MS_BLOB_IO(b, "sf.substeps", s->substeps)) ||
        (st = MS_BLOB_IO(b, "sf.drops", s->drops)) || (st = MS_BLOB_IO(b, "sf.rng", s->rng)) ||
        (st = MS_BLOB_IO(b, "sf.rain", s->rain)) || (st = MS_BLOB_IO(b, "sf.next_id", s->next_id)))
        return st;
    s->uniform = -1; /* a and delta as read: wave.c looks again */
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
    return ms_blob_hash(h, &d->boundary, sizeof d->boundary);
}
