/* The surface thread's task (Fig. 8, core 2) for frame m = n - 1: the SPH
 * height field from the volume thread's snapshot (phase B of eqs. 16-18),
 * the scripted effects, the coupling from the volume (3.5), N_time wave
 * steps (eq. 19), the up-sampled SPH field plus the waves (eq. 20),
 * floaters, spray and foam. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "modesplit/surface.h"
#include "modesplit/volume.h"
#include "sim/sim_internal.h"
#include "surface/surface_internal.h"

/* Obstacle mask at time t: the static footprints and the moving ones. */
static ms_status update_mask(ms_sim *sim, double t)
{
    ms_grid g = sim->wave_grid;
    float z = sim->domain_min[2] + sim->level;
    size_t ns = (size_t)sim->snx * sim->sny;
    memcpy(sim->mask, sim->mask_static, ns);
    for (int i = 0; i < sim->nshapes; ++i) {
        ms_sim_shape *sh = &sim->shapes[i];
        if (!sh->surf || !ms_sim_shape_dynamic(sh))
            continue;
        ms_status st = ms_sim_shape_place(sh, sh->surf, t);
        if (st == MS_OK)
            st = ms_shape_footprint(sh->surf, &g, z, sim->mask);
        if (st != MS_OK)
            return st;
    }
    return ms_surface_set_obstacle_mask(sim->surface, sim->mask);
}

/* Effects scripted for the interval [t0, t1) of the wave field. */
static ms_status scripted_effects(ms_sim *sim, double t0, double t1)
{
    const ms_scene *sc = sim->scene;
    ms_status st = MS_OK;
    if (!sc)
        return MS_OK;
    while (st == MS_OK && sim->next_drop < sc->ndrops &&
           sc->drops[sim->drop_order[sim->next_drop]].time < t1) {
        const ms_scene_drop *d = &sc->drops[sim->drop_order[sim->next_drop++]];
        /* the wave grid's coordinates start at its corner, the domain's min */
        st = ms_surface_add_drop(sim->surface, d->x - sim->domain_min[0], d->y - sim->domain_min[1],
                                 d->radius, d->amplitude);
    }
    if (st == MS_OK && sc->has_boat && !sim->boat_started && t0 >= sc->boat_path.start) {
        sim->boat_started = 1;
        if (sc->boat_path.npoints > 1)
            st = ms_surface_set_disturber_path(sim->surface, sim->boat_id, sc->boat_path.npoints,
                                               sim->boat_xy, sc->boat_path.speed,
                                               sc->boat_path.loop);
    }
    if (st == MS_OK && sc->has_drag && !sim->volume) {
        /* without a volume the pointer presses a dent that it drags along */
        int active = ms_sim_motion_active(&sc->drag_path, t0);
        float pos[2], vel[2];
        ms_scene_motion_eval(&sc->drag_path, t0, pos, vel);
        pos[0] -= sim->domain_min[0];
        pos[1] -= sim->domain_min[1];
        if (active && !sim->drag_id) {
            ms_disturber_desc dd = ms_disturber_desc_default();
            dd.x = pos[0];
            dd.y = pos[1];
            dd.vx = vel[0];
            dd.vy = vel[1];
            dd.radius = sc->drag_radius;
            dd.depth = sc->drag_depth;
            st = ms_surface_add_disturber(sim->surface, &dd, &sim->drag_id);
        } else if (active) {
            st = ms_surface_move_disturber(sim->surface, sim->drag_id, pos[0], pos[1], vel[0],
                                           vel[1]);
        } else if (sim->drag_id) {
            st = ms_surface_remove_disturber(sim->surface, sim->drag_id);
            sim->drag_id = 0;
        }
    }
    if (st == MS_OK && sim->have_moving_mask)
        st = update_mask(sim, t0);
    return st;
}

/* The cells the coupling leaves alone: those within the rim radius of a
 * cell that is dry (H <= 0) at t_m or t_{m-1}. Eq. 16's iso-spheres have
 * radius h, so the field falls from the liquid's level to 0 within h of
 * the last particle; where that slope moves sideways (a glass carried, a
 * paddle turning, liquid spreading) H changes by up to the whole depth in
 * a frame although the free surface does not move vertically, and driving
 * the waves with that change filled them with grid-scale noise: the glass
 * scene's W had an rms of 4.3 mm in a 7 cm column (0.16 mm with a rim of
 * one cell, 0.05 mm with ceil(h / cell) = 2), the stir's 5.2 mm (0.5 mm).
 * The rim is a square of ceil(h / cell) cells, dilated row then column. */
static void rim_mask(ms_sim *sim, const float *h)
{
    const int nx = sim->fnx, ny = sim->fny;
    const float cell = fminf((sim->domain_max[0] - sim->domain_min[0]) / (float)nx,
                             (sim->domain_max[1] - sim->domain_min[1]) / (float)ny);
    const ms_volume_desc vd = ms_volume_get_desc(sim->volume);
    const int r = (int)ceilf(vd.smoothing_length / cell);
    unsigned char *restrict row = sim->rim_row, *restrict rim = sim->rim;
    for (int j = 0; j < ny; ++j)
        for (int i = 0; i < nx; ++i) {
            unsigned char dry = 0;
            for (int a = i - r > 0 ? i - r : 0; a <= i + r && a < nx; ++a) {
                const size_t q = (size_t)j * nx + a;
                dry |= !(h[q] > 0.0f) || !(sim->hprev[q] > 0.0f);
            }
            row[(size_t)j * nx + i] = dry;
        }
    for (int j = 0; j < ny; ++j)
        for (int i = 0; i < nx; ++i) {
            unsigned char dry = 0;
            for (int b = j - r > 0 ? j - r : 0; b <= j + r && b < ny; ++b)
                dry |= row[(size_t)b * nx + i];
            rim[(size_t)j * nx + i] = dry;
        }
}

/* 3.5: "increasing the value of f depending on the scaled derivative of
 * the extracted SPH field": during frame m the wave field moves with the
 * extra vertical velocity u_m = gain * dH/dt = gain * (H_m - H_{m-1}) /
 * dt_frame, with its mean removed (the volume already carries the water; the
 * coupling adds none), so over the frame it is displaced by gain times the
 * SPH field's change, whatever the frame rate, and the displacement runs off
 * as ripples where the volume moves. u_m is 0 on the rim of the liquid
 * (rim_mask) and the mean is taken over the other cells. The offset starts
 * and ends as impulses (ms_surface_excite moves f^n, not f^{n-1}); frame
 * m's start and frame m-1's end are one impulse, (u_m - u_{m-1}) times the
 * wave step it acts over, so a frame costs one pass over the wave grid. */
static ms_status couple_from_volume(ms_sim *sim, const float *h, float dt_frame, float dt_step)
{
    size_t nf = (size_t)sim->fnx * sim->fny;
    rim_mask(sim, h);
    double mean = 0;
    size_t driven = 0;
    for (size_t c = 0; c < nf; ++c)
        if (!sim->rim[c]) {
            mean += (double)h[c] - sim->hprev[c];
            driven++;
        }
    mean = driven ? mean / (double)driven : 0.0;
    /* the impulse's velocity is its size over the step the surface last took
     * (the solver rescales its velocity to each new step) */
    const float dref = sim->wave_dt_last > 0 ? sim->wave_dt_last : dt_step;
    const float k = sim->gain_sv / dt_frame; /* 1/s */
    float *restrict e = sim->dh, *restrict up = sim->u_prev;
    for (size_t c = 0; c < nf; ++c) {
        float u = sim->rim[c] ? 0.0f : k * (float)((double)h[c] - sim->hprev[c] - mean); /* m/s */
        e[c] = (u - up[c]) * dref;                                                       /* m */
        up[c] = u;
    }
    return ms_sim_upsample_excite(sim, e, sim->surface);
}

/* Sum the nx x ny field `in` over the square of radius r cells round each
 * cell (edges: the part inside), row pass into tmp then column pass. */
static void box_sum(const float *restrict in, float *restrict tmp, float *restrict out, int nx,
                    int ny, int r)
{
    for (int j = 0; j < ny; ++j)
        for (int i = 0; i < nx; ++i) {
            float s = 0.0f;
            for (int a = MS_MAX(i - r, 0); a <= MS_MIN(i + r, nx - 1); ++a)
                s += in[(size_t)j * nx + a];
            tmp[(size_t)j * nx + i] = s;
        }
    for (int j = 0; j < ny; ++j)
        for (int i = 0; i < nx; ++i) {
            float s = 0.0f;
            for (int b = MS_MAX(j - r, 0); b <= MS_MIN(j + r, ny - 1); ++b)
                s += tmp[(size_t)b * nx + i];
            out[(size_t)j * nx + i] = s;
        }
}

/* No flow through the waves' walls. Water does not cross a wall (the
 * kinematic condition U.n = 0), but the current built from the SPH flow
 * does: the flow is averaged over h, so near a wall it mixes in the flow
 * turning along it, and the up-sampling reads SPH cells behind the wall.
 * Carried by such a current, waves feed on the wall: in the river scene
 * (data/scenes/river.json) the current met the island's walls at up to 0.14
 * m/s (c = 0.2 m/s) and the waves grew there, their rms from 0.5 mm at 5 s
 * to 1 cm at 30 s and past the domain's top at 59 s; the surface alone
 * under that current held frozen grew 14x every 2 s at the island's wall
 * (measured). So the component of the current normal to a wall is ramped
 * to 0 over the flow's own resolution h: along x (and y), times
 * min(1, d / h), d the distance from the cell's centre to the nearest wall
 * face along that axis. The walls: solid cells of the obstacle mask, dry
 * cells (up(H) <= 0: the waves live only on liquid, ms_sim_waves_on_liquid)
 * and the domain's edges (the volume's box). Tangential flow is kept. With
 * the ramp, the frozen current of that frame carries waves that decay
 * (energy / 10^4 in 12 s) and the river's rms stays 0.6-0.7 mm for 90 s; a
 * ramp of 2 wave cells instead of h let them grow (rms x3 in 30 s). */
static void current_walls(ms_sim *sim, const float *h, float *restrict ux, float *restrict uy)
{
    const int nx = sim->snx, ny = sim->sny;
    const ms_volume_desc vd = ms_volume_get_desc(sim->volume);
    const float cells = vd.smoothing_length / sim->sdx; /* the ramp, in wave cells */
    const unsigned char *mask = sim->have_moving_mask ? sim->mask : sim->mask_static;
    float *restrict wall = sim->current_wall, *restrict line = sim->current_line;
    ms_sim_upsample(sim, h, sim->rowtmp, wall);
    for (size_t c = 0; c < (size_t)nx * ny; ++c)
        wall[c] = (mask && mask[c]) || !(wall[c] > 0.0f) ? 1.0f : 0.0f;
    for (int k = 0; k < 2; ++k) {
        /* k = 0: the x component along rows; k = 1: y along columns */
        const int n = k ? ny : nx, lines = k ? nx : ny;
        const size_t step = k ? (size_t)nx : 1, next = k ? 1 : (size_t)nx;
        float *restrict u = k ? uy : ux;
        for (int l = 0; l < lines; ++l) {
            const size_t o = (size_t)l * next;
            float d = 0.5f; /* cells from the centre to the wall face behind */
            for (int i = 0; i < n; ++i, d += 1.0f) {
                if (wall[o + i * step] > 0.0f)
                    d = -0.5f;
                line[i] = d;
            }
            d = 0.5f;
            for (int i = n - 1; i >= 0; --i, d += 1.0f) {
                const size_t c = o + i * step;
                if (wall[c] > 0.0f) {
                    d = -0.5f;
                    u[c] = 0.0f;
                    continue;
                }
                const float r = fminf(d, line[i]) / cells;
                if (r < 1.0f)
                    u[c] *= r;
            }
        }
    }
}

/* surface.advect: the current that carries the waves during frame m
 * (lib/surface/current.c) is the volume's surface flow of the frame (the
 * particles near the surface, ms_sim_volume_field) averaged over the
 * particles within the smoothing length h of each SPH cell (a square of
 * ceil(h / cell) cells, as rim_mask), and up-sampled onto the wave grid
 * as eq. 20 up-samples the height. SPH resolves velocity at h, not at the
 * field's cell: a cell holds one or two particles near the surface, and
 * their mean alone made a current whose strain rate was particle noise
 * (river.json: |S| of several 1/s in a steady reach, so the turbulence
 * damping took a boat's wake within a fraction of a second). The current
 * then stops at the waves' walls (current_walls). */
static ms_status carry_waves(ms_sim *sim, const float *flow, const float *h)
{
    const int nx = sim->fnx, ny = sim->fny;
    const size_t nf = (size_t)nx * ny;
    const float cell = fminf((sim->domain_max[0] - sim->domain_min[0]) / (float)nx,
                             (sim->domain_max[1] - sim->domain_min[1]) / (float)ny);
    const ms_volume_desc vd = ms_volume_get_desc(sim->volume);
    const int r = (int)ceilf(vd.smoothing_length / cell);
    /* flow_comp: the component's sum per cell, the box sums of the counts
     * and of the component, and the row pass's scratch */
    float *sum = sim->flow_comp, *count = sum + nf, *out = sum + 2 * nf, *tmp = sum + 3 * nf;
    box_sum(sim->flow_count, tmp, count, nx, ny, r);
    for (int k = 0; k < 2; ++k) {
        for (size_t i = 0; i < nf; ++i)
            sum[i] = flow[2 * i + (size_t)k] * sim->flow_count[i];
        box_sum(sum, tmp, out, nx, ny, r);
        for (size_t i = 0; i < nf; ++i)
            out[i] = count[i] > 0 ? out[i] / count[i] : 0.0f;
        ms_sim_upsample(sim, out, sim->rowtmp, sim->current[k]);
    }
    current_walls(sim, h, sim->current[0], sim->current[1]);
    return ms_surface_set_current(sim->surface, sim->current[0], sim->current[1]);
}

void ms_sim_surface_task(void *arg)
{
    ms_sim_task *task = arg;
    ms_sim *sim = task->sim;
    long n = sim->calls + 1, m = n - 1;
    int slot = (int)(m % 2);
    const float *h = sim->volume ? sim->hfield[slot] : NULL; /* H_m */
    double cx = ms_now();
    ms_status st = sim->volume ? ms_sim_volume_field(sim, slot, task->alone) : MS_OK;
    double c0 = ms_now();
    task->ms_x = sim->volume ? (c0 - cx) * 1e3 : 0.0;
    if (!sim->surface) {
        /* a volume-only sim: the SPH field is the surface; only floaters */
        if (st == MS_OK && sim->nfloaters) {
            if (m >= 1)
                ms_sim_floaters_step(sim, sim->flow[slot], NULL, task->plan->dt);
            ms_sim_floaters_height(sim);
        }
        if (st == MS_OK && m >= 1)
            ms_sim_spray_frame(sim, slot, task->plan->dt);
        task->ms_a = 0;
        task->ms_b = (ms_now() - c0) * 1e3;
        task->status = st;
        if (st != MS_OK)
            snprintf(task->err, sizeof task->err, "%s", ms_last_error());
        return;
    }
    if (st == MS_OK && m >= 1) {
        const ms_frame_plan *plan = task->plan; /* frame m's */
        double t1 = sim->t_fields + plan->dt;   /* t_m */
        float dt = plan->dt;
        int n_time = plan->n_time;
        const float dt_step = plan->wave_dt;
        st = scripted_effects(sim, sim->t_fields, t1);
        if (st == MS_OK && h && sim->hprev)
            st = couple_from_volume(sim, h, dt, dt_step);
        if (st == MS_OK && sim->current[0])
            st = carry_waves(sim, sim->flow[slot], h);
        if (st == MS_OK) /* N_time steps, in fused sweeps (the same bytes) */
            st = ms_surface_step_calls(sim->surface, dt_step, n_time);
        if (st == MS_OK && h)
            ms_sim_waves_on_liquid(sim, h);
        sim->wave_dt_last = dt_step;
    }
    double c1 = ms_now();
    if (st == MS_OK) {
        /* the wave field in the solver's own rows: the view
         * (ms_surface_height) is copied only when someone reads it */
        const ms_surface *sf = sim->surface;
        const float *w = sf->h + ms_surface_at(sf, 0, 0);
        float *avg = sim->wave_snap[n % 2];
        if (h)
            ms_sim_combine(sim, h, w, (size_t)sf->stride, sim->combined, avg);
        else {
            const float lvl = sim->level;
            for (int j = 0; j < sim->sny; ++j) {
                const float *restrict src = w + (size_t)j * sf->stride;
                float *restrict out = sim->combined + (size_t)j * sim->snx;
#pragma omp simd
                for (int i = 0; i < sim->snx; ++i)
                    out[i] = src[i] + lvl;
            }
            if (avg)
                ms_sim_average_waves(sim, ms_surface_height(sim->surface, NULL, NULL), avg);
        }
        if (sim->hprev)
            memcpy(sim->hprev, h, (size_t)sim->fnx * sim->fny * sizeof *h);
        if (sim->nfloaters) {
            const float *wv = ms_surface_height(sim->surface, NULL, NULL);
            if (m >= 1)
                ms_sim_floaters_step(sim, h ? sim->flow[slot] : NULL, wv, task->plan->dt);
            ms_sim_floaters_height(sim);
        }
        if (h && m >= 1)
            ms_sim_spray_frame(sim, slot, task->plan->dt);
    }
    double c2 = ms_now();
    task->ms_a = (c1 - c0) * 1e3;
    task->ms_b = (c2 - c1) * 1e3;
    task->status = st;
    if (st != MS_OK)
        snprintf(task->err, sizeof task->err, "%s", ms_last_error());
}
