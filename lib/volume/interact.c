/* Interaction between steps: the paper's mouse drag (a velocity imposed in
 * a region), pushes (an acceleration in a region), removing particles, a
 * viscosity change, and the coupling from the surface waves (paper 3.5). */
#include <math.h>
#include <string.h>

#include "volume/volume_internal.h"

static ms_status check_vec(const char *what, const float *p, const char *unit)
{
    if (!p)
        return ms_fail(MS_ERR_INVALID_ARGUMENT, "volume: %s is NULL", what);
    if (!isfinite(p[0]) || !isfinite(p[1]) || !isfinite(p[2]) || fabsf(p[0]) > 1e6f ||
        fabsf(p[1]) > 1e6f || fabsf(p[2]) > 1e6f)
        return ms_fail(MS_ERR_INVALID_ARGUMENT,
                       "volume: %s (%g, %g, %g) %s must be finite and within 1e6", what, p[0], p[1],
                       p[2], unit);
    return MS_OK;
}

static ms_status add_action(ms_volume *v, ms_action_kind kind, const float centre[3], float radius,
                            const float vec[3], float strength)
{
    const char *name = kind == MS_ACTION_DRAG ? "drag" : "push";
    if (!v)
        return ms_fail(MS_ERR_INVALID_ARGUMENT, "volume: %s on a NULL volume", name);
    ms_status st = check_vec(kind == MS_ACTION_DRAG ? "drag centre" : "push centre", centre, "m");
    if (st != MS_OK)
        return st;
    st = check_vec(kind == MS_ACTION_DRAG ? "drag velocity" : "push acceleration", vec,
                   kind == MS_ACTION_DRAG ? "m/s" : "m/s^2");
    if (st != MS_OK)
        return st;
    if (!isfinite(radius) || !(radius > 0.0f) || radius > 1e6f)
        return ms_fail(MS_ERR_INVALID_ARGUMENT, "volume: %s radius %g m must be in (0, 1e6]", name,
                       radius);
    if (kind == MS_ACTION_DRAG && (!isfinite(strength) || strength < 0.0f || strength > 1e6f))
        return ms_fail(MS_ERR_INVALID_ARGUMENT, "volume: drag strength %g 1/s must be in [0, 1e6]",
                       strength);
    if (v->nactions >= MS_VOLUME_MAX_ACTIONS)
        return ms_fail(MS_ERR_INVALID_ARGUMENT, "volume: %s: at most %d drags and pushes per step",
                       name, MS_VOLUME_MAX_ACTIONS);
    ms_action *a = &v->actions[v->nactions++];
    a->kind = kind;
    memcpy(a->centre, centre, sizeof a->centre);
    memcpy(a->vec, vec, sizeof a->vec);
    a->radius = radius;
    a->strength = strength;
    return MS_OK;
}

ms_status ms_volume_drag(ms_volume *v, const float centre[3], float radius, const float velocity[3],
                         float strength)
{
    return add_action(v, MS_ACTION_DRAG, centre, radius, velocity, strength);
}

ms_status ms_volume_push(ms_volume *v, const float centre[3], float radius, const float accel[3])
{
    return add_action(v, MS_ACTION_PUSH, centre, radius, accel, 0.0f);
}

/* (1 - r/R)^2 inside the ball, 0 outside */
static float weight(const ms_action *a, float x, float y, float z)
{
    float dx = x - a->centre[0], dy = y - a->centre[1], dz = z - a->centre[2];
    float r2 = dx * dx + dy * dy + dz * dz;
    if (r2 >= a->radius * a->radius)
        return 0.0f;
    float q = 1.0f - sqrtf(r2) / a->radius;
    return q * q;
}

void ms_volume_actions_accel(ms_volume *v)
{
    for (int k = 0; k < v->nactions; ++k) {
        const ms_action *a = &v->actions[k];
        if (a->kind != MS_ACTION_PUSH)
            continue;
        for (int i = 0; i < v->n; ++i) {
            float w = weight(a, v->x[i], v->y[i], v->z[i]);
            if (w > 0.0f) {
                v->ax[i] += w * a->vec[0];
                v->ay[i] += w * a->vec[1];
                v->az[i] += w * a->vec[2];
            }
        }
    }
}

void ms_volume_actions_drag(ms_volume *v, float dt)
{
    for (int k = 0; k < v->nactions; ++k) {
        const ms_action *a = &v->actions[k];
        if (a->kind != MS_ACTION_DRAG)
            continue;
        for (int i = 0; i < v->n; ++i) {
            float w = weight(a, v->x[i], v->y[i], v->z[i]);
            if (w > 0.0f) {
                /* exact relaxation: a convex blend of v and the target */
                float keep = expf(-a->strength * w * dt);
                v->vx[i] = a->vec[0] + (v->vx[i] - a->vec[0]) * keep;
                v->vy[i] = a->vec[1] + (v->vy[i] - a->vec[1]) * keep;
                v->vz[i] = a->vec[2] + (v->vz[i] - a->vec[2]) * keep;
            }
        }
    }
}

ms_status ms_volume_remove_box(ms_volume *v, const float lo[3], const float hi[3], int *removed)
{
    if (removed)
        *removed = 0;
    if (!v)
        return ms_fail(MS_ERR_INVALID_ARGUMENT, "volume: remove_box on a NULL volume");
    ms_status st = check_vec("remove_box lo", lo, "m");
    if (st == MS_OK)
        st = check_vec("remove_box hi", hi, "m");
    if (st != MS_OK)
        return st;
    int n = v->n, kept = 0;
    int *new_id = v->nbr; /* scratch, indexed by id: 1 = kept, then the new id */
    for (int i = 0; i < n; ++i) {
        int inside = v->x[i] >= lo[0] && v->x[i] <= hi[0] && v->y[i] >= lo[1] && v->y[i] <= hi[1] &&
                     v->z[i] >= lo[2] && v->z[i] <= hi[2];
        new_id[v->id[i]] = !inside;
    }
    for (int id = 0; id < n; ++id) /* survivors keep their relative order */
        new_id[id] = new_id[id] ? kept++ : -1;
    int k = 0;
    for (int i = 0; i < n; ++i) {
        int nid = new_id[v->id[i]];
        if (nid < 0)
            continue;
        v->x[k] = v->x[i];
        v->y[k] = v->y[i];
        v->z[k] = v->z[i];
        v->vx[k] = v->vx[i];
        v->vy[k] = v->vy[i];
        v->vz[k] = v->vz[i];
        v->id[k] = nid;
        k++;
    }
    v->n = k;
    v->counts_valid = 0;
    if (removed)
        *removed = n - k;
    ms_volume_publish(v);
    return MS_OK;
}

ms_status ms_volume_set_viscosity(ms_volume *v, float viscosity)
{
    if (!v)
        return ms_fail(MS_ERR_INVALID_ARGUMENT, "volume: set_viscosity on a NULL volume");
    ms_status st = ms_check_range("volume", "viscosity", viscosity, 0.0, 1e6, "Pa s");
    if (st != MS_OK)
        return st;
    v->desc.viscosity = viscosity;
    return MS_OK;
}

/* Bilinear sample of a field at world (x, y), cell centres at
 * origin + (i + 0.5) dx, clamped at the edges. */
static float sample(const float *f, const ms_grid *g, float x, float y)
{
    float fx = (x - g->origin[0]) / g->dx - 0.5f, fy = (y - g->origin[1]) / g->dy - 0.5f;
    fx = fminf(fmaxf(fx, 0.0f), (float)(g->nx - 1));
    fy = fminf(fmaxf(fy, 0.0f), (float)(g->ny - 1));
    int i = (int)fx, j = (int)fy;
    int i1 = i + 1 < g->nx ? i + 1 : i, j1 = j + 1 < g->ny ? j + 1 : j;
    float tx = fx - (float)i, ty = fy - (float)j;
    float a = f[(size_t)j * g->nx + i] * (1.0f - tx) + f[(size_t)j * g->nx + i1] * tx;
    float b = f[(size_t)j1 * g->nx + i] * (1.0f - tx) + f[(size_t)j1 * g->nx + i1] * tx;
    return a * (1.0f - ty) + b * ty;
}

ms_status ms_volume_reserve_waves(ms_volume *v, size_t cells)
{
    if (cells <= v->wave_cap)
        return MS_OK;
    float *p = ms_alloc_array(cells, sizeof(float));
    if (!p)
        return ms_fail(MS_ERR_OUT_OF_MEMORY, "volume: out of memory for a wave field of %zu cells",
                       cells);
    ms_free(v->wave_prev);
    v->wave_prev = p;
    v->wave_cap = cells;
    v->wave_valid = 0; /* what it held is gone */
    return MS_OK;
}

ms_status ms_volume_adapt_to_waves(ms_volume *v, const float *wave_height, const ms_grid *g,
                                   float gain)
{
    if (!v || !wave_height || !g)
        return ms_fail(MS_ERR_INVALID_ARGUMENT,
                       "volume: adapt_to_waves needs a volume, a wave field and its grid");
    if (!isfinite(gain) || gain < 0.0f || gain > 1.0f)
        return ms_fail(MS_ERR_INVALID_ARGUMENT, "volume: adapt_to_waves gain %g is outside [0, 1]",
                       gain);
    if (g->nx < 1 || g->ny < 1 || g->nx > 65536 || g->ny > 65536 || !isfinite(g->dx) ||
        !isfinite(g->dy) || !(g->dx > 0.0f) || !(g->dy > 0.0f) || !isfinite(g->origin[0]) ||
        !isfinite(g->origin[1]))
        return ms_fail(MS_ERR_INVALID_ARGUMENT,
                       "volume: adapt_to_waves grid %d x %d, dx %g, dy %g m is not a valid grid",
                       g->nx, g->ny, g->dx, g->dy);
    if (gain == 0.0f)
        return MS_OK;
    size_t cells = (size_t)g->nx * g->ny;
    for (size_t c = 0; c < cells; ++c)
        if (!isfinite(wave_height[c]))
            return ms_fail(MS_ERR_INVALID_ARGUMENT,
                           "volume: adapt_to_waves: wave height %zu is not finite", c);
    int same = v->wave_valid && v->wave_grid.nx == g->nx && v->wave_grid.ny == g->ny &&
               v->wave_grid.dx == g->dx && v->wave_grid.dy == g->dy &&
               v->wave_grid.origin[0] == g->origin[0] && v->wave_grid.origin[1] == g->origin[1];
    double elapsed = v->time - v->wave_time;
    if (same && !(elapsed > 0.0))
        return MS_OK; /* no volume time passed: keep the old record */
    if (same) {
        if (!v->counts_valid) {
            ms_volume_grid_build(v);
            ms_status st = ms_volume_count_neighbours(v);
            if (st != MS_OK)
                return st;
        }
        const float umax = 0.1f * v->c0;
        for (int i = 0; i < v->n; ++i) {
            if (!ms_volume_is_surface(v, i))
                continue;
            float dw = sample(wave_height, g, v->x[i], v->y[i]) -
                       sample(v->wave_prev, g, v->x[i], v->y[i]);
            float u = fminf(fmaxf((float)(dw / elapsed), -umax), umax);
            v->vz[i] += gain * (u - v->vz[i]);
        }
        ms_volume_publish(v);
    } else if (cells > v->wave_cap) {
        ms_status st = ms_volume_reserve_waves(v, cells);
        if (st != MS_OK)
            return st;
    }
    memcpy(v->wave_prev, wave_height, cells * sizeof(float));
    v->wave_grid = *g;
    v->wave_time = v->time;
    v->wave_valid = 1;
    return MS_OK;
}
