/* The time step of the surface: the 2D wave equation (paper eq. 2) in flux
 * form, d2f/dt2 = div(c^2 grad f), by leapfrog finite differences:
 *
 *   f_i^{n+1} = f_i^n + delta_i (f_i^n - f_i^{n-1})
 *             + a_i * sum_{j in N(i)} a_j (f_j^n - f_i^n),   a = c dt / dx
 *
 * stored as h = f^n and v = f^n - f^{n-1} (see surface_internal.h):
 *
 *   v <- delta v + (1 + delta)/2 a_i sum_j a_j (h_j - h_i);   h <- h + v
 *
 * Damping is the centred form of f_tt + gamma f_t: with g = gamma dt / 2,
 *   (1 + g) f^{n+1} = 2 f^n - (1 - g) f^{n-1} + dt^2 L f^n,
 * i.e. delta = (1 - g)/(1 + g) and the flux scaled by 1/(1 + g) =
 * (1 + delta)/2. Scaling only the velocity by delta would shrink the
 * stable Courant number to sqrt((1 + delta)/4) (unstable at 0.7 where
 * delta < 0.96); the centred form keeps the bound at 1/sqrt(2) for any
 * damping.
 *
 * The face coefficient a_i a_j is the geometric mean of c^2 on the two
 * sides: it is second-order accurate for a smooth speed map, symmetric (so
 * volume and the discrete energy are conserved without damping), and zero
 * when either side is solid or dry, which makes obstacles reflect without
 * a branch in the loop. delta_i = damping^dt is the velocity kept per
 * sub-step (1 = undamped).
 *
 * Stability (von Neumann / Gershgorin on the 5-point stencil): the largest
 * eigenvalue of the flux operator is at most 8 max(a)^2, so leapfrog is
 * stable for c dt / dx <= 1/sqrt(2). ms_surface_step splits dt into equal
 * sub-steps at Courant number <= COURANT_MAX just below that bound.
 */
#include <assert.h>
#include <float.h>
#include <stdlib.h>
#include <string.h>
#if defined(__SSE__)
#include <xmmintrin.h>
#endif

#include "surface/surface_internal.h"

#define PART "surface"
#define COURANT_MAX 0.7f                 /* < 1/sqrt(2) = 0.7071 */
#define MAX_STEP 10.0f                   /* s: longer calls are refused as a unit error */
#define MAX_LEVELS MS_SURFACE_MAX_LEVELS /* sub-steps fused into one sweep (block()) */

float ms_surface_stable_dt(const ms_surface *s)
{
    if (s->disp)
        return ms_surface_dispersive_stable_dt(s);
    if (!(s->max_speed > 0))
        return FLT_MAX; /* all cells dry or solid: nothing moves */
    return COURANT_MAX * s->desc.dx / s->max_speed;
}

/* One interior row of the velocity update (all pointers at the row's
 * ghost column 0):
 *   v_i <- delta_i v_i + (1 + delta_i)/2 a_i sum_j a_j (h_j - h_i).
 * Unit stride, no calls, no branches: the loop vectorises. */
static inline __attribute__((always_inline)) void velocity_row(float *restrict v,
                                                               const float *restrict h,
                                                               const float *restrict a,
                                                               const float *restrict d, ptrdiff_t W,
                                                               int nx)
{
    /* the rows above and below as pointers of their own and the cells
     * counted from 0, so the loop is a plain count: clang's vectoriser
     * gave up on the offsets i +- W from one pointer (-Wpass-failed) */
    const float *restrict hn = h - W + 1, *restrict hs = h + W + 1;
    const float *restrict an = a - W + 1, *restrict as = a + W + 1;
    const float *restrict hw = h, *restrict he = h + 2, *restrict aw = a, *restrict ae = a + 2;
    float *restrict vc = v + 1;
    const float *restrict hc = h + 1, *restrict ac = a + 1, *restrict dc = d + 1;
#pragma omp simd
    for (int i = 0; i < nx; ++i) {
        const float c = hc[i];
        const float flux =
            ae[i] * (he[i] - c) + aw[i] * (hw[i] - c) + as[i] * (hs[i] - c) + an[i] * (hn[i] - c);
        vc[i] = dc[i] * vc[i] + (0.5f + 0.5f * dc[i]) * ac[i] * flux;
    }
}

/* velocity_row where every cell of the row and its four neighbours has
 * a = a0 and delta = d0 (ms_surface_find_uniform): the same operations on
 * the same values, so the same bits, without loading the five a and the
 * delta of each cell (fig1's 400^2 step: 1.6x faster, measured). */
static inline __attribute__((always_inline)) void velocity_row_uniform(float *restrict v,
                                                                       const float *restrict h,
                                                                       float a0, float d0,
                                                                       ptrdiff_t W, int nx)
{
    const float *restrict hn = h - W + 1, *restrict hs = h + W + 1;
    const float *restrict hw = h, *restrict he = h + 2;
    float *restrict vc = v + 1;
    const float *restrict hc = h + 1;
#pragma omp simd
    for (int i = 0; i < nx; ++i) {
        const float c = hc[i];
        const float flux =
            a0 * (he[i] - c) + a0 * (hw[i] - c) + a0 * (hs[i] - c) + a0 * (hn[i] - c);
        vc[i] = d0 * vc[i] + (0.5f + 0.5f * d0) * a0 * flux;
    }
}

/* h_i <- h_i + v_i over one row: f^{n+1} = f^n + (f^{n+1} - f^n). */
static inline __attribute__((always_inline)) void height_row(float *restrict h,
                                                             const float *restrict v, int nx)
{
#pragma omp simd
    for (int i = 1; i <= nx; ++i)
        h[i] += v[i];
}

/* Periodic: the ghost ring of f^n holds the opposite edge. */
static void wrap_ghosts(ms_surface *s, float *f)
{
    const int nx = s->nx, ny = s->ny;
    for (int y = 1; y <= ny; ++y) {
        float *row = f + ms_surface_row(s, y);
        row[0] = row[nx];
        row[nx + 1] = row[1];
    }
    memcpy(f + ms_surface_row(s, 0) + 1, f + ms_surface_row(s, ny) + 1, nx * sizeof(float));
    memcpy(f + ms_surface_row(s, ny + 1) + 1, f + ms_surface_row(s, 1) + 1, nx * sizeof(float));
}

/* Absorb: Mur's first-order condition (df/dt + c df/dn = 0 discretised
 * between the edge cell e and its ghost g) advances the ghost to n+1:
 *   g^{n+1} = e^n + (a - 1)/(a + 1) (e^{n+1} - g^n),   a = c dt / dx,
 * once e holds f^{n+1} (so e^n = h - v) and g still holds f^n. */
static inline void mur(float *h, const float *v, const float *a, ptrdiff_t g, ptrdiff_t e)
{
    const float k = (a[e] - 1.0f) / (a[e] + 1.0f);
    h[g] = (h[e] - v[e]) + k * (h[e] - h[g]);
}

/* The ghosts of interior row y (1-based) that Mur advances once the row's
 * height is at the new level: its two side ghosts, and the ghost row below
 * the first row or above the last. */
static void mur_row(ms_surface *s, int y)
{
    const int nx = s->nx, ny = s->ny;
    const ptrdiff_t row = (ptrdiff_t)ms_surface_row(s, y);
    mur(s->h, s->v, s->a, row, row + 1);
    mur(s->h, s->v, s->a, row + nx + 1, row + nx);
    if (y == 1 || y == ny) {
        const ptrdiff_t ghost = (ptrdiff_t)ms_surface_row(s, y == 1 ? 0 : ny + 1);
        for (int x = 1; x <= nx; ++x)
            mur(s->h, s->v, s->a, ghost + x, row + x);
    }
}

/* K sub-steps fused into one sweep over the rows (temporal blocking), so a
 * grid larger than the caches is streamed from memory once per K steps
 * instead of once per step.
 *
 * One step is a row sweep: V(y) updates the velocity of row y from the
 * heights of rows y-1..y+1, and H(y-1) then advances the height of row y-1,
 * which no later stencil of this step needs. Step L of the block (0-based)
 * runs the same sweep 2L rows behind step 0: V_L(y) needs row y+1 at step
 * L-1, which H_{L-1}(y+1) produced earlier in the same iteration, and
 * H_L(y-1) overwrites row y-1 only after every stencil of step L that reads
 * it. Only the 2K + 2 rows around the front are touched at a time.
 *
 * The same operations in the same order per cell as K single steps, so the
 * result is bitwise the same whatever K is. target_clones builds the sweep
 * for AVX-512, AVX2 and the baseline and picks one at load time: with
 * -std=c11 there is no FMA contraction, so every clone gives the same bits. */
#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__) && !defined(__SANITIZE_THREAD__)
__attribute__((target_clones("avx512f", "avx2", "default")))
#endif
static void
block(ms_surface *s, int K, const float *level_xy)
{
    const ptrdiff_t W = s->stride;
    const int nx = s->nx, ny = s->ny, absorb = s->desc.boundary == MS_BOUNDARY_ABSORB;
    float *h = s->h, *v = s->v;
    const float *a = s->a, *d = s->delta;
    const int last = ny + 2 * (K - 1) + 1;
    const int uniform = s->uniform == 1 && nx >= 3;
    for (int t = 1; t <= last; ++t) {
        for (int L = 0; L < K; ++L) {
            const int yv = t - 2 * L, yh = yv - 1;
            if (yv >= 1 && yv <= ny) {
                const size_t o = ms_surface_row(s, yv);
                if (uniform && yv >= 2 && yv <= ny - 1) {
                    /* the whole row from its aligned start, then the two
                     * edge cells again from their old v with the general
                     * row (they see the ghosts' a) */
                    const size_t e = o + (size_t)nx - 1;
                    const float v0 = v[o + 1], v1 = v[e + 1];
                    velocity_row_uniform(v + o, h + o, s->a0, s->d0, W, nx);
                    v[o + 1] = v0;
                    v[e + 1] = v1;
                    velocity_row(v + o, h + o, a + o, d + o, W, 1);
                    velocity_row(v + e, h + e, a + e, d + e, W, 1);
                } else
                    velocity_row(v + o, h + o, a + o, d + o, W, nx);
                if (s->ndist)
                    ms_surface_disturbers_force_row(s, yv - 1, v + o,
                                                    level_xy + (size_t)L * 2 * s->ndist);
            }
            if (yh >= 1 && yh <= ny) {
                const size_t o = ms_surface_row(s, yh);
                height_row(h + o, v + o, nx);
                if (absorb)
                    mur_row(s, yh);
            }
        }
    }
}

/* Advance n sub-steps of dt: blocks of up to MAX_LEVELS fused steps. A
 * periodic grid needs its far edge before its near one, which no sweep
 * can give early, so it runs one step a sweep. The clock advances by K dt
 * a block, or with each_step by dt a step (the sum n calls of one sub-step
 * make: ms_surface_step_calls). */
static ms_status advance(ms_surface *s, float dt, int n, int each_step)
{
    /* ms_surface_add_disturber grows level_xy with the disturbers: a step
     * allocates nothing */
    assert(s->ndist <= s->level_cap);
    float *level_xy = s->level_xy;
    if (s->uniform < 0)
        ms_surface_find_uniform(s);
    const int periodic = s->desc.boundary == MS_BOUNDARY_PERIODIC;
    while (n > 0) {
        if (atomic_exchange(&s->cancel, 0))
            return ms_fail(MS_ERR_CANCELED,
                           "surface: step canceled with %d sub-steps left at t = %g s", n, s->time);
        const int K = periodic ? 1 : MS_MIN(n, MAX_LEVELS);
        /* where each disturber is at each step of the block */
        for (int L = 0; L < K && s->ndist; ++L) {
            ms_surface_disturbers_positions(s, level_xy + (size_t)L * 2 * s->ndist);
            ms_surface_disturbers_advance(s, dt);
        }
        if (periodic)
            wrap_ghosts(s, s->h);
        block(s, K, level_xy);
        if (each_step)
            for (int L = 0; L < K; ++L)
                s->time += (double)dt;
        else
            s->time += (double)K * dt;
        s->substeps += K;
        n -= K;
    }
    return MS_OK;
}

/* v is a displacement per sub-step: when the sub-step changes, rescale it
 * so the velocity v / dt carries over unchanged. */
static void rescale_velocity(ms_surface *s, float dt)
{
    if (s->v_dt > 0 && s->v_dt != dt) {
        const float k = dt / s->v_dt;
        for (size_t i = 0; i < s->plane; ++i)
            s->v[i] *= k;
    }
    s->v_dt = dt;
}

/* calls sub-steps of dt each (ms_surface_step_calls) */
static ms_status step_calls(ms_surface *s, float dt, int calls)
{
    ms_status st;
    if ((st = ms_check_not_null(PART, "surface", s)))
        return st;
    if (!isfinite(dt) || dt < 0 || dt > MAX_STEP)
        return ms_fail(MS_ERR_INVALID_ARGUMENT, "surface: step dt %g s is outside [0, %g] s",
                       (double)dt, (double)MAX_STEP);
    if (dt == 0)
        return MS_OK;
    const float dt_max = ms_surface_stable_dt(s);
    const double n = ceil((double)dt / dt_max);
    if (n > s->desc.max_substeps)
        return ms_fail(MS_ERR_UNSTABLE,
                       "surface: wave_speed %g m/s with dx %g m needs dt <= %.3g s; a step of "
                       "%g s would take %.0f sub-steps, over max_substeps %d",
                       (double)s->max_speed, (double)s->desc.dx, (double)dt_max, (double)dt, n,
                       s->desc.max_substeps);
    const int nsub = n < 1 ? 1 : (int)n;
    const float sub = dt / (float)nsub;
#if defined(__SSE__)
    /* Decaying waves end in subnormal floats, which cost ~100x per
     * operation on x86: flush them to zero for this call (this thread's
     * MXCSR, restored before returning). Values that small (< 1e-38 m)
     * are nothing to the result. */
    const unsigned int csr = _mm_getcsr();
    _mm_setcsr(csr | 0x8040u); /* FTZ | DAZ */
#endif
    /* Calls of one sub-step each without rain (which falls between calls)
     * are one advance: its sweeps fuse up to MAX_LEVELS steps (block()),
     * the same bits as one sweep per call (a sweep per call streamed
     * fig1's grid twice a frame at N_time = 2); the clock adds dt a step, as the calls do. */
    const int fuse = nsub == 1 && !(s->rain.rate > 0);
    st = MS_OK;
    for (int c = 0; c < calls && st == MS_OK; c += fuse ? calls : 1) {
        if (s->rain.rate > 0)
            ms_surface_rain(s, dt);
        ms_surface_refresh_coefficients(s, sub);
        rescale_velocity(s, sub);
        /* the current first, over the time this pass of the loop steps
         * (current.c: Lie splitting) */
        if (s->cur_u && (st = ms_surface_current_advance(s, fuse ? dt * (float)calls : dt)))
            break;
        if (s->disp)
            st = ms_surface_dispersive_advance(s, sub, fuse ? calls : nsub);
        else
            st = fuse ? advance(s, sub, calls, 1) : advance(s, sub, nsub, 0);
    }
#if defined(__SSE__)
    _mm_setcsr(csr);
#endif
    s->view_dirty = 1;
    return st;
}

ms_status ms_surface_step(ms_surface *s, float dt)
{
    return step_calls(s, dt, 1);
}

ms_status ms_surface_step_calls(ms_surface *s, float dt, int calls)
{
    if (calls < 1)
        return ms_fail(MS_ERR_INVALID_ARGUMENT, "surface: %d step calls; at least 1", calls);
    return step_calls(s, dt, calls);
}
