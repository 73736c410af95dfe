/* One frame of the pipeline (see sim_internal.h): N_time for the wave
 * interval (eq. 19), then the volume task and the surface task, at the
 * same time (threads = 2) or one after the other (threads = 1). */
#include <stdio.h>
#include <string.h>

#include "modesplit/surface.h"
#include "modesplit/volume.h"
#include "sim/sim_internal.h"

/* Before the first frame: the extraction snapshot and particles of the
 * start (t_0), which the surface task of the first call turns into the
 * field it shows. Done lazily so that an engine can fill the volume
 * between ms_sim_create and the first step. */
/* No allocation in any step after the first. The first makes
 * every block the frames use at its largest: the second snapshot slot and
 * particle copy (the volume's particle count bounds both); the field
 * extraction's scratch, at the most threads it runs on (into hfield[1],
 * which frame 1 writes again); the one-cell extraction of the pointer's
 * drag, at the most smoothing passes (kinetic energy 0: eq. 18) around a
 * centre cell, the largest rectangle. Results are unchanged: these write
 * only buffers that are written again before they are read. */
static ms_status reserve_pipeline(ms_sim *sim)
{
    ms_status st = ms_sim_volume_snap(sim, 1);
    if (st == MS_OK)
        st = ms_sim_volume_field(sim, 1, 1);
    if (st == MS_OK) {
        ms_extract_snap most = sim->snap[0];
        most.e = 0.0;
        float h;
        st = ms_extract_cell(&most, &sim->work_v, sim->fnx, sim->fny, sim->fnx / 2, sim->fny / 2,
                             &h);
    }
    return st;
}

static ms_status prime(ms_sim *sim)
{
    if (sim->volume) {
        double c0 = ms_now();
        ms_status st = ms_sim_volume_snap(sim, 0);
        if (st == MS_OK)
            st = reserve_pipeline(sim);
        if (st != MS_OK)
            return st;
        sim->stats.extract_ms += (ms_now() - c0) * 1e3;
    }
    sim->primed = 1;
    return MS_OK;
}

/* Eq. 19: N_time = dt_volume / dt_surface wave steps for a frame of dt:
 * the fewest that keep each step within the CFL bound, or the scene's,
 * which must keep within it. */
ms_status ms_sim_plan_waves(const ms_sim *sim, float dt, int *n_time, float *wave_dt)
{
    ms_surface_info info = ms_surface_info_init();
    ms_surface_get_info(sim->surface, &info);
    const double max_dt = info.max_dt; /* s, the CFL bound */
    double n = sim->n_time_fixed;
    if (n > 0) {
        double step = (double)dt / n; /* s */
        if (step > max_dt * (1 + 1e-6))
            return ms_fail(MS_ERR_UNSTABLE,
                           "sim: n_time %d gives wave steps of %.3g s for a frame of %g s; the "
                           "CFL bound of the wave grid allows at most %.3g s (n_time >= %.0f)",
                           sim->n_time_fixed, step, (double)dt, max_dt, ceil(dt / max_dt));
    } else {
        n = ceil((double)dt / max_dt * (1 - 1e-7));
        if (!(n <= 1e7))
            return ms_fail(MS_ERR_UNSTABLE,
                           "sim: a frame of %g s needs %.3g wave steps of at most %.3g s; "
                           "allowed: at most 1e7",
                           (double)dt, n, max_dt);
        n = MS_MAX(n, 1.0);
    }
    *n_time = (int)n;
    *wave_dt = dt / (float)*n_time;
    return MS_OK;
}

/* The second thread's part of a frame: the surface task, then chunks of
 * the volume's loops (ms_vpool_help) until the volume thread closes. */
static void surface_then_help(void *arg)
{
    ms_sim_task *s = arg;
    ms_sim_surface_task(s);
    ms_vpool_help(ms_volume_extract_pool(s->sim->volume));
}

static void run_tasks(ms_sim *sim, ms_sim_task *v, ms_sim_task *s)
{
    int split = sim->threads == 2 && v && s;
    if (split && sim->enqueue) {
        void *h = sim->enqueue(ms_sim_surface_task, s, sim->user_ctx);
        ms_sim_volume_task(v);
        if (h)
            sim->finish(h, sim->user_ctx);
    } else if (split && sim->have_worker) {
        /* the second thread runs the surface task, then takes chunks of
         * the volume's loops until the volume task is done (work sharing,
         * a no-op when the volume has threads of its own) */
        ms_vpool *pool = ms_volume_extract_pool(sim->volume);
        ms_vpool_help_open(pool);
        ms_sim_worker_run(sim, surface_then_help, s);
        ms_sim_volume_task(v);
        ms_vpool_help_close(pool);
        ms_sim_worker_wait(sim);
    } else {
        if (v)
            ms_sim_volume_task(v);
        if (s) {
            s->alone = 1; /* the volume's workers are idle */
            ms_sim_surface_task(s);
        }
    }
}

static ms_status step_frame(ms_sim *sim, float frame_dt);

ms_status ms_sim_step(ms_sim *sim, float frame_dt)
{
    ms_status st = ms_check_not_null("sim", "sim", sim);
    if (st != MS_OK)
        return st;
    /* one thread per handle (sim.h): a second thread caught stepping the
     * same sim is refused, not let in to free what the first one reads */
    if (atomic_exchange(&sim->busy, 1))
        return ms_fail(MS_ERR_STATE,
                       "sim: ms_sim_step while another call is stepping this sim; a sim is "
                       "used by one thread at a time");
    st = step_frame(sim, frame_dt);
    atomic_store(&sim->busy, 0);
    return st;
}

void ms_sim_cancel(ms_sim *sim)
{
    if (!sim)
        return;
    if (sim->volume)
        ms_volume_cancel(sim->volume);
    if (sim->surface)
        ms_surface_cancel(sim->surface);
}

static ms_status step_frame(ms_sim *sim, float frame_dt)
{
    ms_status st = MS_OK;
    if (sim->failed)
        return ms_fail(MS_ERR_STATE, "sim: a previous step failed (%s); destroy the sim",
                       sim->fail_msg);
    /* the frame's dt, checked here once: the tasks take it from the plan */
    if (!isfinite(frame_dt) || !(frame_dt > 0) || frame_dt > 10)
        return ms_fail(MS_ERR_INVALID_ARGUMENT, "sim: frame_dt %g s is outside (0, 10] s",
                       (double)frame_dt);
    ms_frame_plan plan = {.dt = frame_dt};
    if (sim->volume)
        plan.volume_substeps = ms_volume_get_desc(sim->volume).max_substeps;
    /* a fixed N_time too small for this frame: refused before anything
     * runs, not a frame later when the pipeline's waves take
     * it up; a scene's sim was refused at creation already */
    int n_time;
    float wave_dt;
    if (sim->surface && sim->n_time_fixed > 0 &&
        (st = ms_sim_plan_waves(sim, frame_dt, &n_time, &wave_dt)) != MS_OK)
        return st;
    double c0 = ms_now();
    if ((st = ms_sim_worker_ensure(sim)) != MS_OK)
        return st;
    if (!sim->primed && (st = prime(sim)) != MS_OK)
        return st;
    long n = sim->calls + 1;
    ms_frame_plan *waves = &sim->plan[(n - 1) & 1]; /* frame n - 1's, for the surface */
    if (sim->surface && n >= 2 &&
        (st = ms_sim_plan_waves(sim, waves->dt, &waves->n_time, &waves->wave_dt)) != MS_OK)
        return st;
    sim->plan[n & 1] = plan;
    ms_sim_task vt = {.sim = sim, .plan = &sim->plan[n & 1], .status = MS_OK};
    ms_sim_task stt = {.sim = sim, .plan = waves, .status = MS_OK};
    int need_s = sim->volume || sim->surface || sim->nfloaters;
    run_tasks(sim, sim->volume ? &vt : NULL, need_s ? &stt : NULL);
    sim->ndrags = 0; /* an engine's drags last one frame */

    ms_sim_task *bad = vt.status != MS_OK ? &vt : stt.status != MS_OK ? &stt : NULL;
    if (bad) {
        sim->failed = 1;
        sim->fail_status = bad->status;
        snprintf(sim->fail_msg, sizeof sim->fail_msg, "%s", bad->err);
        return ms_fail(bad->status, "%s", bad->err);
    }
    sim->stats.volume_ms += vt.ms_a;
    sim->stats.extract_ms += vt.ms_b + stt.ms_x;
    sim->stats.surface_ms += stt.ms_a;
    sim->stats.combine_ms += stt.ms_b;
    sim->calls = n;
    sim->t_fields = sim->t_volume; /* t_{n-1} */
    sim->t_volume += frame_dt;
    sim->stats.frames = n;
    sim->stats.total_ms += (ms_now() - c0) * 1e3;
    return MS_OK;
}

ms_status ms_sim_set_tasks(ms_sim *sim, ms_enqueue_task_fn *enqueue_task,
                           ms_finish_task_fn *finish_task, void *user_task_context)
{
    ms_status st = ms_check_not_null("sim", "sim", sim);
    if (st != MS_OK)
        return st;
    if ((enqueue_task == NULL) != (finish_task == NULL))
        return ms_fail(MS_ERR_INVALID_ARGUMENT,
                       "sim: enqueue_task and finish_task must both be set or both be NULL");
    sim->enqueue = enqueue_task;
    sim->finish = finish_task;
    sim->user_ctx = user_task_context;
    return ms_sim_setup_threads(sim);
}
