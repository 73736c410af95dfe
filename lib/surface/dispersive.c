/* The dispersive surface model (desc.model = MS_SURFACE_MODEL_DISPERSIVE):
 * linear water waves with the Airy dispersion relation and capillarity at
 * the local depth d,
 *
 *     omega^2(k, d) = (g k + T k^3) tanh(k d),   T = sigma / rho,
 *
 * in place of eq. 2's omega = c k. Every wavelength travels at its own
 * speed: a drop's ring spreads into a train, short capillary ripples ahead
 * and long gravity waves behind, and a boat leaves a Kelvin-like wake.
 *
 * Method: a per-step exact-dispersion operator. The state is eq. 2's
 * (h = f^n, v = f^n - f^{n-1}) and the step eq. 2's leapfrog,
 *
 *     v <- delta v - (1 + delta)/2 S (f + P);   h <- h + v,
 *
 * but S is applied in the eigenbasis of the grid's boundary (cosines,
 * DCT-II, for reflecting and absorbing edges; Fourier modes for periodic
 * ones: fft.c) with the symbol S(k) = 4 sin^2(omega(k, d) dt / 2). For that
 * symbol the leapfrog recurrence cos(omega_n dt) = 1 - S/2 gives every
 * resolved mode exactly the Airy frequency, whatever the sub-step: the
 * phase error comes from the float transforms and the depth bands alone,
 * not from the grid (a 5-point Laplacian is 2.6 % slow at 8 cells per
 * wavelength) or the time step. S lies in [0, 4], so the step is stable
 * for any sub-step; sub-steps keep omega dt <= PHASE_MAX for the fastest
 * mode only so that moving disturbers and the coupler are sampled finely.
 * Tessendorf's iWave (a truncated convolution kernel of the deep-water
 * operator) was not taken: its kernel truncation and explicit time step
 * leave errors of several per cent at the short wavelengths, and its
 * single kernel has no depth.
 *
 * Depth: d = c^2 / g from the speed map (or desc.wave_speed), so a speed
 * map set with ms_surface_speed_from_depth gives its depths back and the
 * long waves keep eq. 2's speed sqrt(g d). Depths are clamped to
 * DEEP_KD / k_min (deep for every mode the grid holds). A uniform depth
 * is one band; a varying one is covered by bands d_b = d_min BAND_RATIO^b,
 * the field is transformed once, and each band's symbol is applied and
 * transformed back; a cell of depth d between bands b and b+1
 * (d = d_b^(1-w) d_{b+1}^w) takes (1 - w) of band b's result and w of
 * band b+1's:
 *
 *     (S f)_i = sum_b w_b(i) (S_b f)_i,
 *
 * the operator of the cell's own depth applied to the whole field (the
 * local-depth approximation), with S interpolated linearly in log d:
 * phase-speed error <= 0.75 % for BAND_RATIO sqrt(2) over depths
 * 1e-4 .. 20 m and omega dt up to PHASE_MAX. A flat surface stays flat
 * (S_b 1 = 0) and a level offset adds no volume however the depth varies
 * (sum_i (S f)_i = sum_b <S_b w_b, f> = 0 for constant f); only where the
 * depth varies is the operator not symmetric, so the energy below is
 * exact for a uniform depth and approximate elsewhere. A blend of the
 * square-root weighted operators (sum_b M_b S_b M_b, symmetric) was
 * measured and not taken: at a jump in depth its weights give a cell a
 * spring of the operator's diagonal, a mode 52 % off its frequency.
 * Cost: 1 + nb transforms a sub-step (nb = 1 for a uniform depth).
 *
 * Obstacles and dry cells have weight 0 in every band: they stay at 0.
 * The operator reads them at the water's mean height, so a flat surface
 * stays flat at any level and waves reflect from them as from a fixed
 * end (eq. 2's walls reflect as a free end); where there are such cells
 * or several bands, the mean of S f over the water is taken out so that
 * the volume stays exact. Filling them with the water next to them
 * continued instead (a free end) was measured and not taken: it let 7.2 %
 * of a wave's mean square height through an 8-cell wall, against 3.3 %
 * this way, and lost the symmetry. The operator is not local:
 * its kernel reaches across a wall, so a thin wall lets part of a wave
 * through (tests/test_dispersion.c measures how much by thickness). Damping and
 * its map are eq. 2's centred delta; an absorbing edge is the same sponge
 * (no Mur condition: it belongs to eq. 2's stencil), over the cosine
 * basis. Drops, rain and the coupler's excitation change h as for eq. 2;
 * a disturber's pressure head P enters the operator as in disturber.c. */
#include <float.h>
#include <math.h>
#include <string.h>

#include "surface/fft.h"
#include "surface/surface_internal.h"

#define PART "surface"
#define BAND_RATIO 1.41421356 /* depth ratio between neighbouring bands */
#define PHASE_MAX 2.0         /* rad: omega dt of the fastest mode in one sub-step */
#define DEEP_KD 5.0           /* tanh(5) = 0.99991: depth beyond 5 / k_min is deep */
#define PI 3.14159265358979323846

struct ms_dispersion {
    int periodic;
    ms_fft *fx, *fy;                /* lengths nx and ny */
    int nb, nb_cap;                 /* depth bands, and room for them in sym */
    double d_lo;                    /* m, depth of band 0 */
    float *sym;                     /* nb * nx * ny: S_b, transposed (index x * ny + y) */
    float sym_dt;                   /* s, the sub-step sym holds; 0 = stale */
    int *band;                      /* per cell: its lower band, or -2 (solid or dry) */
    int wet;                        /* cells with a band (not solid, not dry) */
    float *w0, *w1;                 /* per cell: 1 - w and w, the weights of its two bands */
    float *in, *acc, *u, *t, *spec; /* nx * ny scratch; spec: the transformed field */
    ms_cpx *z, *zt, *zspec;         /* nx * ny, periodic only */
};

/* k in 1/m, d in m: omega in rad/s */
static double omega(const ms_surface *s, double k, double d)
{
    const double g = s->desc.gravity, T = s->desc.surface_tension;
    return sqrt((g * k + T * k * k * k) * tanh(k * d));
}

static double deep_depth(const ms_surface *s)
{
    const double L = (double)MS_MAX(s->nx, s->ny) * s->desc.dx;
    const double kmin = (s->desc.boundary == MS_BOUNDARY_PERIODIC ? 2.0 : 1.0) * PI / L;
    return DEEP_KD / kmin;
}

float ms_surface_dispersive_stable_dt(const ms_surface *s)
{
    if (!(s->max_speed > 0))
        return FLT_MAX;
    const double c = s->max_speed;
    const double d = MS_MIN(c * c / s->desc.gravity, deep_depth(s));
    const double k = PI * sqrt(2.0) / s->desc.dx; /* beyond the grid's largest |k| */
    return (float)(PHASE_MAX / omega(s, k, d));
}

void ms_surface_dispersive_destroy(ms_surface *s)
{
    struct ms_dispersion *p = s->disp;
    if (!p)
        return;
    ms_fft_destroy(p->fx);
    ms_fft_destroy(p->fy);
    ms_free(p->sym);
    ms_free(p->band);
    ms_free(p->w0);
    ms_free(p->w1);
    ms_free(p->spec);
    ms_free(p->zspec);
    ms_free(p->in);
    ms_free(p->acc);
    ms_free(p->u);
    ms_free(p->t);
    ms_free(p->z);
    ms_free(p->zt);
    ms_free(p);
    s->disp = NULL;
}

ms_status ms_surface_dispersive_create(ms_surface *s)
{
    const size_t n = (size_t)s->nx * s->ny;
    struct ms_dispersion *p = ms_alloc_array(1, sizeof *p);
    if (!p)
        return ms_fail(MS_ERR_OUT_OF_MEMORY, "surface: out of memory for the dispersive model");
    s->disp = p;
    p->periodic = s->desc.boundary == MS_BOUNDARY_PERIODIC;
    p->fx = ms_fft_create(s->nx);
    p->fy = ms_fft_create(s->ny);
    p->band = ms_alloc_array(n, sizeof *p->band);
    p->w0 = ms_alloc_array(n, sizeof(float));
    p->w1 = ms_alloc_array(n, sizeof(float));
    p->spec = ms_alloc_array(n, sizeof(float));
    p->in = ms_alloc_array(n, sizeof(float));
    p->acc = ms_alloc_array(n, sizeof(float));
    p->u = ms_alloc_array(n, sizeof(float));
    p->t = ms_alloc_array(n, sizeof(float));
    if (p->periodic) {
        p->z = ms_alloc_array(n, sizeof(ms_cpx));
        p->zt = ms_alloc_array(n, sizeof(ms_cpx));
        p->zspec = ms_alloc_array(n, sizeof(ms_cpx));
    }
    if (!p->fx || !p->fy || !p->band || !p->w0 || !p->w1 || !p->in || !p->acc || !p->u || !p->t ||
        !p->spec || (p->periodic && (!p->z || !p->zt || !p->zspec))) {
        ms_surface_dispersive_destroy(s);
        return ms_fail(MS_ERR_OUT_OF_MEMORY,
                       "surface: the dispersive model of a %d x %d grid needs %zu MiB", s->nx,
                       s->ny, (n * (8 * sizeof(float) + 3 * sizeof(ms_cpx))) >> 20);
    }
    return MS_OK;
}

size_t ms_surface_dispersive_bytes(const ms_surface *s)
{
    const struct ms_dispersion *p = s->disp;
    if (!p)
        return 0;
    const size_t n = (size_t)s->nx * s->ny;
    return sizeof *p + ms_fft_bytes(p->fx) + ms_fft_bytes(p->fy) +
           n * (sizeof(int) + 7 * sizeof(float)) + (p->periodic ? 3 * n * sizeof(ms_cpx) : 0) +
           (size_t)p->nb_cap * n * sizeof(float);
}

/* in: the solid and dry cells take the mean height of the water (a
 * wall at the still level: a flat surface stays flat, whatever its level,
 * and waves reflect from the wall as from a fixed end). */
static void extend(const ms_surface *s, float *in)
{
    const struct ms_dispersion *p = s->disp;
    const size_t n = (size_t)s->nx * s->ny;
    if (p->wet == (int)n || p->wet == 0)
        return;
    double sum = 0;
    for (size_t i = 0; i < n; ++i)
        if (p->band[i] >= 0)
            sum += in[i];
    const float m = (float)(sum / p->wet);
    for (size_t i = 0; i < n; ++i)
        if (p->band[i] < 0)
            in[i] = m;
}

/* The depth bands and each cell's weights, from the stepped speeds (solid
 * cells at 0). Called when the speeds change, outside the steps. */
ms_status ms_surface_dispersive_bands(ms_surface *s)
{
    struct ms_dispersion *p = s->disp;
    const int nx = s->nx, ny = s->ny;
    const size_t n = (size_t)nx * ny;
    const double g = s->desc.gravity, deep = deep_depth(s), lr = log(BAND_RATIO);
    double lo = INFINITY, hi = 0;
    for (int y = 0; y < ny; ++y)
        for (int x = 0; x < nx; ++x) {
            const double c = s->speed[ms_surface_at(s, x, y)];
            if (c > 0) {
                const double d = MS_MIN(c * c / g, deep);
                lo = MS_MIN(lo, d);
                hi = MS_MAX(hi, d);
            }
        }
    int nb = 1;
    if (!(hi > 0))
        lo = hi = deep; /* all dry: one band, no cell in it */
    else if (hi > lo * (1 + 1e-6))
        nb = 2 + (int)floor(log(hi / lo) / lr * (1 - 1e-12));
    if (nb > p->nb_cap) {
        float *sym = ms_alloc_array((size_t)nb * n, sizeof(float));
        if (!sym)
            return ms_fail(MS_ERR_OUT_OF_MEMORY,
                           "surface: out of memory for %d depth bands of the dispersive model "
                           "(depths %g .. %g m)",
                           nb, lo, hi);
        ms_free(p->sym);
        p->sym = sym;
        p->nb_cap = nb;
    }
    p->nb = nb;
    p->d_lo = lo;
    for (int y = 0; y < ny; ++y)
        for (int x = 0; x < nx; ++x) {
            const size_t i = (size_t)y * nx + x;
            const double c = s->speed[ms_surface_at(s, x, y)];
            if (!(c > 0)) {
                p->band[i] = -2;
                p->w0[i] = p->w1[i] = 0.0f;
                continue;
            }
            if (nb == 1) {
                p->band[i] = 0;
                p->w0[i] = 1.0f;
                p->w1[i] = 0.0f;
                continue;
            }
            const double tb = log(MS_MIN(c * c / g, deep) / lo) / lr;
            int b = MS_CLAMP((int)floor(tb), 0, nb - 2);
            const double w = MS_CLAMP(tb - b, 0.0, 1.0);
            p->band[i] = b;
            p->w0[i] = (float)(1 - w);
            p->w1[i] = (float)w;
        }
    p->wet = 0;
    for (size_t i = 0; i < n; ++i)
        p->wet += p->band[i] >= 0;
    p->sym_dt = 0.0f;
    (void)n;
    return MS_OK;
}

int ms_surface_dispersive_band_count(const ms_surface *s)
{
    return s->disp ? s->disp->nb : 0;
}

void ms_surface_dispersive_invalidate(ms_surface *s)
{
    if (s->disp)
        s->disp->sym_dt = 0.0f;
}

/* S_b(k) = 4 sin^2(omega(k, d_b) dt / 2) on the transform's wavenumbers,
 * in the transposed layout the operator multiplies in. */
static void build_symbols(ms_surface *s, float dt)
{
    struct ms_dispersion *p = s->disp;
    const int nx = s->nx, ny = s->ny;
    const double dx = s->desc.dx;
    for (int b = 0; b < p->nb; ++b) {
        const double d = p->d_lo * pow(BAND_RATIO, b);
        float *sym = p->sym + (size_t)b * nx * ny;
        for (int x = 0; x < nx; ++x) {
            double kx;
            if (p->periodic)
                kx = 2 * PI * (x <= nx / 2 ? x : x - nx) / (nx * dx);
            else
                kx = PI * x / (nx * dx);
            for (int y = 0; y < ny; ++y) {
                double ky;
                if (p->periodic)
                    ky = 2 * PI * (y <= ny / 2 ? y : y - ny) / (ny * dx);
                else
                    ky = PI * y / (ny * dx);
                const double k = sqrt(kx * kx + ky * ky);
                const double ph = MS_MIN(omega(s, k, d) * dt, PI);
                const double sn = sin(0.5 * ph);
                sym[(size_t)x * ny + y] = (float)(4 * sn * sn);
            }
        }
    }
    p->sym_dt = dt;
}

/* dst (cols x rows) = src (rows x cols) transposed, in cache blocks */
static void transpose(float *restrict dst, const float *restrict src, int rows, int cols)
{
    enum { B = 32 };
    for (int r0 = 0; r0 < rows; r0 += B)
        for (int c0 = 0; c0 < cols; c0 += B)
            for (int r = r0; r < MS_MIN(r0 + B, rows); ++r)
                for (int c = c0; c < MS_MIN(c0 + B, cols); ++c)
                    dst[(size_t)c * rows + r] = src[(size_t)r * cols + c];
}

static void transpose_cpx(ms_cpx *restrict dst, const ms_cpx *restrict src, int rows, int cols)
{
    enum { B = 32 };
    for (int r0 = 0; r0 < rows; r0 += B)
        for (int c0 = 0; c0 < cols; c0 += B)
            for (int r = r0; r < MS_MIN(r0 + B, rows); ++r)
                for (int c = c0; c < MS_MIN(c0 + B, cols); ++c)
                    dst[(size_t)c * rows + r] = src[(size_t)r * cols + c];
}

/* DCT-II (inverse: its inverse) of the `count` rows of length len at
 * rows, two at a time */
static void dct_rows(ms_fft *f, float *rows, int count, int len, int inverse)
{
    int r = 0;
    for (; r + 1 < count; r += 2) {
        float *a = rows + (size_t)r * len, *b = a + len;
        if (inverse)
            ms_dct_inverse2(f, a, b);
        else
            ms_dct_forward2(f, a, b);
    }
    if (r < count) {
        if (inverse)
            ms_dct_inverse(f, rows + (size_t)r * len);
        else
            ms_dct_forward(f, rows + (size_t)r * len);
    }
}

/* spec (or zspec) <- the transform of in, transposed (index x * ny + y) */
static void forward(ms_surface *s, const float *in)
{
    struct ms_dispersion *p = s->disp;
    const int nx = s->nx, ny = s->ny;
    const size_t n = (size_t)nx * ny;
    if (!p->periodic) {
        memcpy(p->u, in, n * sizeof *in);
        dct_rows(p->fx, p->u, ny, nx, 0);
        transpose(p->spec, p->u, ny, nx);
        dct_rows(p->fy, p->spec, nx, ny, 0);
        return;
    }
    for (size_t j = 0; j < n; ++j) {
        p->z[j].re = in[j];
        p->z[j].im = 0.0f;
    }
    for (int y = 0; y < ny; ++y)
        ms_fft_forward(p->fx, p->z + (size_t)y * nx);
    transpose_cpx(p->zspec, p->z, ny, nx);
    for (int x = 0; x < nx; ++x)
        ms_fft_forward(p->fy, p->zspec + (size_t)x * ny);
}

/* u <- S_b f, from the transform forward() left */
static void band_inverse(ms_surface *s, int b)
{
    struct ms_dispersion *p = s->disp;
    const int nx = s->nx, ny = s->ny;
    const size_t n = (size_t)nx * ny;
    const float *sym = p->sym + (size_t)b * n;
    if (!p->periodic) {
        for (size_t j = 0; j < n; ++j)
            p->t[j] = p->spec[j] * sym[j];
        dct_rows(p->fy, p->t, nx, ny, 1);
        transpose(p->u, p->t, nx, ny);
        dct_rows(p->fx, p->u, ny, nx, 1);
        return;
    }
    for (size_t j = 0; j < n; ++j) {
        p->zt[j].re = p->zspec[j].re * sym[j];
        p->zt[j].im = p->zspec[j].im * sym[j];
    }
    for (int x = 0; x < nx; ++x)
        ms_fft_inverse(p->fy, p->zt + (size_t)x * ny);
    transpose_cpx(p->z, p->zt, nx, ny);
    for (int y = 0; y < ny; ++y)
        ms_fft_inverse(p->fx, p->z + (size_t)y * nx);
    const float inv = 1.0f / (float)n;
    for (size_t j = 0; j < n; ++j)
        p->u[j] = p->z[j].re * inv;
}

/* acc = sum_b w_b (S_b in): the row blend of the header, with the solid
 * and dry cells of in at the water's mean first (extend; they have no
 * band: acc is 0 there). Where the grid has such cells or several bands,
 * the mean of acc over the water is taken out, so the volume is kept
 * exactly; for one depth the operator is then P S P on heights of zero
 * mean (P: the water's cells), symmetric, and the energy is kept too. */
static void apply(ms_surface *s, float *in, float *acc)
{
    struct ms_dispersion *p = s->disp;
    const size_t n = (size_t)s->nx * s->ny;
    memset(acc, 0, n * sizeof *acc);
    extend(s, in);
    forward(s, in);
    for (int b = 0; b < p->nb; ++b) {
        int any = 0;
        for (size_t i = 0; i < n && !any; ++i)
            any =
                (p->band[i] == b && p->w0[i] != 0.0f) || (p->band[i] == b - 1 && p->w1[i] != 0.0f);
        if (!any)
            continue;
        band_inverse(s, b);
        for (size_t i = 0; i < n; ++i) {
            const float w = p->band[i] == b ? p->w0[i] : p->band[i] == b - 1 ? p->w1[i] : 0.0f;
            acc[i] += w * p->u[i];
        }
    }
    if ((p->nb > 1 || p->wet < (int)n) && p->wet > 0) {
        double sum = 0;
        for (size_t i = 0; i < n; ++i)
            sum += acc[i];
        const float m = (float)(sum / p->wet);
        for (size_t i = 0; i < n; ++i)
            if (p->band[i] >= 0)
                acc[i] -= m;
    }
}

ms_status ms_surface_dispersive_advance(ms_surface *s, float dt, int n)
{
    struct ms_dispersion *p = s->disp;
    const int nx = s->nx, ny = s->ny;
    if (p->sym_dt != dt)
        build_symbols(s, dt);
    while (n > 0) {
        if (atomic_exchange(&s->cancel, 0))
            return ms_fail(MS_ERR_CANCELED,
                           "surface: step canceled with %d sub-steps left at t = %g s", n, s->time);
        for (int y = 0; y < ny; ++y)
            memcpy(p->in + (size_t)y * nx, s->h + ms_surface_at(s, 0, y), nx * sizeof(float));
        if (s->ndist) {
            /* the heads where the disturbers are at this sub-step */
            ms_surface_disturbers_positions(s, s->level_xy);
            ms_surface_disturbers_advance(s, dt);
            ms_surface_disturbers_head_field(s, s->level_xy, p->in);
        }
        apply(s, p->in, p->acc);
        for (int y = 0; y < ny; ++y) {
            float *restrict h = s->h + ms_surface_at(s, 0, y), *restrict v =
                                                                   s->v + ms_surface_at(s, 0, y);
            const float *restrict dl = s->delta + ms_surface_at(s, 0, y);
            const float *restrict a = p->acc + (size_t)y * nx;
            for (int x = 0; x < nx; ++x) {
                v[x] = dl[x] * v[x] - (0.5f + 0.5f * dl[x]) * a[x];
                h[x] += v[x];
            }
        }
        s->time += (double)dt;
        s->substeps++;
        --n;
    }
    return MS_OK;
}

/* 1/2 dx^2 [sum (v/dt)^2 + sum f^{n+1} S f^n / dt^2]: the staggered energy
 * that the leapfrog step keeps exactly for a symmetric S (a uniform depth;
 * the analogue of energy.c's). Before the first step, at the sub-step of
 * the stable bound. */
double ms_surface_dispersive_energy(const ms_surface *cs)
{
    /* the handle's scratch and symbol cache: a function of (dt, bands)
     * only, so rebuilding them changes no later result */
    ms_surface *s = (ms_surface *)cs;
    struct ms_dispersion *p = s->disp;
    const int nx = s->nx, ny = s->ny;
    const float dt = s->v_dt > 0 ? s->v_dt : ms_surface_dispersive_stable_dt(s);
    if (!(dt < FLT_MAX))
        return 0.0;
    if (p->sym_dt != dt)
        build_symbols(s, dt);
    for (int y = 0; y < ny; ++y) {
        const float *h = s->h + ms_surface_at(s, 0, y), *v = s->v + ms_surface_at(s, 0, y);
        for (int x = 0; x < nx; ++x)
            p->in[(size_t)y * nx + x] = h[x] - v[x]; /* f^n */
    }
    apply(s, p->in, p->acc);
    double kin = 0, pot = 0;
    for (int y = 0; y < ny; ++y) {
        const float *h = s->h + ms_surface_at(s, 0, y), *v = s->v + ms_surface_at(s, 0, y);
        for (int x = 0; x < nx; ++x) {
            kin += (double)v[x] * v[x];
            pot += (double)h[x] * p->acc[(size_t)y * nx + x];
        }
    }
    const double dx = s->desc.dx;
    return 0.5 * dx * dx * (kin + pot) / ((double)dt * dt);
}
