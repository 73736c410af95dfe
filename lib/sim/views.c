/* What a finished frame shows: views of the published fields (frame
 * n - 1 after the n-th step), their grids, particles, floaters, time,
 * statistics; and the engine's interaction calls. */
#include <string.h>

#include "modesplit/surface.h"
#include "modesplit/volume.h"
#include "shape/shape_internal.h"
#include "sim/sim_internal.h"
#include "sim/sim_sizes.h"

/* The slot of the published frame's volume data. */
static int pub_slot(const ms_sim *sim)
{
    return sim->calls > 0 ? (int)((sim->calls - 1) % 2) : 0;
}

const float *ms_sim_volume_height(const ms_sim *sim, int *nx, int *ny)
{
    int ok = sim && sim->volume && sim->primed;
    if (nx)
        *nx = ok ? sim->fnx : 0;
    if (ny)
        *ny = ok ? sim->fny : 0;
    return ok ? sim->hfield[pub_slot(sim)] : NULL;
}

const float *ms_sim_surface_height(const ms_sim *sim, int *nx, int *ny)
{
    if (!sim || !sim->surface) {
        if (nx)
            *nx = 0;
        if (ny)
            *ny = 0;
        return NULL;
    }
    return ms_surface_height(sim->surface, nx, ny);
}

const float *ms_sim_height(const ms_sim *sim, int *nx, int *ny)
{
    if (sim && !sim->surface)
        return ms_sim_volume_height(sim, nx, ny);
    int ok = sim && sim->calls > 0;
    if (nx)
        *nx = ok ? sim->snx : 0;
    if (ny)
        *ny = ok ? sim->sny : 0;
    return ok ? sim->combined : NULL;
}

ms_status ms_sim_field_grid(const ms_sim *sim, unsigned field, ms_grid *out)
{
    ms_status st = ms_check_not_null("sim", "sim", sim);
    if (st == MS_OK)
        st = ms_check_not_null("sim", "out", out);
    if (st != MS_OK)
        return st;
    int vol = field == MS_FIELD_VOLUME || (field == MS_FIELD_COMBINED && !sim->surface);
    if (field != MS_FIELD_COMBINED && field != MS_FIELD_SURFACE && field != MS_FIELD_VOLUME)
        return ms_fail(MS_ERR_INVALID_ARGUMENT,
                       "sim: field %u is not one of MS_FIELD_COMBINED, _SURFACE, _VOLUME", field);
    if ((vol && !sim->volume) || (field == MS_FIELD_SURFACE && !sim->surface))
        return ms_fail(MS_ERR_STATE, "sim: the %s field does not exist: the sim has no %s",
                       vol ? "volume" : "surface", vol ? "volume" : "surface");
    float ex = sim->domain_max[0] - sim->domain_min[0];
    float ey = sim->domain_max[1] - sim->domain_min[1];
    if (vol)
        *out = (ms_grid){.nx = sim->fnx,
                         .ny = sim->fny,
                         .dx = ex / (float)sim->fnx,
                         .dy = ey / (float)sim->fny,
                         .origin = {sim->domain_min[0], sim->domain_min[1]}};
    else
        *out = sim->wave_grid;
    return MS_OK;
}

ms_status ms_sim_particles(const ms_sim *sim, int *n, const float *pos[3], const float *vel[3])
{
    ms_status st = ms_check_not_null("sim", "sim", sim);
    if (st == MS_OK)
        st = ms_check_not_null("sim", "n", n);
    if (st != MS_OK)
        return st;
    int ok = sim->volume && sim->primed;
    int slot = pub_slot(sim);
    *n = ok ? sim->pcount[slot] : 0;
    for (int a = 0; a < 3; ++a) {
        if (pos)
            pos[a] = ok ? sim->ppos[slot][a] : NULL;
        if (vel)
            vel[a] = ok ? sim->pvel[slot][a] : NULL;
    }
    return MS_OK;
}

const float *ms_sim_floaters(const ms_sim *sim, int *n)
{
    int have = sim && sim->nfloaters > 0;
    if (n)
        *n = have ? sim->nfloaters : 0;
    return have ? sim->floater_xyz : NULL;
}

const float *ms_sim_spray(const ms_sim *sim, int *n)
{
    int have = sim && sim->spray.cap > 0;
    if (n)
        *n = have ? sim->spray.n : 0;
    return have ? sim->spray.pos : NULL;
}

const float *ms_sim_foam(const ms_sim *sim, int *nx, int *ny)
{
    int have = sim && sim->spray.cap > 0;
    if (nx)
        *nx = have ? sim->spray.gnx : 0;
    if (ny)
        *ny = have ? sim->spray.gny : 0;
    return have ? sim->spray.foam : NULL;
}

ms_status ms_sim_foam_grid(const ms_sim *sim, ms_grid *out)
{
    MS_TRY(ms_check_not_null("sim", "sim", sim));
    MS_TRY(ms_check_not_null("sim", "out", out));
    if (!sim->spray.cap)
        return ms_fail(MS_ERR_STATE, "sim: no foam without the scene's effects.spray");
    *out = (ms_grid){.nx = sim->spray.gnx,
                     .ny = sim->spray.gny,
                     .dx = sim->spray.gdx,
                     .dy = sim->spray.gdy,
                     .origin = {sim->domain_min[0], sim->domain_min[1]}};
    return MS_OK;
}

double ms_sim_time(const ms_sim *sim)
{
    return sim ? sim->t_fields : 0;
}

long ms_sim_frame(const ms_sim *sim)
{
    return sim ? sim->calls : 0;
}

const ms_scene *ms_sim_scene(const ms_sim *sim)
{
    return sim ? sim->scene : NULL;
}

ms_volume *ms_sim_volume(ms_sim *sim)
{
    return sim ? sim->volume : NULL;
}

ms_surface *ms_sim_surface(ms_sim *sim)
{
    return sim ? sim->surface : NULL;
}

void ms_sim_stats(const ms_sim *sim, ms_stats *out)
{
    ms_sim_get_stats(sim, out);
}

void ms_sim_get_stats(const ms_sim *sim, ms_stats *user)
{
    size_t size = ms_struct_out(user, MS_SIZES_STATS, "sim");
    if (!size)
        return;
    ms_stats full = ms_stats_init(), *out = &full;
    if (!sim) {
        ms_struct_write(user, &full, size);
        return;
    }
    *out = sim->stats;
    out->volume_bytes = sim->own_volume_bytes;
    out->surface_bytes = sim->own_surface_bytes;
    out->effects_bytes = sim->own_effects_bytes;
    if (sim->volume) {
        ms_volume_info vi = ms_volume_info_init();
        ms_volume_get_info(sim->volume, &vi);
        out->volume_steps = vi.substeps;
        out->volume_bytes += vi.bytes;
        for (int k = 0; k < 2; ++k)
            out->volume_bytes +=
                (size_t)sim->pcap[k] * 6 * sizeof(float) + ms_extract_snap_bytes(&sim->snap[k]);
        out->volume_bytes +=
            ms_extract_work_bytes(&sim->work_v) + ms_extract_work_bytes(&sim->work_s);
    }
    if (sim->surface) {
        ms_surface_info si = ms_surface_info_init();
        ms_surface_get_info(sim->surface, &si);
        out->surface_steps = si.substeps;
        out->surface_bytes += si.bytes;
        out->drops = si.drops;
        out->n_time = ms_sim_wave_plan(sim)->n_time;
    }
    out->spray = sim->spray.n;
    out->spray_emitted = sim->spray.emitted;
    out->spray_ms = sim->spray.ms;
    out->bytes = sizeof *sim + out->volume_bytes + out->surface_bytes + out->effects_bytes;
    ms_struct_write(user, &full, size);
}

void ms_sim_get_info(const ms_sim *sim, ms_sim_info *user)
{
    size_t size = ms_struct_out(user, MS_SIZES_SIM_INFO, "sim");
    if (!size)
        return;
    ms_sim_info full = ms_sim_info_init(), *out = &full;
    if (!sim) {
        ms_struct_write(user, &full, size);
        return;
    }
    out->has_volume = sim->volume != NULL;
    out->has_surface = sim->surface != NULL;
    out->threads = sim->threads;
    if (sim->volume) {
        out->field_nx = sim->fnx;
        out->field_ny = sim->fny;
        out->particles = ms_volume_count(sim->volume);
        out->spacing = sim->spacing;
        out->spray_budget = sim->spray.cap;
    }
    if (sim->surface) {
        out->surface_nx = sim->snx;
        out->surface_ny = sim->sny;
    }
    if (sim->volume && sim->surface) {
        out->n_surf_x = (float)sim->snx / (float)sim->fnx;
        out->n_surf_y = (float)sim->sny / (float)sim->fny;
    }
    out->n_time = sim->n_time_fixed;
    out->floaters = sim->nfloaters;
    out->obstacles = sim->nshapes;
    ms_struct_write(user, &full, size);
}

ms_status ms_sim_drag(ms_sim *sim, const float pos[2], const float vel[2], float radius,
                      float depth, float strength)
{
    ms_status st = ms_check_not_null("sim", "sim", sim);
    if (st == MS_OK)
        st = ms_check_not_null("sim", "pos", pos);
    if (st == MS_OK)
        st = ms_check_not_null("sim", "vel", vel);
    if (st != MS_OK)
        return st;
    if (!sim->volume)
        return ms_fail(MS_ERR_STATE,
                       "sim: drag moves the volume and this sim has none (add a disturber to "
                       "ms_sim_surface instead)");
    if (sim->ndrags >= MS_SIM_MAX_DRAGS)
        return ms_fail(MS_ERR_STATE, "sim: %d drags are queued for this frame already; allowed: %d",
                       sim->ndrags, MS_SIM_MAX_DRAGS);
    static const char *const pk[2] = {"drag pos[0]", "drag pos[1]"};
    static const char *const vk[2] = {"drag vel[0]", "drag vel[1]"};
    for (int k = 0; k < 2 && st == MS_OK; ++k) {
        st = ms_check_range("sim", pk[k], pos[k], -1e4, 1e4, "m");
        if (st == MS_OK)
            st = ms_check_range("sim", vk[k], vel[k], -1e3, 1e3, "m/s");
    }
    if (st == MS_OK)
        st = ms_check_range("sim", "drag radius", radius, 1e-6, 100, "m");
    if (st == MS_OK)
        st = ms_check_range("sim", "drag depth", depth, 0, 100, "m");
    if (st == MS_OK)
        st = ms_check_range("sim", "drag strength", strength, 1e-6, 1e4, "1/s");
    if (st != MS_OK)
        return st;
    ms_sim_drag_req *r = &sim->drags[sim->ndrags++];
    memcpy(r->pos, pos, sizeof r->pos);
    memcpy(r->vel, vel, sizeof r->vel);
    r->radius = radius;
    r->depth = depth;
    r->strength = strength;
    return MS_OK;
}

/* A shape the engine moves or turns becomes a moving footprint: take it out
 * of the static mask. */
static ms_status unfreeze_mask(ms_sim *sim)
{
    ms_status st = MS_OK;
    size_t ns = (size_t)sim->snx * sim->sny;
    memset(sim->mask_static, 0, ns);
    float z = sim->domain_min[2] + sim->level;
    for (int j = 0; j < sim->nshapes; ++j) {
        ms_sim_shape *o = &sim->shapes[j];
        if (o->surf && !ms_sim_shape_dynamic(o) &&
            (st = ms_shape_footprint(o->surf, &sim->wave_grid, z, sim->mask_static)) != MS_OK)
            return st;
    }
    sim->have_moving_mask = 1;
    return MS_OK;
}

static ms_status move_shape(ms_sim *sim, int i, const char *what, const float pos[3],
                            const float vel[3])
{
    ms_status st = ms_check_not_null("sim", "pos", pos);
    if (st != MS_OK)
        return st;
    for (int k = 0; k < 3 && st == MS_OK; ++k) {
        st = ms_check_range("sim", "pos", pos[k], -1e4, 1e4, "m");
        if (st == MS_OK && vel)
            st = ms_check_range("sim", "vel", vel[k], -1e3, 1e3, "m/s");
    }
    if (st != MS_OK)
        return st;
    (void)what;
    ms_sim_shape *sh = &sim->shapes[i];
    sh->api_set = 1;
    memcpy(sh->api_pos, pos, sizeof sh->api_pos);
    for (int k = 0; k < 3; ++k)
        sh->api_vel[k] = vel ? vel[k] : 0.0f;
    if (sh->surf && !sim->have_moving_mask)
        return unfreeze_mask(sim);
    return MS_OK;
}

static ms_status turn_shape(ms_sim *sim, int i, const float quat[4], const float omega[3])
{
    ms_status st = ms_check_not_null("sim", "orientation", quat);
    if (st == MS_OK)
        st = ms_shape_check_orientation("sim", quat, omega);
    if (st != MS_OK)
        return st;
    ms_sim_shape *sh = &sim->shapes[i];
    sh->api_turn = 1;
    memcpy(sh->api_quat, quat, sizeof sh->api_quat);
    for (int k = 0; k < 3; ++k)
        sh->api_omega[k] = omega ? omega[k] : 0.0f;
    if (sh->surf && !sim->have_moving_mask)
        return unfreeze_mask(sim);
    return MS_OK;
}

/* The index in sim->shapes of the container or of obstacle i, or the
 * refusal. */
static ms_status shape_index(ms_sim *sim, int container, int i, int *at)
{
    ms_status st = ms_check_not_null("sim", "sim", sim);
    if (st != MS_OK)
        return st;
    if (container) {
        if (sim->container < 0)
            return ms_fail(MS_ERR_STATE, "sim: the scene has no container (effects.container)");
        *at = sim->container;
        return MS_OK;
    }
    int nobs = sim->container >= 0 ? sim->nshapes - 1 : sim->nshapes;
    if (nobs == 0)
        return ms_fail(MS_ERR_STATE, "sim: the scene has no obstacles");
    if (i < 0 || i >= nobs)
        return ms_fail(MS_ERR_INVALID_ARGUMENT, "sim: obstacle %d is outside [0, %d)", i, nobs);
    *at = i;
    return MS_OK;
}

ms_status ms_sim_turn_container(ms_sim *sim, const float orientation[4], const float omega[3])
{
    int at = -1;
    ms_status st = shape_index(sim, 1, 0, &at);
    return st != MS_OK ? st : turn_shape(sim, at, orientation, omega);
}

ms_status ms_sim_turn_obstacle(ms_sim *sim, int i, const float orientation[4], const float omega[3])
{
    int at = -1;
    ms_status st = shape_index(sim, 0, i, &at);
    return st != MS_OK ? st : turn_shape(sim, at, orientation, omega);
}

ms_status ms_sim_move_container(ms_sim *sim, const float pos[3], const float vel[3])
{
    int at = -1;
    ms_status st = shape_index(sim, 1, 0, &at);
    return st != MS_OK ? st : move_shape(sim, at, "container", pos, vel);
}

ms_status ms_sim_move_obstacle(ms_sim *sim, int i, const float pos[3], const float vel[3])
{
    int at = -1;
    ms_status st = shape_index(sim, 0, i, &at);
    return st != MS_OK ? st : move_shape(sim, at, "obstacle", pos, vel);
}
