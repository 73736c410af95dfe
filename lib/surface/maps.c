/* Speed map, damping map and obstacle mask of the surface (paper 3.2:
 * "according to the liquid depth, a velocity map can vary c"; "in
 * combination with a damping map the damping according to e.g. the type of
 * ground can be described"; obstacles reflect waves), and the per-cell
 * coefficients of the leapfrog step that follow from them. */
#include <stdint.h>
#include <string.h>

#include "surface/surface_internal.h"

#define PART "surface"

/* Width (cells) and strength of the absorbing sponge. Mur's condition at
 * the edge is exact at normal incidence; the sponge damps what it lets
 * back at oblique incidence. sigma rises quadratically from 0 to
 * sigma_max over the width, so the sponge itself reflects little. */
static int sponge_width(const ms_surface *s)
{
    int n = MS_MIN(s->nx, s->ny);
    return MS_CLAMP(n / 16, 3, 16);
}

/* Ghost speeds carry the boundary condition (see surface_internal.h). */
static void set_ghost_speeds(ms_surface *s)
{
    const int nx = s->nx, ny = s->ny;
    float *c = s->speed;
    for (int y = 0; y < ny; ++y) {
        size_t row = ms_surface_row(s, y + 1);
        switch (s->desc.boundary) {
        case MS_BOUNDARY_REFLECT:
            c[row] = c[row + nx + 1] = 0.0f;
            break;
        case MS_BOUNDARY_PERIODIC:
            c[row] = c[row + nx];
            c[row + nx + 1] = c[row + 1];
            break;
        default: /* absorb: the wave runs on into the ghost cell */
            c[row] = c[row + 1];
            c[row + nx + 1] = c[row + nx];
            break;
        }
    }
    float *bottom = c + ms_surface_row(s, 0), *top = c + ms_surface_row(s, ny + 1);
    const float *first = c + ms_surface_row(s, 1), *last = c + ms_surface_row(s, ny);
    for (int x = 1; x <= nx; ++x) {
        switch (s->desc.boundary) {
        case MS_BOUNDARY_REFLECT:
            bottom[x] = top[x] = 0.0f;
            break;
        case MS_BOUNDARY_PERIODIC:
            bottom[x] = last[x];
            top[x] = first[x];
            break;
        default:
            bottom[x] = first[x];
            top[x] = last[x];
            break;
        }
    }
}

/* Rebuild the stepped speeds from the map (or the uniform speed) and the
 * obstacle mask (and the dispersive model's depth bands from them). */
static ms_status rebuild_speed(ms_surface *s)
{
    float maxc = 0.0f;
    for (int y = 0; y < s->ny; ++y) {
        size_t i0 = ms_surface_at(s, 0, y);
        for (int x = 0; x < s->nx; ++x) {
            size_t i = i0 + x;
            float c = s->speed_map ? s->speed_map[i] : s->desc.wave_speed;
            if (s->solid && s->solid[i])
                c = 0.0f;
            s->speed[i] = c;
            maxc = MS_MAX(maxc, c);
        }
    }
    s->max_speed = maxc;
    set_ghost_speeds(s);
    s->coef_dt = 0.0f; /* the coefficients are stale */
    return s->disp ? ms_surface_dispersive_bands(s) : MS_OK;
}

void ms_surface_refresh_coefficients(ms_surface *s, float dt)
{
    if (s->coef_dt == dt)
        return;
    const float k = dt / s->desc.dx;
    for (size_t i = 0; i < s->plane; ++i)
        s->a[i] = s->speed[i] * k;

    /* damping is the fraction of the velocity kept per second, so the
     * factor per sub-step is damping^dt: independent of sub-stepping. */
    const double base = s->desc.damping;
    const float uniform = (float)pow(base, dt);
    const int w = s->desc.boundary == MS_BOUNDARY_ABSORB ? sponge_width(s) : 0;
    const double sigma_max = w ? 6.0 * s->max_speed / (w * s->desc.dx) : 0.0; /* 1/s */
    for (int y = 0; y < s->ny; ++y) {
        size_t i0 = ms_surface_at(s, 0, y);
        int dy = MS_MIN(y, s->ny - 1 - y);
        for (int x = 0; x < s->nx; ++x) {
            double f = s->damp_map ? pow(base * s->damp_map[i0 + x], dt) : uniform;
            int d = MS_MIN(dy, MS_MIN(x, s->nx - 1 - x));
            if (d < w) {
                double r = (w - d - 0.5) / w;
                f *= exp(-sigma_max * r * r * dt);
            }
            s->delta[i0 + x] = (float)f;
        }
    }
    s->coef_dt = dt;
    ms_surface_find_uniform(s);
    ms_surface_dispersive_invalidate(s);
}

/* The same bits, not only equal values (+0 and -0 compare equal). */
static int same_bits(float x, float y)
{
    uint32_t a, b;
    memcpy(&a, &x, sizeof a);
    memcpy(&b, &y, sizeof b);
    return a == b;
}

void ms_surface_find_uniform(ms_surface *s)
{
    const size_t c0 = ms_surface_at(s, 0, 0);
    const float a0 = s->a[c0], d0 = s->delta[c0];
    int same = 1;
    for (int y = 0; y < s->ny && same; ++y) {
        const size_t i0 = ms_surface_at(s, 0, y);
        for (int x = 0; x < s->nx; ++x)
            same &= same_bits(s->a[i0 + x], a0) & same_bits(s->delta[i0 + x], d0);
    }
    s->uniform = same;
    s->a0 = a0;
    s->d0 = d0;
}

ms_status ms_surface_set_speed_map(ms_surface *s, const float *c)
{
    ms_status st;
    if ((st = ms_check_not_null(PART, "surface", s)))
        return st;
    if (!c) {
        ms_free(s->speed_map);
        s->speed_map = NULL;
        return rebuild_speed(s);
    }
    size_t n = (size_t)s->nx * s->ny;
    for (size_t i = 0; i < n; ++i)
        if (!isfinite(c[i]) || c[i] < 0)
            return ms_fail(MS_ERR_INVALID_ARGUMENT,
                           "surface: speed map[%zu] is %g m/s; speeds must be finite and >= 0", i,
                           (double)c[i]);
    if (!s->speed_map && !(s->speed_map = ms_alloc_array(s->plane, sizeof(float))))
        return ms_fail(MS_ERR_OUT_OF_MEMORY, "surface: out of memory for the speed map");
    for (int y = 0; y < s->ny; ++y)
        memcpy(s->speed_map + ms_surface_at(s, 0, y), c + (size_t)y * s->nx, s->nx * sizeof(float));
    return rebuild_speed(s);
}

ms_status ms_surface_set_damping_map(ms_surface *s, const float *d)
{
    ms_status st;
    if ((st = ms_check_not_null(PART, "surface", s)))
        return st;
    if (d) {
        size_t n = (size_t)s->nx * s->ny;
        for (size_t i = 0; i < n; ++i)
            if (!isfinite(d[i]) || !(d[i] > 0) || d[i] > 1)
                return ms_fail(MS_ERR_INVALID_ARGUMENT,
                               "surface: damping map[%zu] is %g; it must be in (0, 1] "
                               "(fraction of the velocity kept per second)",
                               i, (double)d[i]);
        if (!s->damp_map && !(s->damp_map = ms_alloc_array(s->plane, sizeof(float))))
            return ms_fail(MS_ERR_OUT_OF_MEMORY, "surface: out of memory for the damping map");
        for (int y = 0; y < s->ny; ++y)
            memcpy(s->damp_map + ms_surface_at(s, 0, y), d + (size_t)y * s->nx,
                   s->nx * sizeof(float));
    } else {
        ms_free(s->damp_map);
        s->damp_map = NULL;
    }
    s->coef_dt = 0.0f;
    return MS_OK;
}

ms_status ms_surface_set_obstacle_mask(ms_surface *s, const unsigned char *mask)
{
    ms_status st;
    if ((st = ms_check_not_null(PART, "surface", s)))
        return st;
    if (mask) {
        if (!s->solid && !(s->solid = ms_alloc(s->plane)))
            return ms_fail(MS_ERR_OUT_OF_MEMORY, "surface: out of memory for the obstacle mask");
        for (int y = 0; y < s->ny; ++y) {
            unsigned char *row = s->solid + ms_surface_at(s, 0, y);
            for (int x = 0; x < s->nx; ++x)
                row[x] = mask[(size_t)y * s->nx + x] != 0;
        }
        ms_surface_zero_solid(s, s->h);
        ms_surface_zero_solid(s, s->v);
        s->view_dirty = 1;
    } else {
        ms_free(s->solid);
        s->solid = NULL;
    }
    return rebuild_speed(s);
}

ms_status ms_surface_speed_from_depth(const float *depth, size_t n, float gravity, float *speed_out)
{
    ms_status st;
    if ((st = ms_check_not_null(PART, "depth", depth)) ||
        (st = ms_check_not_null(PART, "speed_out", speed_out)) ||
        (st = ms_check_positive(PART, "gravity", gravity, "m/s^2")))
        return st;
    for (size_t i = 0; i < n; ++i)
        if (!isfinite(depth[i]))
            return ms_fail(MS_ERR_INVALID_ARGUMENT,
                           "surface: depth[%zu] is %g m; depths must be finite", i,
                           (double)depth[i]);
    for (size_t i = 0; i < n; ++i)
        speed_out[i] = depth[i] > 0 ? sqrtf(gravity * depth[i]) : 0.0f; /* shallow water */
    return MS_OK;
}
