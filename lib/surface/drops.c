/* Drops and rain on the surface (paper 3.2, Fig. 3a-b): "radially
 * propagating waves can be created at position x0 and time t0 by
 * displacing f(x0, t0)". A drop is a smooth raised-cosine bump, never a
 * one-cell spike (which would excite the grid's shortest, most dispersive
 * waves and show as noise); rain draws drops from the handle's seeded RNG. */
#include "surface/surface_internal.h"
#include "surface/surface_sizes.h"

#define PART "surface"
#define MIN_RADIUS_CELLS 2.0f
/* Rain's work per second is bounded: at most this many drops a second
 * over the whole grid (1700 a frame at 60 Hz, ~1.7e4 in a 10 s hitch), so
 * no in-range rate over a large grid makes a frame endless. */
#define MAX_RAIN_DROPS_PER_S 1e5

double ms_surface_drop_cells(const ms_surface *s, float radius)
{
    const double rmin = MIN_RADIUS_CELLS * (double)s->desc.dx;
    const double r = (double)radius < rmin ? rmin : (double)radius;
    const double side = 2.0 * r / (double)s->desc.dx + 2.0; /* floor and ceil at both ends */
    const double nx = side < (double)s->nx ? side : (double)s->nx;
    const double ny = side < (double)s->ny ? side : (double)s->ny;
    return nx * ny;
}

/* Add the bump to f^n and f^{n-1} alike (h, not v): a displacement at rest. Cells are
 * wrapped on a periodic grid and clipped otherwise; solid cells stay 0. */
static void splat(ms_surface *s, float x, float y, float radius, float amplitude)
{
    const float dx = s->desc.dx;
    const float rmin = MIN_RADIUS_CELLS * dx;
    if (radius < rmin) {
        /* keep the displaced volume (proportional to amplitude * radius^2) */
        amplitude *= (radius / rmin) * (radius / rmin);
        radius = rmin;
    }
    const int periodic = s->desc.boundary == MS_BOUNDARY_PERIODIC;
    const int x0 = (int)floorf((x - radius) / dx), x1 = (int)ceilf((x + radius) / dx);
    const int y0 = (int)floorf((y - radius) / dx), y1 = (int)ceilf((y + radius) / dx);
    const float inv_r = 1.0f / radius;
    const float pi = 3.14159265358979f;
    for (int j = y0; j <= y1; ++j) {
        int jj = j;
        if (periodic)
            jj = ((j % s->ny) + s->ny) % s->ny;
        else if (j < 0 || j >= s->ny)
            continue;
        for (int i = x0; i <= x1; ++i) {
            int ii = i;
            if (periodic)
                ii = ((i % s->nx) + s->nx) % s->nx;
            else if (i < 0 || i >= s->nx)
                continue;
            float rx = ((float)i + 0.5f) * dx - x, ry = ((float)j + 0.5f) * dx - y;
            float r = sqrtf(rx * rx + ry * ry) * inv_r;
            if (r >= 1.0f)
                continue;
            size_t k = ms_surface_at(s, ii, jj);
            if (s->solid && s->solid[k])
                continue;
            float b = amplitude * 0.5f * (1.0f + cosf(pi * r));
            s->h[k] += b;
        }
    }
    s->drops++;
    s->view_dirty = 1;
}

ms_status ms_surface_add_drop(ms_surface *s, float x, float y, float radius, float amplitude)
{
    ms_status st;
    if ((st = ms_check_not_null(PART, "surface", s)) || (st = ms_check_finite(PART, "x", x)) ||
        (st = ms_check_finite(PART, "y", y)) ||
        (st = ms_check_finite(PART, "amplitude", amplitude)))
        return st;
    const float extent = (float)MS_MAX(s->nx, s->ny) * s->desc.dx;
    if (!isfinite(radius) || !(radius > 0) || radius > extent)
        return ms_fail(MS_ERR_INVALID_ARGUMENT,
                       "surface: drop radius %g m is outside (0, %g] m (the grid's extent)",
                       (double)radius, (double)extent);
    splat(s, x, y, radius, amplitude);
    return MS_OK;
}

ms_rain ms_rain_default(void)
{
    ms_rain r = {(uint32_t)sizeof r, 0.0f, 0.01f, -0.002f};
    return r;
}

ms_status ms_surface_check_rain(const ms_surface *s, const ms_rain *rain)
{
    ms_status st;
    const float extent = (float)MS_MAX(s->nx, s->ny) * s->desc.dx;
    if ((st = ms_check_range(PART, "rain rate", rain->rate, 0, 1e6, "drops/m^2/s")) ||
        (st = ms_check_range(PART, "rain radius", rain->radius, 1e-9, extent, "m")) ||
        (st = ms_check_finite(PART, "rain amplitude", rain->amplitude)))
        return st;
    const double area = (double)s->nx * s->desc.dx * ((double)s->ny * s->desc.dx);
    if ((double)rain->rate * area > MAX_RAIN_DROPS_PER_S)
        return ms_fail(MS_ERR_INVALID_ARGUMENT,
                       "surface: rain rate %g drops/m^2/s over the grid's %g m^2 is %g drops "
                       "a second; at most %g (rate <= %g here)",
                       (double)rain->rate, area, rain->rate * area, MAX_RAIN_DROPS_PER_S,
                       MAX_RAIN_DROPS_PER_S / area);
    /* and the cells they visit: drops of the grid's size at the rate cap
     * would visit ~1e12 cells a second */
    const double cells = (double)rain->rate * area * ms_surface_drop_cells(s, rain->radius);
    if (cells > MS_SURFACE_MAX_DROP_CELLS)
        return ms_fail(MS_ERR_INVALID_ARGUMENT,
                       "surface: rain of %g drops a second of radius up to %g m visits %.3g wave "
                       "cells a second; at most %.3g (fewer or smaller drops)",
                       (double)rain->rate * area, (double)rain->radius, cells,
                       MS_SURFACE_MAX_DROP_CELLS);
    return MS_OK;
}

ms_status ms_surface_set_rain(ms_surface *s, const ms_rain *user)
{
    ms_status st;
    if ((st = ms_check_not_null(PART, "surface", s)))
        return st;
    ms_rain r = ms_rain_default(), *rain = NULL;
    if (user) {
        if ((st = ms_struct_in(user, &r, MS_SIZES_RAIN, PART)))
            return st;
        rain = &r;
    }
    if (!rain || rain->rate == 0) {
        s->rain.rate = 0;
        return MS_OK;
    }
    if ((st = ms_surface_check_rain(s, rain)))
        return st;
    s->rain = *rain;
    return MS_OK;
}

/* Drops falling during dt: a Poisson count with mean rate * area * dt,
 * then uniform positions and radii/amplitudes in [1/2, 1] of the set
 * values. All from the handle's RNG, in a fixed order. */
void ms_surface_rain(ms_surface *s, float dt)
{
    const double lx = s->nx * (double)s->desc.dx, ly = s->ny * (double)s->desc.dx;
    long n = ms_rng_poisson(&s->rng, s->rain.rate * lx * ly * dt);
    for (long k = 0; k < n; ++k) {
        float x = (float)(ms_rng_uniform(&s->rng) * lx);
        float y = (float)(ms_rng_uniform(&s->rng) * ly);
        float r = s->rain.radius * (0.5f + 0.5f * ms_rng_uniform(&s->rng));
        float a = s->rain.amplitude * (0.5f + 0.5f * ms_rng_uniform(&s->rng));
        splat(s, x, y, r, a);
    }
}
