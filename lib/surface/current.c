/* Waves carried by the flow: a horizontal current U(x, y) under the
 * surface (ms_surface_set_current; in a sim, the volume's surface velocity
 * up-sampled to the wave grid when desc.advect is set) moves the waves
 * with it and damps them where it shears.
 *
 * Advection. In a frame that moves with a uniform current U, eq. 2 holds
 * unchanged, so in the ground frame (d/dt + U.grad)^2 f = div(c^2 grad f):
 * a packet travels at c + U and a source of fixed frequency omega makes
 * waves of wavenumber k = omega / (c +- U) down- and upstream (the Doppler
 * shift). The step splits the two (Lie splitting): before the wave steps
 * of a call, both levels of the leapfrog state (h = f^n and v = f^n -
 * f^{n-1}, so f^{n-1} too) are moved along U by the call's dt,
 * semi-Lagrangian: the value at a cell is the state at its departure point
 * x - U(x) dt_a, along x and then along y (for a uniform U the same as
 * the 4 x 4 point stencil, at half its cost; a varying U adds a splitting
 * error of order dt grad U). For a uniform U the advection and the wave
 * step commute, so the packet's speed is c + U exactly up to the
 * interpolation. The interpolation is the 4-point cubic Lagrange one
 * along each axis: bilinear's damping per advection of a
 * wave of k dx = 2 pi / 8 is ~5 % at a shift of 0.2 cells (a packet would
 * vanish in a few dozen steps); cubic's is ~0.5 %, and like bilinear's
 * it is at most 1 for every wavenumber and shift, so the scheme is stable.
 * A call is split into ceil(max|U| dt / dx) advections, so no departure
 * point lies more than a cell away (the CFL bound of the advection; a
 * backtrace over more would cross a varying U unseen).
 *
 * Turbulence damping. Where the current shears, eddies the size of the
 * flow's resolution mix the surface layer. Smagorinsky's eddy viscosity
 * nu_t = (C_s D)^2 |S| (|S| = sqrt(2 S_ij S_ij) the strain rate of U, D
 * the flow's cell, C_s = 0.17 Lilly's constant) damps a wave of wavenumber
 * k at Lamb's viscous rate: amplitude ~ exp(-2 nu_t k^2 t). The waves the
 * flow does not resolve start at its Nyquist wavenumber k = pi / D, where
 * the rate is 2 pi^2 C_s^2 |S|, free of D. Eq. 2 with a damping term
 * f_tt + gamma f_t decays amplitudes at gamma / 2, so
 *
 *     gamma = kappa |S|,   kappa = 4 pi^2 C_s^2 = 1.14,
 *
 * desc.turbulence_damping holds kappa (0 turns the damping off). A uniform
 * current does not shear (|S| = 0): it carries waves without damping them.
 * It acts on v with the leapfrog's own damping (v <- exp(-gamma dt) v).
 *
 * Solid and dry cells (speed 0) hold no wave: after each advection they
 * are set to 0, as the obstacle mask does. Departure points beyond the
 * grid read its edge (periodic grids wrap). No current set: nothing here
 * runs and nothing is allocated.
 */
#include <string.h>

#include "surface/surface_internal.h"

#define PART "surface"
#define MAX_CURRENT 100.0f /* m/s: faster is refused as a unit error */

static int wrap(int i, int n)
{
    i %= n;
    return i < 0 ? i + n : i;
}

/* Cubic Lagrange weights at offset a in [0, 1) from node 0 of the nodes
 * -1, 0, 1, 2 (at a = 0 exactly 0, 1, 0, 0: a current of zero moves no
 * bit). */
static inline void lagrange4(float a, float w[4])
{
    const float am = a + 1.0f, a1 = a - 1.0f, a2 = a - 2.0f;
    const float sixth = 1.0f / 6.0f;
    w[0] = -a * a1 * a2 * sixth;
    w[1] = am * a1 * a2 * 0.5f;
    w[2] = -am * a * a2 * 0.5f;
    w[3] = am * a * a1 * sixth;
}

/* Index i of n cells, clamped or wrapped. */
static inline int edge(int i, int n, int periodic)
{
    return periodic ? wrap(i, n) : MS_CLAMP(i, 0, n - 1);
}

/* One advection by dt (s) along one axis (axis 0: x, 1: y): h and v at the
 * departure points x - U dt along it, from copies. A stencil inside the
 * grid reads its four cells straight (most cells); one near an edge clamps
 * or wraps each index. */
static void advect_axis(ms_surface *s, float dt, int axis)
{
    const int nx = s->nx, ny = s->ny, periodic = s->desc.boundary == MS_BOUNDARY_PERIODIC;
    const int n = axis ? ny : nx;
    const ptrdiff_t step = axis ? s->stride : 1; /* floats between neighbours along the axis */
    const float k = dt / s->desc.dx;             /* cells per (m/s) */
    const float *restrict cur = axis ? s->cur_v : s->cur_u;
    float *restrict th = s->cur_tmp, *restrict tv = s->cur_tmp + s->plane;
    memcpy(th, s->h, s->plane * sizeof(float));
    memcpy(tv, s->v, s->plane * sizeof(float));
    for (int y = 0; y < ny; ++y) {
        const size_t r = ms_surface_at(s, 0, y);
        for (int x = 0; x < nx; ++x) {
            const size_t i = r + (size_t)x;
            const int at = axis ? y : x;
            const float p = (float)at - cur[i] * k;
            /* floor without a call (p lies in [-1, n]: a cell at most an
             * advection) */
            const int ip = (int)p - (p < (float)(int)p);
            float w[4];
            lagrange4(p - (float)ip, w);
            float sh, sv;
            if (ip >= 1 && ip <= n - 3) {
                const ptrdiff_t o = (ptrdiff_t)i + (ptrdiff_t)(ip - 1 - at) * step;
                const float *restrict ph = th + o, *restrict pv = tv + o;
                sh = w[0] * ph[0] + w[1] * ph[step] + w[2] * ph[2 * step] + w[3] * ph[3 * step];
                sv = w[0] * pv[0] + w[1] * pv[step] + w[2] * pv[2 * step] + w[3] * pv[3 * step];
            } else {
                sh = sv = 0.0f;
                for (int q = 0; q < 4; ++q) {
                    const int c = edge(ip - 1 + q, n, periodic);
                    const size_t o = axis ? ms_surface_at(s, x, c) : r + (size_t)c;
                    sh += w[q] * th[o];
                    sv += w[q] * tv[o];
                }
            }
            const int wet = s->speed[i] > 0.0f;
            s->h[i] = wet ? sh : 0.0f;
            s->v[i] = wet ? sv : 0.0f;
        }
    }
}

ms_status ms_surface_current_advance(ms_surface *s, float dt)
{
    if (!s->cur_u || !(dt > 0))
        return MS_OK;
    if (s->cur_max > 0.0f) {
        const double n = ceil((double)s->cur_max * dt / s->desc.dx);
        if (n > s->desc.max_substeps)
            return ms_fail(MS_ERR_UNSTABLE,
                           "surface: a current of %g m/s with dx %g m moves the waves %.0f cells "
                           "in %g s, over max_substeps %d advections of a cell each",
                           (double)s->cur_max, (double)s->desc.dx, n, (double)dt,
                           s->desc.max_substeps);
        const int na = n < 1 ? 1 : (int)n;
        for (int a = 0; a < na; ++a) {
            advect_axis(s, dt / (float)na, 0);
            advect_axis(s, dt / (float)na, 1);
        }
    }
    if (s->cur_gamma_max > 0.0f) /* f_tt + gamma f_t, on the velocity */
        for (int y = 0; y < s->ny; ++y) {
            const size_t r = ms_surface_at(s, 0, y);
            for (int x = 0; x < s->nx; ++x)
                s->v[r + x] *= expf(-s->cur_gamma[r + x] * dt);
        }
    s->view_dirty = 1;
    return MS_OK;
}

/* gamma = kappa |S| from central differences of U (one-sided at edges). */
static void strain_damping(ms_surface *s)
{
    const int nx = s->nx, ny = s->ny;
    const float kappa = s->desc.turbulence_damping, inv = 1.0f / s->desc.dx;
    float gmax = 0.0f;
    for (int y = 0; y < ny; ++y)
        for (int x = 0; x < nx; ++x) {
            const int x0 = x > 0 ? x - 1 : x, x1 = x < nx - 1 ? x + 1 : x;
            const int y0 = y > 0 ? y - 1 : y, y1 = y < ny - 1 ? y + 1 : y;
            const float sx = inv / (float)MS_MAX(x1 - x0, 1), sy = inv / (float)MS_MAX(y1 - y0, 1);
            const size_t e = ms_surface_at(s, x1, y), w = ms_surface_at(s, x0, y);
            const size_t n = ms_surface_at(s, x, y1), so = ms_surface_at(s, x, y0);
            const float ux = (s->cur_u[e] - s->cur_u[w]) * sx,
                        vy = (s->cur_v[n] - s->cur_v[so]) * sy;
            const float uy = (s->cur_u[n] - s->cur_u[so]) * sy,
                        vx = (s->cur_v[e] - s->cur_v[w]) * sx;
            const float shear = uy + vx;
            const float S = sqrtf(2.0f * (ux * ux + vy * vy) + shear * shear); /* 1/s */
            const float g = kappa * S;
            s->cur_gamma[ms_surface_at(s, x, y)] = g;
            gmax = MS_MAX(gmax, g);
        }
    s->cur_gamma_max = gmax;
}

ms_status ms_surface_set_current(ms_surface *s, const float *ux, const float *uy)
{
    ms_status st;
    if ((st = ms_check_not_null(PART, "surface", s)))
        return st;
    if (!ux != !uy)
        return ms_fail(MS_ERR_INVALID_ARGUMENT,
                       "surface: current needs both ux and uy, or neither (NULL: no current)");
    if (!ux) {
        ms_free(s->cur_u);
        ms_free(s->cur_tmp);
        s->cur_u = s->cur_v = s->cur_gamma = s->cur_tmp = NULL;
        s->cur_max = s->cur_gamma_max = 0.0f;
        return MS_OK;
    }
    const size_t n = (size_t)s->nx * s->ny;
    for (size_t i = 0; i < n; ++i) {
        const float m = sqrtf(ux[i] * ux[i] + uy[i] * uy[i]);
        if (!(m <= MAX_CURRENT))
            return ms_fail(MS_ERR_INVALID_ARGUMENT,
                           "surface: current (%g, %g) m/s at cell %zu is not finite or over %g "
                           "m/s",
                           (double)ux[i], (double)uy[i], i, (double)MAX_CURRENT);
    }
    if (!s->cur_u) {
        /* u, v and gamma in one block, the two scratch planes in another */
        s->cur_u = ms_alloc_array(3 * s->plane, sizeof(float));
        s->cur_tmp = ms_alloc_array(2 * s->plane, sizeof(float));
        if (!s->cur_u || !s->cur_tmp) {
            ms_free(s->cur_u);
            ms_free(s->cur_tmp);
            s->cur_u = s->cur_tmp = NULL;
            return ms_fail(MS_ERR_OUT_OF_MEMORY, "surface: out of memory for a current on %d x %d",
                           s->nx, s->ny);
        }
        s->cur_v = s->cur_u + s->plane;
        s->cur_gamma = s->cur_u + 2 * s->plane;
    }
    float m2 = 0.0f; /* m^2/s^2 */
    for (int y = 0; y < s->ny; ++y) {
        const size_t r = ms_surface_at(s, 0, y);
        memcpy(s->cur_u + r, ux + (size_t)y * s->nx, s->nx * sizeof(float));
        memcpy(s->cur_v + r, uy + (size_t)y * s->nx, s->nx * sizeof(float));
        for (int x = 0; x < s->nx; ++x)
            m2 = MS_MAX(m2, s->cur_u[r + x] * s->cur_u[r + x] + s->cur_v[r + x] * s->cur_v[r + x]);
    }
    s->cur_max = sqrtf(m2);
    strain_damping(s);
    return MS_OK;
}

size_t ms_surface_current_bytes(const ms_surface *s)
{
    return s->cur_u ? 5 * s->plane * sizeof(float) : 0;
}
