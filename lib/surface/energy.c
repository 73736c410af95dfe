/* The discrete energy of the leapfrog scheme (wave.c):
 *
 *   E^{n+1/2} = dx^2 [ 1/2 sum_i ((f_i^{n+1} - f_i^n) / dt)^2
 *                    + 1/2 sum_faces c_i c_j (f_i^{n+1} - f_j^{n+1})(f_i^n - f_j^n) / dx^2 ]
 *
 * the staggered form of 1/2 integral (f_t^2 + c^2 |grad f|^2) that leapfrog
 * conserves exactly (to round-off) on a closed, undamped grid. Summed in
 * double. */
#include "surface/surface_internal.h"

/* c_i c_j (f_i^{n+1} - f_j^{n+1}) (f_i^n - f_j^n), with f^n = h - v */
static double face(const float *c, const float *h, const float *v, size_t i, size_t j)
{
    double dnew = (double)h[i] - h[j];
    double dold = dnew - ((double)v[i] - v[j]);
    return (double)c[i] * c[j] * dnew * dold;
}

double ms_surface_energy_region(const ms_surface *s, int x0, int x1, int y0, int y1)
{
    const double dt = s->v_dt;
    const double dx = s->desc.dx;
    const double kx = dt > 0 ? 1.0 / dt : 0.0;
    const float *h = s->h, *v = s->v, *c = s->speed;
    const ptrdiff_t W = s->stride;
    /* on a periodic grid the last column and row face the first; other
     * faces to the ghosts are boundary, not stored energy */
    const int wrap_x = s->desc.boundary == MS_BOUNDARY_PERIODIC && x0 == 0 && x1 == s->nx;
    const int wrap_y = s->desc.boundary == MS_BOUNDARY_PERIODIC && y0 == 0 && y1 == s->ny;
    double kin = 0.0, pot = 0.0;
    for (int y = y0; y < y1; ++y) {
        size_t i0 = ms_surface_at(s, 0, y);
        for (int x = x0; x < x1; ++x) {
            size_t i = i0 + x;
            double vel = (double)v[i] * kx;
            kin += vel * vel;
            if (x + 1 < x1)
                pot += face(c, h, v, i, i + 1);
            else if (wrap_x)
                pot += face(c, h, v, i, i0);
            if (y + 1 < y1)
                pot += face(c, h, v, i, i + W);
            else if (wrap_y)
                pot += face(c, h, v, i, ms_surface_at(s, x, 0));
        }
    }
    return dx * dx * (0.5 * kin + 0.5 * pot / (dx * dx));
}

double ms_surface_energy(const ms_surface *s)
{
    if (!s)
        return 0.0;
    if (s->disp)
        return ms_surface_dispersive_energy(s);
    return ms_surface_energy_region(s, 0, s->nx, 0, s->ny);
}
