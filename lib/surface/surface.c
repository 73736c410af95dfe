/* ms_surface lifecycle, validation and views: the part of the surface
 * solver (paper section 3.2, eq. 2) that is not the time step. */
#include <stdlib.h>
#include <string.h>

#include "surface/surface_internal.h"
#include "surface/surface_sizes.h"

#define PART "surface"
#define MAX_CELLS_PER_SIDE 16384
#define MIN_DX 1e-6 /* m */

ms_surface_desc ms_surface_desc_default(void)
{
    ms_surface_desc d;
    memset(&d, 0, sizeof d);
    d.size = (uint32_t)sizeof d;
    d.nx = 256;
    d.ny = 256;
    d.dx = 0.01f;        /* m */
    d.wave_speed = 0.5f; /* m/s: shallow water 2.5 cm deep */
    d.damping = 0.9f;    /* velocity kept per second */
    d.boundary = MS_BOUNDARY_REFLECT;
    d.seed = 1;
    d.max_substeps = 100000;
    d.model = MS_SURFACE_MODEL_WAVE;
    d.gravity = 9.81f;            /* m/s^2 */
    d.surface_tension = 7.28e-5f; /* m^3/s^2: 0.0728 N/m / 1000 kg/m^3 */
    d.advect = 0;
    /* kappa = 4 pi^2 C_s^2, C_s = 0.17 (current.c) */
    d.turbulence_damping = 4.0f * 3.14159265f * 3.14159265f * 0.17f * 0.17f;
    return d;
}

static ms_status validate(const ms_surface_desc *d)
{
    ms_status st;
    if ((st = ms_check_int_range(PART, "nx", d->nx, 2, MAX_CELLS_PER_SIDE)) ||
        (st = ms_check_int_range(PART, "ny", d->ny, 2, MAX_CELLS_PER_SIDE)))
        return st;
    /* a micrometre: below it capillarity, not gravity, carries the waves
     * (eq. 2 no longer holds), and float32 cell centres (x + 0.5) dx of a
     * grid placed metres from the origin lose the cell apart */
    if (!isfinite(d->dx) || !(d->dx >= MIN_DX))
        return ms_fail_key(MS_ERR_INVALID_ARGUMENT, "dx",
                           "surface: dx %g m is below %g m or not finite (the cell size)", d->dx,
                           MIN_DX);
    if (!isfinite(d->wave_speed) || !(d->wave_speed > 0))
        return ms_fail_key(MS_ERR_INVALID_ARGUMENT, "wave_speed",
                           "surface: wave_speed %g m/s must be finite and > 0 (c of eq. 2)",
                           d->wave_speed);
    if (!isfinite(d->damping) || !(d->damping > 0) || d->damping > 1)
        return ms_fail_key(MS_ERR_INVALID_ARGUMENT, "damping",
                           "surface: damping %g is outside (0, 1] (fraction of the wave "
                           "velocity kept per second; 1 = none)",
                           d->damping);
    if (d->boundary != MS_BOUNDARY_REFLECT && d->boundary != MS_BOUNDARY_ABSORB &&
        d->boundary != MS_BOUNDARY_PERIODIC)
        return ms_fail_key(MS_ERR_INVALID_ARGUMENT, "boundary",
                           "surface: boundary %d is not one of reflect (0), absorb (1), "
                           "periodic (2)",
                           (int)d->boundary);
    if (d->max_substeps < 1)
        return ms_fail_key(MS_ERR_INVALID_ARGUMENT, "max_substeps",
                           "surface: max_substeps %d must be >= 1", d->max_substeps);
    if (d->model != MS_SURFACE_MODEL_WAVE && d->model != MS_SURFACE_MODEL_DISPERSIVE)
        return ms_fail_key(MS_ERR_INVALID_ARGUMENT, "model",
                           "surface: model %d is not one of wave (0), dispersive (1)",
                           (int)d->model);
    if ((st = ms_check_range(PART, "gravity", d->gravity, 1e-9, 1000, "m/s^2")) ||
        (st = ms_check_range(PART, "surface_tension", d->surface_tension, 0, 1, "m^3/s^2")) ||
        (st = ms_check_int_range(PART, "advect", d->advect, 0, 1)) ||
        (st = ms_check_range(PART, "turbulence_damping", d->turbulence_damping, 0, 100, "")))
        return st;
    return MS_OK;
}

ms_status ms_surface_desc_check(const ms_surface_desc *user)
{
    ms_surface_desc d = ms_surface_desc_default();
    MS_TRY(ms_struct_in(user, &d, MS_SIZES_SURFACE_DESC, PART));
    return validate(&d);
}

ms_status ms_surface_create(const ms_surface_desc *d, ms_surface **out)
{
    ms_status st;
    if ((st = ms_check_not_null(PART, "out", out)))
        return st;
    *out = NULL;
    ms_surface_desc desc = ms_surface_desc_default();
    if ((st = ms_struct_in(d, &desc, MS_SIZES_SURFACE_DESC, PART)) || (st = validate(&desc)))
        return st;
    d = &desc;

    ms_surface *s = ms_alloc_array(1, sizeof *s);
    if (!s)
        return ms_fail(MS_ERR_OUT_OF_MEMORY, "surface: out of memory for the handle");
    s->desc = *d;
    s->nx = d->nx;
    s->ny = d->ny;
    /* whole cache lines per row, interior aligned (see surface_internal.h) */
    s->stride = (MS_SURFACE_ORIGIN + d->nx + 2 + 15) & ~15;
    s->plane = (size_t)s->stride * (size_t)(d->ny + 2);
    s->h = ms_alloc_array(s->plane, sizeof(float));
    s->v = ms_alloc_array(s->plane, sizeof(float));
    s->speed = ms_alloc_array(s->plane, sizeof(float));
    s->a = ms_alloc_array(s->plane, sizeof(float));
    s->delta = ms_alloc_array(s->plane, sizeof(float));
    s->view = ms_alloc_array((size_t)d->nx * (size_t)d->ny, sizeof(float));
    if (!s->h || !s->v || !s->speed || !s->a || !s->delta || !s->view) {
        size_t mb = (5 * s->plane + (size_t)d->nx * d->ny) * sizeof(float) >> 20;
        ms_surface_destroy(s);
        return ms_fail(MS_ERR_OUT_OF_MEMORY, "surface: a %d x %d grid needs %zu MiB", d->nx, d->ny,
                       mb);
    }
    if ((d->model == MS_SURFACE_MODEL_DISPERSIVE && (st = ms_surface_dispersive_create(s))) ||
        (st = ms_surface_set_speed_map(s, NULL))) {
        ms_surface_destroy(s);
        return st;
    }
    ms_rng_seed(&s->rng, d->seed);
    s->next_id = 1;
    *out = s;
    return MS_OK;
}

void ms_surface_destroy(ms_surface *s)
{
    if (!s)
        return;
    ms_free(s->h);
    ms_free(s->v);
    ms_free(s->speed);
    ms_free(s->speed_map);
    ms_free(s->a);
    ms_free(s->delta);
    ms_free(s->damp_map);
    ms_free(s->solid);
    ms_free(s->view);
    for (int i = 0; i < s->ndist; ++i)
        ms_free(s->dist[i].path);
    ms_free(s->dist);
    ms_free(s->level_xy);
    ms_surface_dispersive_destroy(s);
    ms_free(s->cur_u);
    ms_free(s->cur_tmp);
    ms_free(s);
}

void ms_surface_zero_solid(ms_surface *s, float *field)
{
    if (!s->solid)
        return;
    for (size_t i = 0; i < s->plane; ++i)
        if (s->solid[i])
            field[i] = 0.0f;
}

static ms_status check_field(const char *what, const float *v, size_t n)
{
    for (size_t i = 0; i < n; ++i)
        if (!isfinite(v[i]))
            return ms_fail(MS_ERR_INVALID_ARGUMENT,
                           "surface: %s[%zu] is %g; every value must be finite", what, i,
                           (double)v[i]);
    return MS_OK;
}

ms_status ms_surface_set_height(ms_surface *s, const float *h)
{
    ms_status st;
    if ((st = ms_check_not_null(PART, "surface", s)) || (st = ms_check_not_null(PART, "h", h)))
        return st;
    if ((st = check_field("h", h, (size_t)s->nx * s->ny)))
        return st;
    for (int y = 0; y < s->ny; ++y) {
        memcpy(s->h + ms_surface_at(s, 0, y), h + (size_t)y * s->nx, s->nx * sizeof(float));
    }
    memset(s->v, 0, s->plane * sizeof(float)); /* at rest */
    ms_surface_zero_solid(s, s->h);
    s->view_dirty = 1;
    return MS_OK;
}

ms_status ms_surface_excite(ms_surface *s, const float *dh, float gain)
{
    ms_status st;
    if ((st = ms_check_not_null(PART, "surface", s)) || (st = ms_check_not_null(PART, "dh", dh)) ||
        (st = ms_check_finite(PART, "gain", gain)))
        return st;
    if ((st = check_field("dh", dh, (size_t)s->nx * s->ny)))
        return st;
    for (int y = 0; y < s->ny; ++y) {
        float *row = s->h + ms_surface_at(s, 0, y), *vel = s->v + ms_surface_at(s, 0, y);
        const float *src = dh + (size_t)y * s->nx;
        for (int x = 0; x < s->nx; ++x) {
            row[x] += gain * src[x];
            vel[x] += gain * src[x]; /* f^{n-1} stays: an impulse */
        }
    }
    ms_surface_zero_solid(s, s->h);
    ms_surface_zero_solid(s, s->v);
    s->view_dirty = 1;
    return MS_OK;
}

const float *ms_surface_height(const ms_surface *s, int *nx, int *ny)
{
    if (nx)
        *nx = s ? s->nx : 0;
    if (ny)
        *ny = s ? s->ny : 0;
    if (!s)
        return NULL;
    if (s->view_dirty) {
        /* The view is refreshed lazily: a handle is used by one thread at a
         * time, and the object was not defined const, so this is safe. */
        ms_surface *m = (ms_surface *)s;
        for (int y = 0; y < s->ny; ++y)
            memcpy(m->view + (size_t)y * s->nx, s->h + ms_surface_at(s, 0, y),
                   s->nx * sizeof(float));
        m->view_dirty = 0;
    }
    return s->view;
}

void ms_surface_get_info(const ms_surface *s, ms_surface_info *user)
{
    size_t size = ms_struct_out(user, MS_SIZES_SURFACE_INFO, PART);
    if (!size)
        return;
    ms_surface_info info = ms_surface_info_init(), *out = &info;
    if (!s) {
        ms_struct_write(user, &info, size);
        return;
    }
    out->time = s->time;
    out->substeps = s->substeps;
    out->max_dt = ms_surface_stable_dt(s);
    out->max_speed = s->max_speed;
    out->drops = s->drops;
    size_t fields = 5 + (s->damp_map ? 1 : 0);
    out->bytes = sizeof *s + fields * s->plane * sizeof(float) + (s->solid ? s->plane : 0) +
                 (size_t)s->nx * s->ny * sizeof(float) + (size_t)s->cap_dist * sizeof(disturber);
    for (int i = 0; i < s->ndist; ++i)
        out->bytes += (size_t)s->dist[i].npath * 2 * sizeof(float);
    out->bytes += ms_surface_dispersive_bytes(s) + ms_surface_current_bytes(s);
    ms_struct_write(user, &info, size);
}

void ms_surface_cancel(ms_surface *s)
{
    if (s)
        atomic_store(&s->cancel, 1);
}

ms_surface_desc ms_surface_get_desc(const ms_surface *s)
{
    if (!s)
        return ms_surface_desc_default();
    return s->desc;
}
