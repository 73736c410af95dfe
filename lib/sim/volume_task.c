/* The volume thread's task (Fig. 8, core 1): interaction, the coupling
 * from the surface (3.5), the SPH step (eqs. 9-15), phase A of the height
 * field (eqs. 16-18: the surface particles, volume/extract.h) and the
 * copies the surface thread and the public views read in the next call;
 * phase B (the columns) and the surface flow, which the surface thread
 * runs. */
#include <stdio.h>
#include <string.h>

#include "modesplit/volume.h"
#include "sim/sim_internal.h"

/* Pose of a scene shape at time t (s). */
static void shape_pose(const ms_sim_shape *sh, double t, float pos[3], float vel[3])
{
    if (sh->api_set) {
        memcpy(pos, sh->api_pos, 3 * sizeof *pos);
        memcpy(vel, sh->api_vel, 3 * sizeof *vel);
    } else if (sh->spec->path.npoints > 0) {
        ms_scene_motion_eval(&sh->spec->path, t, pos, vel);
    } else {
        for (int k = 0; k < 3; ++k) {
            pos[k] = (float)(sh->spec->position[k] + sh->spec->velocity[k] * t);
            vel[k] = sh->spec->velocity[k];
        }
    }
}

/* Orientation (quaternion) and angular velocity (rad/s) of a scene shape
 * at time t (s): the engine's (ms_sim_turn_*), else the scene's turned by
 * its spin since t = 0. 0 if it is neither turned nor turning. */
static int shape_turn(const ms_sim_shape *sh, double t, float quat[4], float omega[3])
{
    if (sh->api_turn) {
        memcpy(quat, sh->api_quat, 4 * sizeof *quat);
        memcpy(omega, sh->api_omega, 3 * sizeof *omega);
        return 1;
    }
    const float *q0 = sh->spec->orientation, *w = sh->spec->spin;
    const double w2 = (double)w[0] * w[0] + (double)w[1] * w[1] + (double)w[2] * w[2];
    if (w2 == 0.0 && q0[1] == 0.0f && q0[2] == 0.0f && q0[3] == 0.0f)
        return 0;
    /* q(t) = dq q0, dq = (cos(a/2), sin(a/2) w/|w|), a = |w| t */
    double dq[4] = {1.0, 0.0, 0.0, 0.0};
    if (w2 > 0.0) {
        const double len = sqrt(w2), half = 0.5 * len * t, s = sin(half) / len;
        dq[0] = cos(half);
        dq[1] = s * w[0];
        dq[2] = s * w[1];
        dq[3] = s * w[2];
    }
    quat[0] = (float)(dq[0] * q0[0] - dq[1] * q0[1] - dq[2] * q0[2] - dq[3] * q0[3]);
    quat[1] = (float)(dq[0] * q0[1] + dq[1] * q0[0] + dq[2] * q0[3] - dq[3] * q0[2]);
    quat[2] = (float)(dq[0] * q0[2] - dq[1] * q0[3] + dq[2] * q0[0] + dq[3] * q0[1]);
    quat[3] = (float)(dq[0] * q0[3] + dq[1] * q0[2] - dq[2] * q0[1] + dq[3] * q0[0]);
    memcpy(omega, w, 3 * sizeof *omega);
    return 1;
}

ms_status ms_sim_shape_place(const ms_sim_shape *sh, ms_shape *s, double t)
{
    float pos[3], vel[3], quat[4], omega[3];
    shape_pose(sh, t, pos, vel);
    ms_status st = ms_shape_set_pose(s, pos, vel);
    if (st == MS_OK && shape_turn(sh, t, quat, omega))
        st = ms_shape_set_orientation(s, quat, omega);
    return st;
}

/* Is a scripted pointer pressed at time t: after its start, and while it
 * moves (a path that does not loop lets go at its end). */
int ms_sim_motion_active(const ms_scene_motion *p, double t)
{
    if (p->npoints <= 0 || t < p->start)
        return 0;
    if (p->loop || p->npoints == 1)
        return 1;
    double len = 0;
    for (int s = 0; s + 1 < p->npoints; ++s) {
        double d2 = 0;
        for (int k = 0; k < p->dim; ++k) {
            double d = (double)p->points[(s + 1) * p->dim + k] - p->points[s * p->dim + k];
            d2 += d * d;
        }
        len += sqrt(d2);
    }
    return (t - p->start) * p->speed < len;
}

/* Height (m above domain_min z) at world (x, y), nearest cell, of the
 * field of snapshot s: that cell alone, the same bits as the whole field
 * the surface thread is computing from s meanwhile. */
static ms_status field_at(ms_sim *sim, const ms_extract_snap *s, float x, float y, float *h)
{
    float fx = (x - sim->domain_min[0]) / (sim->domain_max[0] - sim->domain_min[0]) * sim->fnx;
    float fy = (y - sim->domain_min[1]) / (sim->domain_max[1] - sim->domain_min[1]) * sim->fny;
    int i = (int)MS_CLAMP(fx, 0.0f, (float)(sim->fnx - 1));
    int j = (int)MS_CLAMP(fy, 0.0f, (float)(sim->fny - 1));
    return ms_extract_cell(s, &sim->work_v, sim->fnx, sim->fny, i, j, h);
}

static ms_status apply_drag(ms_sim *sim, const ms_extract_snap *s, const float pos[2],
                            const float vel[2], float radius, float depth, float strength)
{
    float h;
    ms_status st = field_at(sim, s, pos[0], pos[1], &h);
    if (st != MS_OK)
        return st;
    float surf = sim->domain_min[2] + h;
    float centre[3] = {pos[0], pos[1], MS_MAX(surf - depth, sim->domain_min[2])};
    float v[3] = {vel[0], vel[1], 0};
    return ms_volume_drag(sim->volume, centre, radius, v, strength);
}

/* Copy the particles (stable order) into slot `slot`, structure of arrays. */
static ms_status volume_grab(ms_sim *sim, int slot)
{
    int n = ms_volume_count(sim->volume);
    if (n > sim->pcap[slot]) {
        int cap = n + n / 8 + 64;
        /* x, y, z (and vx, vy, vz) in one block each, cap floats apart:
         * sim.h promises it, so FFI users view them as one (n, 3) array
         * with strides (4, 4 cap) without a copy. */
        ms_free(sim->ppos[slot][0]);
        ms_free(sim->pvel[slot][0]);
        float *pos = ms_alloc_array((size_t)cap * 3, sizeof(float));
        float *vel = ms_alloc_array((size_t)cap * 3, sizeof(float));
        for (int a = 0; a < 3; ++a) {
            sim->ppos[slot][a] = pos ? pos + (size_t)a * (size_t)cap : NULL;
            sim->pvel[slot][a] = vel ? vel + (size_t)a * (size_t)cap : NULL;
        }
        if (!pos || !vel) {
            ms_free(pos);
            ms_free(vel);
            for (int a = 0; a < 3; ++a)
                sim->ppos[slot][a] = sim->pvel[slot][a] = NULL;
            sim->pcap[slot] = 0;
            return ms_fail(MS_ERR_OUT_OF_MEMORY, "sim: out of memory copying %d particles", n);
        }
        sim->pcap[slot] = cap;
    }
    sim->pcount[slot] = n;
    if (n > 0)
        ms_volume_copy_particles(sim->volume, sim->ppos[slot], sim->pvel[slot]);
    return MS_OK;
}

ms_status ms_sim_volume_snap(ms_sim *sim, int slot)
{
    ms_status st = ms_volume_extract_snap(sim->volume, &sim->snap[slot]);
    return st == MS_OK ? volume_grab(sim, slot) : st;
}

/* Phase B of the extraction from snap[slot] into hfield[slot]; with
 * floaters, the mean horizontal velocity of the particles of slot within
 * two spacings of that surface, per field cell. With `alone` the volume
 * thread is idle and lends its workers (any split: the same bytes). */
ms_status ms_sim_volume_field(ms_sim *sim, int slot, int alone)
{
    ms_vpool *pool = alone ? ms_volume_extract_pool(sim->volume) : NULL;
    ms_status st = ms_extract_field(&sim->snap[slot], &sim->work_s, pool, sim->fnx, sim->fny,
                                    sim->hfield[slot]);
    int n = sim->pcount[slot];
    if (st == MS_OK && sim->flow[slot] && n > 0) {
        /* surface flow for the floaters: the mean horizontal velocity of
         * the particles within two spacings of the surface, per field cell
         * (sums in the stable particle order: deterministic) */
        size_t nf = (size_t)sim->fnx * sim->fny;
        float *restrict flow = sim->flow[slot], *restrict cnt = sim->flow_count;
        const float *h = sim->hfield[slot];
        memset(flow, 0, 2 * nf * sizeof *flow);
        memset(cnt, 0, nf * sizeof *cnt);
        float sx = sim->fnx / (sim->domain_max[0] - sim->domain_min[0]);
        float sy = sim->fny / (sim->domain_max[1] - sim->domain_min[1]);
        float band = 2 * sim->spacing; /* m */
        for (int i = 0; i < n; ++i) {
            int ci = (int)MS_CLAMP((sim->ppos[slot][0][i] - sim->domain_min[0]) * sx, 0.0f,
                                   (float)(sim->fnx - 1));
            int cj = (int)MS_CLAMP((sim->ppos[slot][1][i] - sim->domain_min[1]) * sy, 0.0f,
                                   (float)(sim->fny - 1));
            size_t c = (size_t)cj * sim->fnx + ci;
            if (sim->ppos[slot][2][i] - sim->domain_min[2] < h[c] - band)
                continue;
            flow[2 * c] += sim->pvel[slot][0][i];
            flow[2 * c + 1] += sim->pvel[slot][1][i];
            cnt[c] += 1.0f;
        }
        for (size_t c = 0; c < nf; ++c)
            if (cnt[c] > 0) {
                flow[2 * c] /= cnt[c];
                flow[2 * c + 1] /= cnt[c];
            }
    }
    return st;
}

void ms_sim_volume_task(void *arg)
{
    ms_sim_task *task = arg;
    ms_sim *sim = task->sim;
    long n = sim->calls + 1;
    int slot = (int)(n % 2), prev = 1 - slot;
    double t0 = sim->t_volume; /* s, start of this volume step */
    double c0 = ms_now();
    ms_status st = MS_OK;

    /* interaction at t0: moved shapes, the pointer, the engine's drags */
    for (int i = 0; st == MS_OK && i < sim->nshapes; ++i) {
        ms_sim_shape *sh = &sim->shapes[i];
        if (sh->vol && ms_sim_shape_dynamic(sh))
            st = ms_sim_shape_place(sh, sh->vol, t0);
    }
    const ms_scene *sc = sim->scene;
    if (st == MS_OK && sc && sc->has_drag && ms_sim_motion_active(&sc->drag_path, t0)) {
        float pos[2], vel[2];
        ms_scene_motion_eval(&sc->drag_path, t0, pos, vel);
        st = apply_drag(sim, &sim->snap[prev], pos, vel, sc->drag_radius, sc->drag_depth,
                        sc->drag_strength);
    }
    for (int i = 0; st == MS_OK && i < sim->ndrags; ++i) {
        const ms_sim_drag_req *r = &sim->drags[i];
        st = apply_drag(sim, &sim->snap[prev], r->pos, r->vel, r->radius, r->depth, r->strength);
    }
    /* 3.5: particles near the surface follow high waves (W_{n-2} averaged
     * over each SPH cell, handed over by the surface thread in the previous
     * call: the particles resolve nothing finer) */
    if (st == MS_OK && sim->wave_snap[prev] && n >= 2)
        st = ms_volume_adapt_to_waves(sim->volume, sim->wave_snap[prev], &sim->field_grid,
                                      sim->gain_vs);
    if (st == MS_OK)
        st = ms_volume_step(sim->volume, task->plan->dt);
    /* the neighbour pass at the step's end positions, which phase A reads
     * and the next step's first sub-step takes as its own: SPH work, timed
     * as volume_ms unless no step can take it (a collider jumped) */
    double c1 = ms_now();
    int for_step = 0;
    if (st == MS_OK)
        st = ms_volume_extract_counts(sim->volume, &for_step);
    if (for_step)
        c1 = ms_now();
    if (st == MS_OK)
        st = ms_sim_volume_snap(sim, slot);
    double c2 = ms_now();
    task->ms_a = (c1 - c0) * 1e3;
    task->ms_b = (c2 - c1) * 1e3;
    task->status = st;
    if (st != MS_OK)
        snprintf(task->err, sizeof task->err, "%s", ms_last_error());
}
