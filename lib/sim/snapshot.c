/* ms_sim_snapshot / ms_sim_restore: the whole state of a sim
 * between two steps as one byte blob, so that a run continues from it
 * with the same bytes as a run never stopped (the one-frame pipeline of
 * Fig. 8 included: both slots of the hand-over buffers).
 *
 * The blob: a 72-byte header (magic "MSSNAP", header size, format version,
 * total size, a hash of what the sim was made from, a checksum of the
 * rest, the library version that wrote it), then named, size-led records
 * (core/blob.h): the sim's own state (clock, pipeline buffers, effects:
 * drops done, boat, pointer, engine's moves and turns, drags, floaters),
 * then the surface's (lib/surface/snapshot.c) and the volume's
 * (lib/volume/snapshot.c). Statistics are not state: they count what this
 * handle did.
 */
#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "core/blob.h"
#include "sim/sim_internal.h"
#include "surface/snapshot.h"
#include "volume/snapshot.h"

#define MAGIC "MSSNAP\0\0"
#define SNAP_VERSION 2u
#define VERSION_LEN 32
/* header offsets */
enum {
    H_MAGIC = 0,
    H_HEADER = 8,  /* uint32 header bytes */
    H_FORMAT = 12, /* uint32 format version */
    H_TOTAL = 16,  /* uint64 blob bytes */
    H_HASH = 24,   /* uint64 what the sim was made from */
    H_SUM = 32,    /* uint64 checksum of the records */
    H_LIBVER = 40, /* char[32] library version */
    H_SIZE = 72
};

static uint64_t sim_hash(const ms_sim *sim)
{
    uint64_t h = MS_BLOB_HASH0;
    if (sim->scene) {
        const char *t = ms_scene_text(sim->scene);
        h = ms_blob_hash(h, t, strlen(t));
    }
    const int ints[] = {
        sim->volume != NULL, sim->surface != NULL, sim->fnx,      sim->fny, sim->snx, sim->sny,
        sim->n_time_fixed,   sim->nshapes,         sim->nfloaters};
    const float floats[] = {sim->sdx,           sim->gain_sv,       sim->gain_vs,
                            sim->level,         sim->domain_min[0], sim->domain_min[1],
                            sim->domain_min[2], sim->domain_max[0], sim->domain_max[1],
                            sim->domain_max[2]};
    h = ms_blob_hash(h, ints, sizeof ints);
    h = ms_blob_hash(h, floats, sizeof floats);
    if (sim->surface)
        h = ms_surface_snapshot_hash(sim->surface, h);
    if (sim->volume)
        h = ms_volume_snapshot_hash(sim->volume, h);
    return h;
}

/* A float buffer the sim may not have (NULL): 0 bytes. Both sides hold
 * it or neither: the sims were made alike (the header's hash). */
static ms_status buf_io(ms_blob *b, const char *name, float *p, size_t count)
{
    return ms_blob_floats(b, name, p, p ? count : 0, -INFINITY, INFINITY, "");
}

/* The extraction snapshot of a slot (phase A, volume/extract.h). */
static ms_status extract_io(ms_blob *b, const ms_volume *v, ms_extract_snap *s, int max, int fresh)
{
    int m = s->m, n = s->n_all;
    ms_status st;
    if ((st = MS_BLOB_IO(b, "sim.x.empty", s->empty)) ||
        (st = ms_blob_count(b, "sim.x.m", &m, max)) || (st = ms_blob_count(b, "sim.x.n", &n, max)))
        return st;
    if (b->reading && (n < m || n > max))
        return ms_fail(MS_ERR_INVALID_ARGUMENT,
                       "sim: snapshot holds %d marked of %d particles; the marked are at most "
                       "all, and all at most %d",
                       m, n, max);
    if (b->reading && (st = ms_blob_expect(b, "sim.x.x", (size_t)n * sizeof(float))))
        return st;
    if (b->reading && n > s->cap) {
        float *q = ms_alloc_array((size_t)n * 3, sizeof(float));
        if (!q)
            return ms_fail(MS_ERR_OUT_OF_MEMORY, "sim: out of memory restoring %d particles", n);
        ms_free(s->x);
        s->x = q;
        s->y = q + n;
        s->z = q + 2 * (size_t)n;
        s->cap = n;
    }
    if (b->reading) {
        s->m = m;
        s->n_all = n;
    }
    /* the marked particles, then the others (extract.h) */
    const size_t fb = (size_t)n * sizeof(float);
    if ((st = ms_blob_io(b, "sim.x.x", s->x, fb)) || (st = ms_blob_io(b, "sim.x.y", s->y, fb)) ||
        (st = ms_blob_io(b, "sim.x.z", s->z, fb)) || (st = MS_BLOB_IO(b, "sim.x.e", s->e)) ||
        (st = MS_BLOB_IO(b, "sim.x.iso", s->iso)) || (st = MS_BLOB_IO(b, "sim.x.R", s->R)) ||
        (st = MS_BLOB_IO(b, "sim.x.spacing", s->spacing)) ||
        (st = MS_BLOB_IO(b, "sim.x.lo", s->lo)) || (st = MS_BLOB_IO(b, "sim.x.hi", s->hi)) ||
        (st = MS_BLOB_IO(b, "sim.x.smooth", s->smooth_steps)) ||
        (st = MS_BLOB_IO(b, "sim.x.smooth_e", s->smooth_energy)))
        return st;
    return b->reading ? ms_volume_snapshot_check_extract(v, s, fresh) : MS_OK;
}

/* The particle copy of a slot, in the layout volume_task.c makes
 * (x, y, z one block, cap floats apart: sim.h's views). */
static ms_status particles_io(ms_blob *b, ms_sim *sim, int slot, int max)
{
    int n = sim->pcount[slot];
    ms_status st = ms_blob_count(b, "sim.p.n", &n, max);
    if (st == MS_OK && b->reading)
        st = ms_blob_expect(b, "sim.p.x", (size_t)n * sizeof(float));
    if (st != MS_OK)
        return st;
    if (b->reading && n > sim->pcap[slot]) {
        float *pos = ms_alloc_array((size_t)n * 3, sizeof(float));
        float *vel = ms_alloc_array((size_t)n * 3, sizeof(float));
        if (!pos || !vel) {
            ms_free(pos);
            ms_free(vel);
            return ms_fail(MS_ERR_OUT_OF_MEMORY, "sim: out of memory restoring %d particles", n);
        }
        ms_free(sim->ppos[slot][0]);
        ms_free(sim->pvel[slot][0]);
        for (int a = 0; a < 3; ++a) {
            sim->ppos[slot][a] = pos + (size_t)a * (size_t)n;
            sim->pvel[slot][a] = vel + (size_t)a * (size_t)n;
        }
        sim->pcap[slot] = n;
    }
    if (b->reading)
        sim->pcount[slot] = n;
    static const char *const pn[3] = {"sim.p.x", "sim.p.y", "sim.p.z"};
    static const char *const vn[3] = {"sim.p.vx", "sim.p.vy", "sim.p.vz"};
    /* the copies are published as they are: finite, near the domain */
    for (int a = 0; st == MS_OK && a < 3; ++a) {
        const double lo = sim->domain_min[a], hi = sim->domain_max[a], ext = hi - lo;
        if ((st = ms_blob_floats(b, pn[a], sim->ppos[slot][a], (size_t)n, lo - ext, hi + ext,
                                 "m")) == MS_OK)
            st =
                ms_blob_floats(b, vn[a], sim->pvel[slot][a], (size_t)n, -INFINITY, INFINITY, "m/s");
    }
    return st;
}

static ms_status shapes_io(ms_blob *b, ms_sim *sim)
{
    ms_status st = MS_OK;
    for (int i = 0; st == MS_OK && i < sim->nshapes; ++i) {
        ms_sim_shape *sh = &sim->shapes[i];
        if ((st = MS_BLOB_IO(b, "sim.sh.moving", sh->moving)) ||
            (st = MS_BLOB_IO(b, "sim.sh.api_set", sh->api_set)) ||
            (st = MS_BLOB_FINITE(b, "sim.sh.api_pos", sh->api_pos)) ||
            (st = MS_BLOB_FINITE(b, "sim.sh.api_vel", sh->api_vel)) ||
            (st = MS_BLOB_IO(b, "sim.sh.api_turn", sh->api_turn)) ||
            (st = MS_BLOB_FINITE(b, "sim.sh.quat", sh->api_quat)) ||
            (st = MS_BLOB_FINITE(b, "sim.sh.omega", sh->api_omega)))
            break;
    }
    return st;
}

/* Drags an engine asked for, in the ranges ms_sim_drag accepts (views.c):
 * a drag's radius bounds the particles it visits. */
static ms_status check_drags(const ms_sim_drag_req *d, int n)
{
    ms_status st = MS_OK;
    for (int i = 0; i < n && st == MS_OK; ++i)
        if ((st = ms_blob_check_floats("sim.drags pos", d[i].pos, 2, -1e4, 1e4, "m")) ||
            (st = ms_blob_check_floats("sim.drags vel", d[i].vel, 2, -1e3, 1e3, "m/s")) ||
            (st = ms_blob_check_floats("sim.drags radius", &d[i].radius, 1, 1e-6, 100, "m")) ||
            (st = ms_blob_check_floats("sim.drags depth", &d[i].depth, 1, 0, 100, "m")) ||
            (st = ms_blob_check_floats("sim.drags strength", &d[i].strength, 1, 1e-6, 1e4, "1/s")))
            break;
    return st;
}

/* Spray and foam (only a sim with spray holds these records, so a blob of
 * a scene without stays as it was): the droplets in flight, the foam and
 * its box, the generator. */
static ms_status spray_io(ms_blob *b, ms_sim *sim)
{
    ms_sim_spray_state *s = &sim->spray;
    const size_t ng = (size_t)s->gnx * s->gny;
    int n = s->n;
    ms_status st;
    if ((st = ms_blob_count(b, "sim.spray.n", &n, s->cap)) ||
        (st = buf_io(b, "sim.spray.pos", s->pos, 3 * (size_t)n)) ||
        (st = buf_io(b, "sim.spray.vel", s->vel, 3 * (size_t)n)) ||
        (st = ms_blob_floats(b, "sim.spray.foam", s->foam, ng, 0.0, 1.0, "")) ||
        (st = MS_BLOB_IO(b, "sim.spray.foam_on", s->foam_on)) ||
        (st = ms_blob_io(b, "sim.spray.box", s->box, sizeof s->box)) ||
        (st = ms_blob_io(b, "sim.spray.rng", &s->rng, sizeof s->rng)))
        return st;
    if (b->reading) {
        if ((st = ms_blob_check_int("sim.spray.foam_on", s->foam_on, 0, 1)))
            return st;
        for (int k = 0; k < 4; ++k)
            if (s->foam_on && (st = ms_blob_check_int("sim.spray.box", s->box[k], 0,
                                                      k < 2 ? s->gnx - 1 : s->gny - 1)))
                return st;
        s->n = n;
    }
    return MS_OK;
}

/* Every record of the sim, either way. */
static ms_status sim_io(ms_sim *sim, ms_blob *b)
{
    const size_t nf = (size_t)sim->fnx * sim->fny, ns = (size_t)sim->snx * sim->sny;
    const int maxp = sim->volume ? ms_volume_snapshot_max_particles(sim->volume) : 0;
    const int ndrops = sim->scene ? sim->scene->ndrops : 0;
    ms_status st;
    /* clock and pipeline: of the plans, what the next call needs (the dt
     * of the last frame, which its surface task takes up) and the wave
     * steps of the frame before (ms_stats.n_time); the records keep their
     * names (dt_cur: the last call's dt, as dt_prev) */
    float dt_last = ms_sim_volume_plan(sim)->dt, dt_cur = dt_last;
    int n_time_last = ms_sim_wave_plan(sim)->n_time;
    /* times within what ms_sim_step accepts: frame_dt in (0, 10] s, at
     * most 1e7 wave steps a frame (step.c) */
    if ((st = MS_BLOB_IO(b, "sim.calls", sim->calls)) ||
        (st = ms_blob_double(b, "sim.t_volume", &sim->t_volume, 0.0, 1e12, "s")) ||
        (st = ms_blob_double(b, "sim.t_fields", &sim->t_fields, 0.0, 1e12, "s")) ||
        (st = ms_blob_floats(b, "sim.dt_prev", &dt_last, 1, 0.0, 10.0, "s")) ||
        (st = ms_blob_floats(b, "sim.dt_cur", &dt_cur, 1, 0.0, 10.0, "s")) ||
        (st = MS_BLOB_IO(b, "sim.primed", sim->primed)) ||
        (st = MS_BLOB_IO(b, "sim.n_time_last", n_time_last)) ||
        (st = ms_blob_floats(b, "sim.wave_dt", &sim->wave_dt_last, 1, 0.0, 10.0, "s")))
        return st;
    if (b->reading && ((st = ms_blob_check_int("sim.calls", sim->calls, 0, LONG_MAX)) ||
                       (st = ms_blob_check_int("sim.primed", sim->primed, 0, 1)) ||
                       (st = ms_blob_check_int("sim.n_time_last", n_time_last, 0, 10000000))))
        return st;
    if (b->reading) {
        memset(sim->plan, 0, sizeof sim->plan);
        sim->plan[(unsigned long)sim->calls & 1u].dt = dt_last;
        sim->plan[(unsigned long)(sim->calls - 1) & 1u].n_time = n_time_last;
    }
    for (int k = 0; st == MS_OK && k < 2; ++k) {
        if (sim->volume &&
            (st = extract_io(b, sim->volume, &sim->snap[k], maxp, sim->calls == 0)) == MS_OK &&
            (st = particles_io(b, sim, k, maxp)) == MS_OK)
            st = buf_io(b, "sim.hfield", sim->hfield[k], nf);
        if (st == MS_OK && (st = buf_io(b, "sim.flow", sim->flow[k], 2 * nf)) == MS_OK)
            st = buf_io(b, "sim.wave_snap", sim->wave_snap[k], nf);
    }
    if (st != MS_OK || (st = buf_io(b, "sim.hprev", sim->hprev, nf)) ||
        (st = buf_io(b, "sim.u_prev", sim->u_prev, nf)) ||
        (st = buf_io(b, "sim.combined", sim->combined, ns)) ||
        (st = ms_blob_io(b, "sim.mask", sim->mask, sim->mask ? ns : 0)))
        return st;
    /* effects */
    int next_drop = sim->next_drop, ndrags = sim->ndrags;
    if ((st = MS_BLOB_IO(b, "sim.boat_go", sim->boat_started)) ||
        (st = MS_BLOB_IO(b, "sim.drag_id", sim->drag_id)) ||
        (st = ms_blob_count(b, "sim.next_drop", &next_drop, ndrops)) ||
        (st = ms_blob_count(b, "sim.ndrags", &ndrags, MS_SIM_MAX_DRAGS)) ||
        (st = ms_blob_io(b, "sim.drags", sim->drags, (size_t)ndrags * sizeof sim->drags[0])) ||
        (b->reading && (st = check_drags(sim->drags, ndrags))) || (st = shapes_io(b, sim)) ||
        (st = buf_io(b, "sim.floater_xyz", sim->floater_xyz, 3 * (size_t)sim->nfloaters)) ||
        (st = buf_io(b, "sim.floater_vel", sim->floater_vel, 2 * (size_t)sim->nfloaters)))
        return st;
    if (sim->spray.cap > 0 && (st = spray_io(b, sim)) != MS_OK)
        return st;
    if (b->reading) {
        sim->next_drop = next_drop;
        sim->ndrags = ndrags;
        sim->stats.frames = sim->calls; /* frames finished, as ms_sim_frame */
    }
    /* the parts */
    if (sim->surface && (st = ms_surface_snapshot_io(sim->surface, b)))
        return st;
    int recount = 0;
    if (sim->volume && (st = ms_volume_snapshot_io(sim->volume, b, &recount)))
        return st;
    if (b->reading && b->pos != b->len)
        return ms_fail(MS_ERR_INVALID_ARGUMENT,
                       "snapshot: %zu bytes left over after the last record", b->len - b->pos);
    if (b->reading && sim->volume && sim->calls >= 1) {
        /* the colliders where the last volume task put them (its t0 is now
         * t_fields), as the snapshot's neighbour counts saw them */
        for (int i = 0; st == MS_OK && i < sim->nshapes; ++i)
            if (sim->shapes[i].vol && ms_sim_shape_dynamic(&sim->shapes[i]))
                st = ms_sim_shape_place(&sim->shapes[i], sim->shapes[i].vol, sim->t_fields);
    }
    if (st == MS_OK && recount)
        st = ms_volume_snapshot_recount(sim->volume);
    return st;
}

static ms_status between_steps(const ms_sim *sim, const char *what)
{
    ms_status st = ms_check_not_null("sim", "sim", sim);
    if (st == MS_OK && atomic_load(&((ms_sim *)sim)->busy))
        st = ms_fail(MS_ERR_STATE, "sim: %s while a step is running; call it between steps", what);
    return st;
}

ms_status ms_sim_snapshot_size(const ms_sim *sim, size_t *bytes)
{
    ms_status st = between_steps(sim, "ms_sim_snapshot_size");
    if (st == MS_OK)
        st = ms_check_not_null("sim", "bytes", bytes);
    if (st != MS_OK)
        return st;
    ms_blob b = {0};
    st = sim_io((ms_sim *)sim, &b); /* writing with no buffer: counts only */
    *bytes = H_SIZE + b.len;
    return st;
}

ms_status ms_sim_snapshot(const ms_sim *sim, void *buf, size_t capacity, size_t *written)
{
    ms_status st = between_steps(sim, "ms_sim_snapshot");
    if (st == MS_OK)
        st = ms_check_not_null("sim", "buf", buf);
    if (st != MS_OK)
        return st;
    if (written)
        *written = 0;
    if (sim->failed)
        return ms_fail(MS_ERR_STATE, "sim: no snapshot of a failed sim (%s)", sim->fail_msg);
    size_t need = 0;
    if ((st = ms_sim_snapshot_size(sim, &need)) != MS_OK)
        return st;
    if (capacity < need)
        return ms_fail(MS_ERR_INVALID_ARGUMENT,
                       "sim: a snapshot buffer of %zu bytes; this sim's snapshot needs %zu "
                       "(ms_sim_snapshot_size)",
                       capacity, need);
    unsigned char *p = buf;
    ms_blob b = {.out = p + H_SIZE, .cap = need - H_SIZE};
    if ((st = sim_io((ms_sim *)sim, &b)) != MS_OK)
        return st;
    memset(p, 0, H_SIZE);
    memcpy(p + H_MAGIC, MAGIC, 8);
    const uint32_t hsize = H_SIZE, version = SNAP_VERSION;
    const uint64_t total = need, hash = sim_hash(sim),
                   sum = ms_blob_hash(MS_BLOB_HASH0, p + H_SIZE, need - H_SIZE);
    memcpy(p + H_HEADER, &hsize, sizeof hsize);
    memcpy(p + H_FORMAT, &version, sizeof version);
    memcpy(p + H_TOTAL, &total, sizeof total);
    memcpy(p + H_HASH, &hash, sizeof hash);
    memcpy(p + H_SUM, &sum, sizeof sum);
    strncpy((char *)p + H_LIBVER, ms_version(), VERSION_LEN - 1);
    if (written)
        *written = need;
    return MS_OK;
}

/* The header: everything that must match before a record is read. */
static ms_status check_header(const ms_sim *sim, const unsigned char *p, size_t bytes)
{
    if (bytes < H_SIZE || memcmp(p + H_MAGIC, MAGIC, 6) != 0)
        return ms_fail(MS_ERR_INVALID_ARGUMENT,
                       "sim: %zu bytes that are not a snapshot (no \"MSSNAP\" header of %d "
                       "bytes)",
                       bytes, H_SIZE);
    uint32_t hsize, version;
    uint64_t total, hash, sum;
    memcpy(&hsize, p + H_HEADER, sizeof hsize);
    memcpy(&version, p + H_FORMAT, sizeof version);
    memcpy(&total, p + H_TOTAL, sizeof total);
    memcpy(&hash, p + H_HASH, sizeof hash);
    memcpy(&sum, p + H_SUM, sizeof sum);
    char lib[VERSION_LEN];
    memcpy(lib, p + H_LIBVER, VERSION_LEN);
    lib[VERSION_LEN - 1] = '\0';
    if (version != SNAP_VERSION || hsize != H_SIZE)
        return ms_fail(MS_ERR_UNSUPPORTED,
                       "sim: snapshot format version %u (header %u bytes); this library reads "
                       "version %u",
                       version, hsize, SNAP_VERSION);
    if (strcmp(lib, ms_version()) != 0)
        return ms_fail(MS_ERR_UNSUPPORTED,
                       "sim: the snapshot was taken by library version %s, this is %s (another "
                       "build may step differently)",
                       lib, ms_version());
    if (total != bytes)
        return ms_fail(MS_ERR_INVALID_ARGUMENT,
                       "sim: %zu snapshot bytes given, its header says %llu (cut or padded)", bytes,
                       (unsigned long long)total);
    if (ms_blob_hash(MS_BLOB_HASH0, p + H_SIZE, bytes - H_SIZE) != sum)
        return ms_fail(MS_ERR_INVALID_ARGUMENT,
                       "sim: the snapshot's checksum does not match its %zu bytes (corrupt)",
                       bytes);
    if (hash != sim_hash(sim))
        return ms_fail(MS_ERR_INVALID_ARGUMENT,
                       "sim: the snapshot is of another scene or desc (hash %016llx, this sim "
                       "%016llx): restore it into a sim made the same way",
                       (unsigned long long)hash, (unsigned long long)sim_hash(sim));
    return MS_OK;
}

ms_status ms_sim_restore(ms_sim *sim, const void *buf, size_t bytes)
{
    ms_status st = between_steps(sim, "ms_sim_restore");
    if (st == MS_OK)
        st = ms_check_not_null("sim", "buf", buf);
    if (st == MS_OK)
        st = check_header(sim, buf, bytes);
    if (st != MS_OK)
        return st;
    ms_blob b = {.reading = 1, .in = (const unsigned char *)buf + H_SIZE, .len = bytes - H_SIZE};
    st = sim_io(sim, &b);
    if (st != MS_OK) {
        /* the header matched, so only a forged or damaged blob gets here:
         * part of the state is overwritten, the sim cannot go on */
        sim->failed = 1;
        sim->fail_status = st;
        snprintf(sim->fail_msg, sizeof sim->fail_msg, "restore failed: %s", ms_last_error());
        return st;
    }
    sim->failed = 0;
    sim->fail_msg[0] = '\0';
    sim->fail_status = MS_OK;
    return MS_OK;
}
