/* Creating a sim from a desc (engines) or a scene: the two solvers, the
 * grids of eq. 20, the hand-over buffers of the pipeline, and the scene's
 * effects. Only what is asked for is allocated. */
#include <string.h>

#include "modesplit/volume.h"
#include "sim/sim_internal.h"
#include "volume/volume_internal.h"
#include "sim/sim_sizes.h"
#include "surface/surface_sizes.h"
#include "volume/volume_sizes.h"

ms_sim_desc ms_sim_desc_default(void)
{
    ms_sim_desc d;
    memset(&d, 0, sizeof d);
    d.size = (uint32_t)sizeof d;
    d.volume = NULL;
    d.surface = NULL;
    d.field_nx = d.field_ny = 0; /* derived */
    d.surface_substeps = 0;      /* derived (eq. 19) */
    d.couple_surface_from_volume = 0;
    d.couple_volume_from_surface = 0;
    d.threads = 1;
    return d;
}

static void *sim_alloc(size_t *account, size_t count, size_t size)
{
    void *p = ms_alloc_array(count, size);
    if (p)
        *account += count * size;
    return p;
}

static ms_status oom(const char *what)
{
    return ms_fail(MS_ERR_OUT_OF_MEMORY, "sim: out of memory for %s", what);
}

static ms_status check_own(const ms_sim_desc *d)
{
    if (!d->volume && !d->surface)
        return ms_fail(MS_ERR_INVALID_ARGUMENT,
                       "sim: desc has neither a volume nor a surface; give at least one");
    MS_TRY(ms_check_int_range("sim", "field_nx", d->field_nx, 0, 4096));
    MS_TRY(ms_check_int_range("sim", "field_ny", d->field_ny, 0, 4096));
    if ((d->field_nx == 0) != (d->field_ny == 0))
        return ms_fail_key(MS_ERR_INVALID_ARGUMENT, "field_nx",
                           "sim: field_nx %d and field_ny %d must both be 0 (derived) or both set",
                           d->field_nx, d->field_ny);
    if (d->field_nx == 1 || d->field_ny == 1)
        return ms_fail_key(MS_ERR_INVALID_ARGUMENT, "field_nx",
                           "sim: field %d x %d must be at least 2 x 2", d->field_nx, d->field_ny);
    MS_TRY(ms_check_int_range("sim", "surface_substeps", d->surface_substeps, 0, 100000));
    /* [0, 1]: the waves are displaced by at most the SPH surface's own
     * change; a gain above 1 amplified it into waves of tens of metres in a
     * 0.5 m pool, and 1 (with volume_from_surface 1) still grew fig10's
     * field past its 0.5 m depth within 7 s; 0.25 (5x the shipped 0.05)
     * kept fig1 and fig10 within 0.33 m over the first 300 and 360
     * simulated seconds with volume_from_surface at 1 (measured), and
     * test_stability's check-long cases hold them within 0.5 m for 10
     * simulated minutes */
    MS_TRY(ms_check_range("sim", "couple_surface_from_volume", d->couple_surface_from_volume, 0,
                          0.25, ""));
    MS_TRY(ms_check_range("sim", "couple_volume_from_surface", d->couple_volume_from_surface, 0, 1,
                          ""));
    MS_TRY(ms_check_int_range("sim", "threads", d->threads, 1, 2));
    if ((d->enqueue_task == NULL) != (d->finish_task == NULL))
        return ms_fail_key(MS_ERR_INVALID_ARGUMENT, "enqueue_task",
                           "sim: enqueue_task and finish_task must both be set or both be NULL");
    return MS_OK;
}

/* The one check across the parts, made after each part has checked its
 * own desc (in its create), so that a bad value is named by its part
 * ("surface: dx -1 m ...") rather than through the extent it spoils. */
static ms_status check_extent(const ms_sim_desc *d)
{
    if (d->volume && d->surface) {
        /* one x-y extent for both fields */
        const ms_volume_desc *v = d->volume;
        const ms_surface_desc *s = d->surface;
        double ex = (double)v->domain_max[0] - v->domain_min[0];
        double ey = (double)v->domain_max[1] - v->domain_min[1];
        double sx = (double)s->nx * s->dx, sy = (double)s->ny * s->dx;
        if (!(fabs(sx - ex) <= 1e-3 * ex) || !(fabs(sy - ey) <= 1e-3 * ey))
            return ms_fail(MS_ERR_INVALID_ARGUMENT,
                           "sim: the wave grid spans %g m x %g m (nx %d, ny %d, dx %g m) but the "
                           "volume domain %g m x %g m; both fields must cover the same x-y "
                           "extent",
                           sx, sy, s->nx, s->ny, (double)s->dx, ex, ey);
    }
    return MS_OK;
}

/* Field cells per particle spacing (eq. 16-18): the derived field has 2;
 * past 8 a cell is narrower than an eighth of the spacing, holds no
 * particle of its own, and only adds extraction work (a 4096 x 4096 field
 * over fig1's 20 spacings took 43 s of extraction a frame). */
#define MAX_FIELD_PER_SPACING 8

static ms_status check_field_resolution(const ms_sim_desc *d)
{
    const ms_volume_desc *v = d->volume;
    const int n[2] = {d->field_nx, d->field_ny};
    for (int a = 0; a < 2; ++a) {
        double spacings = ((double)v->domain_max[a] - v->domain_min[a]) / v->spacing;
        double most = MS_MAX(2.0, floor(MAX_FIELD_PER_SPACING * spacings + 1e-3));
        if (n[a] > most)
            return ms_fail_key(MS_ERR_INVALID_ARGUMENT, a ? "field_ny" : "field_nx",
                               "sim: %s %d puts %.3g field cells on each particle spacing "
                               "(%g m, %.4g spacings across the domain); allowed: at most %d a "
                               "spacing (%s <= %.0f): finer cells hold no particle and cost "
                               "extraction time for nothing",
                               a ? "field_ny" : "field_nx", n[a], n[a] / spacings,
                               (double)v->spacing, spacings, MAX_FIELD_PER_SPACING,
                               a ? "field_ny" : "field_nx", most);
    }
    return MS_OK;
}

/* The sim's own fields, then each part's desc (a bad value named by its
 * part), then the extent the parts must share. */
static ms_status check_all(const ms_sim_desc *d)
{
    MS_TRY(check_own(d));
    if (d->volume) {
        MS_TRY(ms_volume_desc_check(d->volume));
        MS_TRY(check_field_resolution(d));
    }
    if (d->surface) {
        MS_TRY(ms_surface_desc_check(d->surface));
        ms_surface_desc sd = ms_surface_desc_default();
        MS_TRY(ms_struct_in(d->surface, &sd, MS_SIZES_SURFACE_DESC, "surface"));
        if (sd.advect && !d->volume)
            return ms_fail_key(MS_ERR_INVALID_ARGUMENT, "advect",
                               "surface: advect 1 needs a volume, whose flow carries the waves "
                               "(a surface alone: ms_surface_set_current)");
    }
    return check_extent(d);
}

static ms_status alloc_buffers(ms_sim *sim, int floaters)
{
    size_t nf = (size_t)sim->fnx * (size_t)sim->fny;
    size_t ns = (size_t)sim->snx * (size_t)sim->sny;
    /* the surface flow is the floaters' and, with surface.advect, the
     * current that carries the waves (surface_task.c): one extraction
     * for both */
    const int advect = sim->volume && sim->surface && ms_surface_get_desc(sim->surface).advect;
    const int flow = floaters || advect;
    if (sim->volume) {
        for (int k = 0; k < 2; ++k) {
            sim->hfield[k] = sim_alloc(&sim->own_volume_bytes, nf, sizeof(float));
            if (!sim->hfield[k])
                return oom("the SPH height field");
            if (flow) {
                sim->flow[k] = sim_alloc(&sim->own_effects_bytes, 2 * nf, sizeof(float));
                if (!sim->flow[k])
                    return oom("the surface flow");
            }
        }
        if (flow) {
            sim->flow_count = sim_alloc(&sim->own_effects_bytes, nf, sizeof(float));
            if (!sim->flow_count)
                return oom("the surface flow");
        }
    }
    if (advect) {
        /* the flow's averaging (surface_task.c) and the current on the wave grid */
        sim->flow_comp = sim_alloc(&sim->own_effects_bytes, 4 * nf, sizeof(float));
        for (int k = 0; k < 2; ++k)
            sim->current[k] = sim_alloc(&sim->own_effects_bytes, ns, sizeof(float));
        sim->current_wall = sim_alloc(&sim->own_effects_bytes, ns, sizeof(float));
        sim->current_line =
            sim_alloc(&sim->own_effects_bytes, (size_t)MS_MAX(sim->snx, sim->sny), sizeof(float));
        if (!sim->flow_comp || !sim->current[0] || !sim->current[1] || !sim->current_wall ||
            !sim->current_line)
            return oom("the current that carries the waves");
    }
    if (sim->surface) {
        sim->combined = sim_alloc(&sim->own_surface_bytes, ns, sizeof(float));
        if (!sim->combined)
            return oom("the combined field");
        sim->wave_grid = (ms_grid){.nx = sim->snx,
                                   .ny = sim->sny,
                                   .dx = sim->sdx,
                                   .dy = sim->sdx,
                                   .origin = {sim->domain_min[0], sim->domain_min[1]}};
        if (sim->volume) {
            MS_TRY(ms_sim_upsample_init(sim));
            if (sim->gain_sv > 0) {
                sim->hprev = sim_alloc(&sim->own_surface_bytes, nf, sizeof(float));
                sim->dh = sim_alloc(&sim->own_surface_bytes, nf, sizeof(float));
                sim->u_prev = sim_alloc(&sim->own_surface_bytes, nf, sizeof(float));
                sim->excite = sim_alloc(&sim->own_surface_bytes, ns, sizeof(float));
                sim->rim = sim_alloc(&sim->own_surface_bytes, nf, 1);
                sim->rim_row = sim_alloc(&sim->own_surface_bytes, nf, 1);
                if (!sim->hprev || !sim->dh || !sim->u_prev || !sim->excite || !sim->rim ||
                    !sim->rim_row)
                    return oom("the volume->surface coupling");
            }
            if (sim->gain_vs > 0) {
                /* the waves averaged over each SPH cell, for the volume */
                for (int k = 0; k < 2; ++k) {
                    sim->wave_snap[k] = sim_alloc(&sim->own_volume_bytes, nf, sizeof(float));
                    if (!sim->wave_snap[k])
                        return oom("the surface->volume coupling");
                }
                /* and the volume's record of them (steps allocate nothing) */
                MS_TRY(ms_volume_reserve_waves(sim->volume, nf));
                sim->wave_colmap =
                    sim_alloc(&sim->own_surface_bytes, (size_t)sim->snx, sizeof *sim->wave_colmap);
                sim->wave_rowsum = sim_alloc(&sim->own_surface_bytes, nf, sizeof(float));
                if (!sim->wave_colmap || !sim->wave_rowsum)
                    return oom("the surface->volume coupling");
                for (int i = 0; i < sim->snx; ++i) /* the SPH column of wave column i */
                    sim->wave_colmap[i] = (int)(((2L * i + 1) * sim->fnx) / (2L * sim->snx));
                sim->field_grid =
                    (ms_grid){.nx = sim->fnx,
                              .ny = sim->fny,
                              .dx = (sim->domain_max[0] - sim->domain_min[0]) / (float)sim->fnx,
                              .dy = (sim->domain_max[1] - sim->domain_min[1]) / (float)sim->fny,
                              .origin = {sim->domain_min[0], sim->domain_min[1]}};
            }
        }
    }
    return MS_OK;
}

/* About two field cells per particle spacing, the finest the particles
 * resolve, and no finer than the wave grid. */
static int derive_field(float extent, float spacing, int wave_n)
{
    double n = floor(2.0 * extent / spacing + 0.5);
    n = MS_CLAMP(n, 2.0, 4096.0);
    if (wave_n > 0 && n > wave_n)
        n = wave_n;
    return (int)n;
}

/* The caller's descs (sim, volume, surface) read at the sizes they were
 * built with (core.h: struct sizes) into the sim's own copies. */
typedef struct descs {
    ms_sim_desc sim;
    ms_volume_desc volume;
    ms_surface_desc surface;
} descs;

static ms_status read_descs(const ms_sim_desc *user, descs *out)
{
    out->sim = ms_sim_desc_default();
    MS_TRY(ms_struct_in(user, &out->sim, MS_SIZES_SIM_DESC, "sim"));
    if (out->sim.volume) {
        out->volume = ms_volume_desc_default();
        MS_TRY(ms_struct_in(out->sim.volume, &out->volume, MS_SIZES_VOLUME_DESC, "volume"));
        out->sim.volume = &out->volume;
    }
    if (out->sim.surface) {
        out->surface = ms_surface_desc_default();
        MS_TRY(ms_struct_in(out->sim.surface, &out->surface, MS_SIZES_SURFACE_DESC, "surface"));
        out->sim.surface = &out->surface;
    }
    return MS_OK;
}

ms_status ms_sim_desc_check(const ms_sim_desc *user)
{
    descs ds;
    MS_TRY(read_descs(user, &ds));
    return check_all(&ds.sim);
}

static ms_status create_common(const ms_sim_desc *user, const float *origin, float level,
                               const ms_scene *sc, ms_sim **out)
{
    MS_TRY(ms_check_not_null("sim", "out", out));
    *out = NULL;
    descs ds;
    MS_TRY(read_descs(user, &ds));
    const ms_sim_desc *d = &ds.sim;
    MS_TRY(check_all(d));
    ms_sim *sim = ms_alloc(sizeof *sim);
    if (!sim)
        return oom("the sim");
    sim->scene = sc;
    sim->threads = d->threads;
    sim->enqueue = d->enqueue_task;
    sim->finish = d->finish_task;
    sim->user_ctx = d->user_task_context;
    sim->n_time_fixed = d->surface_substeps;
    sim->gain_sv = d->couple_surface_from_volume;
    sim->gain_vs = d->couple_volume_from_surface;
    sim->level = level;
    sim->gravity = 9.81f;
    sim->container = -1;
    sim->boat_id = sim->drag_id = 0;

    ms_status st = MS_OK;
    if (d->volume) {
        ms_volume_desc vd = *d->volume;
        /* threads is the sim's whole budget: one thread runs everything on
         * it. On two, the surface thread takes the extraction's column
         * search even in a volume-only sim, so the volume keeps its own
         * count (default 1): a second SPH thread would compete with it
         * (fig4c_x10: 1.87x with 1 against 1.26x with 2; any count gives
         * the same bytes). */
        if (d->threads == 1)
            vd.threads = 1;
        st = ms_volume_create(&vd, &sim->volume);
        if (st == MS_OK) {
            memcpy(sim->domain_min, vd.domain_min, sizeof sim->domain_min);
            memcpy(sim->domain_max, vd.domain_max, sizeof sim->domain_max);
            sim->spacing = vd.spacing;
            double g =
                sqrt((double)vd.gravity[0] * vd.gravity[0] + (double)vd.gravity[1] * vd.gravity[1] +
                     (double)vd.gravity[2] * vd.gravity[2]);
            sim->gravity = (float)g;
        }
    }
    if (st == MS_OK && d->surface) {
        st = ms_surface_create(d->surface, &sim->surface);
        if (st == MS_OK) {
            sim->snx = d->surface->nx;
            sim->sny = d->surface->ny;
            sim->sdx = d->surface->dx;
            if (!d->volume) {
                float o[2] = {0, 0};
                if (origin)
                    memcpy(o, origin, sizeof o);
                sim->domain_min[0] = o[0];
                sim->domain_min[1] = o[1];
                sim->domain_max[0] = o[0] + (float)sim->snx * sim->sdx;
                sim->domain_max[1] = o[1] + (float)sim->sny * sim->sdx;
                sim->domain_min[2] = origin ? origin[2] : 0;
                sim->domain_max[2] = origin ? origin[3] : 0;
            }
        }
    }
    if (st == MS_OK && sim->volume) {
        sim->fnx = d->field_nx ? d->field_nx
                               : derive_field(sim->domain_max[0] - sim->domain_min[0], sim->spacing,
                                              sim->snx);
        sim->fny = d->field_ny ? d->field_ny
                               : derive_field(sim->domain_max[1] - sim->domain_min[1], sim->spacing,
                                              sim->sny);
    }
    /* the surface flow: floaters ride it, foam is carried by it */
    int floaters = sc && (sc->has_floaters || sc->has_spray);
    if (st == MS_OK)
        st = alloc_buffers(sim, floaters);
    if (st == MS_OK && sc)
        st = ms_sim_setup_effects(sim, sc);
    if (st == MS_OK) /* the second thread, or the engine's tasks for it and the loops */
        st = ms_sim_setup_threads(sim);
    if (st != MS_OK) {
        ms_sim_destroy(sim);
        return st;
    }
    *out = sim;
    return MS_OK;
}

/* The bounds a frame of frame_dt seconds cannot meet by sub-stepping:
 * a fixed N_time (eq. 19) whose wave steps exceed the CFL bound of the
 * wave grid, and an SPH frame needing more than max_substeps sub-steps
 * even at rest (the bound ms_volume_step applies before any work: no
 * state allows a sub-step over courant h / c0). ms_sim_create has no frame
 * yet: there ms_sim_step refuses them on the first call. */
static ms_status check_scene_frame(const ms_sim *sim, double frame_dt)
{
    if (sim->surface) {
        int n_time;
        float wave_dt;
        MS_TRY(ms_sim_plan_waves(sim, (float)frame_dt, &n_time, &wave_dt));
    }
    if (sim->volume) {
        ms_volume_desc vd = ms_volume_get_desc(sim->volume);
        ms_volume_info in = ms_volume_info_init();
        ms_volume_get_info(sim->volume, &in);
        const double at_rest = (double)vd.courant * vd.smoothing_length / in.sound_speed;
        const double least = ceil(frame_dt / at_rest);
        if (in.sound_speed > 0 && least > vd.max_substeps)
            return ms_fail(MS_ERR_UNSTABLE,
                           "sim: a frame of %g s needs at least %.3g SPH sub-steps (courant %g, "
                           "smoothing_length %g m, sound speed %g m/s: at most %.3g s each even "
                           "at rest), more than max_substeps %d",
                           frame_dt, least, (double)vd.courant, (double)vd.smoothing_length,
                           (double)in.sound_speed, at_rest, vd.max_substeps);
    }
    return MS_OK;
}

ms_status ms_sim_create(const ms_sim_desc *d, ms_sim **out)
{
    return create_common(d, NULL, 0, NULL, out);
}

ms_status ms_sim_create_from_scene(const ms_scene *sc, int threads, ms_sim **out)
{
    MS_TRY(ms_check_not_null("sim", "out", out));
    *out = NULL;
    MS_TRY(ms_check_not_null("sim", "scene", sc));
    MS_TRY(ms_check_int_range("sim", "threads", threads, 0, 2));
    /* the scene's descs as its keys set them (lib/scene/sections.c) */
    ms_sim_desc d = sc->sim;
    if (threads)
        d.threads = threads;
    float origin[4] = {sc->domain_min[0], sc->domain_min[1], sc->domain_min[2], sc->domain_max[2]};
    ms_sim *sim;
    MS_TRY(create_common(&d, origin, sc->level, sc, &sim));
    /* the scene knows its frame: what no sub-stepping can make stable at
     * that frame is refused here, at creation */
    ms_status bad = check_scene_frame(sim, sc->frame_dt);
    if (bad != MS_OK) {
        ms_sim_destroy(sim);
        return bad;
    }
    for (int i = 0; i < sc->nfill; ++i) {
        ms_status st = ms_volume_fill_box(sim->volume, sc->fill_lo[i], sc->fill_hi[i]);
        if (st != MS_OK) {
            ms_sim_destroy(sim);
            return st;
        }
    }
    if (sc->nfill > 0) {
        ms_status st = ms_volume_settle(sim->volume, sc->settle);
        if (st != MS_OK) {
            ms_sim_destroy(sim);
            return st;
        }
    }
    *out = sim;
    return MS_OK;
}

void ms_sim_destroy(ms_sim *sim)
{
    if (!sim)
        return;
    ms_sim_worker_stop(sim);
    for (int i = 0; i < sim->nshapes; ++i) {
        ms_sim_shape *sh = &sim->shapes[i];
        if (sh->vol && sim->volume)
            ms_volume_remove_collider(sim->volume, sh->vol);
        ms_shape_destroy(sh->vol);
        ms_shape_destroy(sh->surf);
        ms_shape_destroy(sh->spray);
    }
    ms_free(sim->shapes);
    ms_volume_destroy(sim->volume);
    ms_surface_destroy(sim->surface);
    for (int k = 0; k < 2; ++k) {
        ms_free(sim->hfield[k]);
        ms_extract_snap_free(&sim->snap[k]);
        ms_free(sim->flow[k]);
        ms_free(sim->wave_snap[k]);
        ms_free(sim->ppos[k][0]); /* one block per slot (volume_task.c) */
        ms_free(sim->pvel[k][0]);
    }
    ms_free(sim->wave_colmap);
    ms_free(sim->wave_rowsum);
    ms_free(sim->flow_count);
    ms_free(sim->flow_comp);
    ms_free(sim->current[0]);
    ms_free(sim->current[1]);
    ms_free(sim->current_wall);
    ms_free(sim->current_line);
    ms_extract_work_free(&sim->work_v);
    ms_extract_work_free(&sim->work_s);
    ms_free(sim->hprev);
    ms_free(sim->dh);
    ms_free(sim->u_prev);
    ms_free(sim->rim);
    ms_free(sim->rim_row);
    ms_free(sim->excite);
    ms_free(sim->combined);
    ms_sim_upsample_free(sim);
    ms_free(sim->mask_static);
    ms_free(sim->mask);
    ms_free(sim->drop_order);
    ms_free(sim->boat_xy);
    ms_free(sim->floater_xyz);
    ms_free(sim->floater_vel);
    ms_sim_spray_free(sim);
    ms_free(sim);
}
