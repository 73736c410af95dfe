/* ms_volume_step: sub-steps of symplectic Euler (v += a dt, then
 * x += v dt) with the time step of each sub-step chosen from the state.
 * Under MS_PRESSURE_DFSPH (dfsph.c) a sub-step is Bender & Koschier's:
 * density and factors, the divergence-free solve of v, the other forces,
 * the kick, the constant-density solve of v*, the drift; c = 0 below (no
 * sound speed: the velocity's CFL, lambda spacings a sub-step, and
 * a dt^2 <= 0.16 lambda^2 spacing) and there is no eq. 15 field.
 *
 *   CFL      dt <= lambda h / (c + v_max + v_collider)   c: sound speed
 *   force    dt <= lambda sqrt(h / a_max)                 (Monaghan 1992)
 *   viscous  dt <= lambda / D_max,  D_i = mu/rho_i sum_j m/(2 rho_j) lap W_visc
 *            (explicit diffusion of eq. 14 is stable for dt D_i <= 1)
 *
 * lambda = desc.courant <= 0.5. The collider field's stiffness
 * omega = sqrt(2 A / r_c) = sqrt(8) c / h needs dt < 2/omega = 0.71 h/c,
 * which the CFL bound with lambda <= 0.5 always meets. The rest of the
 * step is split into k = ceil(rest / bound) equal parts and one part is
 * taken, so sub-steps are deterministic and never leave a sliver.
 */
#include <math.h>

#include <stdatomic.h>

#include "volume/volume_internal.h"

/* The factor ms_volume_settle scales every velocity by after each sub-step:
 * the slow modes of the column (a period of many sub-steps) are damped in
 * a few of their periods, the settling of a 0.25 m pool at a 5 cm spacing
 * done in about 5 s (tests/test_stability.c). */
#define SETTLE_DAMP 0.9f

#if MS_VOLUME_HAVE_AVX512
#include <immintrin.h>

#include "volume/records_avx512.h"
#endif

typedef struct bounds_ctx {
    ms_volume *v;
    float vmax2[MS_VOLUME_MAX_THREADS];
    float amax2[MS_VOLUME_MAX_THREADS];
    float dmax[MS_VOLUME_MAX_THREADS];
    float rhomax[MS_VOLUME_MAX_THREADS];
    int bad[MS_VOLUME_MAX_THREADS];
} bounds_ctx;

#if MS_VOLUME_HAVE_AVX512
/* Lanes [i, i + 16) of [i, e): the valid ones (the next part's particles
 * belong to another thread). */
__attribute__((target("avx512f,bmi2"), always_inline)) static inline __mmask16 block_mask(int i,
                                                                                          int e)
{
    const unsigned rem = (unsigned)(e - i);
    return ms_lanes_left(rem);
}

/* |(x, y, z)|^2 of 16 lanes, (x x + y y) + z z as the C loop. */
__attribute__((target("avx512f"), always_inline)) static inline __m512 norm2(__m512 x, __m512 y,
                                                                             __m512 z)
{
    return _mm512_add_ps(_mm512_add_ps(_mm512_mul_ps(x, x), _mm512_mul_ps(y, y)),
                         _mm512_mul_ps(z, z));
}

/* bounds_part in 16 lanes (GCC leaves the C loop scalar at -O2): max_ps(a, m) is `a > m ? a : m`, the C loop's test (a
 * NaN a keeps m), and the maxima of lanes that start at +0 do not depend
 * on the order: the same results. Masked lanes read 0 and change
 * nothing. */
__attribute__((target("avx512f,bmi2"))) static void bounds_avx512(const ms_volume *v, int b, int e,
                                                                  float out[4], int *bad)
{
    const __m512 inf = _mm512_set1_ps(INFINITY);
    __m512 vm = _mm512_setzero_ps(), am = vm, dm = vm, rm = vm;
    __mmask16 ok = 0xffff;
    for (int i = b; i < e; i += 16) {
        const __mmask16 m = block_mask(i, e);
        const __m512 v2 =
            norm2(_mm512_maskz_loadu_ps(m, v->vx + i), _mm512_maskz_loadu_ps(m, v->vy + i),
                  _mm512_maskz_loadu_ps(m, v->vz + i));
        const __m512 a2 =
            norm2(_mm512_maskz_loadu_ps(m, v->ax + i), _mm512_maskz_loadu_ps(m, v->ay + i),
                  _mm512_maskz_loadu_ps(m, v->az + i));
        const __m512 d = _mm512_maskz_loadu_ps(m, v->visc_rate + i);
        ok &= _mm512_cmp_ps_mask(v2, inf, _CMP_LT_OQ) & _mm512_cmp_ps_mask(a2, inf, _CMP_LT_OQ) &
              _mm512_cmp_ps_mask(d, inf, _CMP_LT_OQ);
        vm = _mm512_max_ps(v2, vm);
        am = _mm512_max_ps(a2, am);
        dm = _mm512_max_ps(d, dm);
        rm = _mm512_max_ps(_mm512_maskz_loadu_ps(m, v->rho + i), rm);
    }
    out[0] = _mm512_reduce_max_ps(vm);
    out[1] = _mm512_reduce_max_ps(am);
    out[2] = _mm512_reduce_max_ps(dm);
    out[3] = _mm512_reduce_max_ps(rm);
    *bad = ok != 0xffff;
}
#endif

static void bounds_part(void *ctxp, int part, int b, int e)
{
    bounds_ctx *ctx = ctxp;
    const ms_volume *v = ctx->v;
#if MS_VOLUME_HAVE_AVX512
    if (v->isa == MS_VOLUME_ISA_AVX512) {
        float m[4];
        bounds_avx512(v, b, e, m, &ctx->bad[part]);
        ctx->vmax2[part] = m[0];
        ctx->amax2[part] = m[1];
        ctx->dmax[part] = m[2];
        ctx->rhomax[part] = m[3];
        return;
    }
#endif
    float vm = 0.0f, am = 0.0f, dm = 0.0f, rm = 0.0f;
    int bad = 0;
    for (int i = b; i < e; ++i) {
        float v2 = v->vx[i] * v->vx[i] + v->vy[i] * v->vy[i] + v->vz[i] * v->vz[i];
        float a2 = v->ax[i] * v->ax[i] + v->ay[i] * v->ay[i] + v->az[i] * v->az[i];
        bad |= !(v2 < INFINITY) | !(a2 < INFINITY) | !(v->visc_rate[i] < INFINITY);
        vm = v2 > vm ? v2 : vm;
        am = a2 > am ? a2 : am;
        dm = v->visc_rate[i] > dm ? v->visc_rate[i] : dm;
        rm = v->rho[i] > rm ? v->rho[i] : rm;
    }
    ctx->vmax2[part] = vm;
    ctx->amax2[part] = am;
    ctx->dmax[part] = dm;
    ctx->rhomax[part] = rm;
    ctx->bad[part] = bad;
}

typedef struct move_ctx {
    ms_volume *v;
    float dt;
} move_ctx;

#if MS_VOLUME_HAVE_AVX512
/* u[i] += a[i] dt over [b, e) in 16 lanes (the same operations: the same
 * bits; the C loops below are scalar at -O2). */
__attribute__((target("avx512f,bmi2"))) static void axpy_avx512(float *restrict u,
                                                                const float *restrict a, float dt,
                                                                int b, int e)
{
    const __m512 t = _mm512_set1_ps(dt);
    for (int i = b; i < e; i += 16) {
        const __mmask16 m = block_mask(i, e);
        const __m512 x = _mm512_maskz_loadu_ps(m, u + i);
        _mm512_mask_storeu_ps(u + i, m,
                              _mm512_add_ps(x, _mm512_mul_ps(_mm512_maskz_loadu_ps(m, a + i), t)));
    }
}

/* drift_part's axis in 16 lanes: x0 = x, x += u dt. */
__attribute__((target("avx512f,bmi2"))) static void drift_avx512(float *restrict x,
                                                                 float *restrict x0,
                                                                 const float *restrict u, float dt,
                                                                 int b, int e)
{
    const __m512 t = _mm512_set1_ps(dt);
    for (int i = b; i < e; i += 16) {
        const __mmask16 m = block_mask(i, e);
        const __m512 p = _mm512_maskz_loadu_ps(m, x + i);
        _mm512_mask_storeu_ps(x0 + i, m, p);
        _mm512_mask_storeu_ps(x + i, m,
                              _mm512_add_ps(p, _mm512_mul_ps(_mm512_maskz_loadu_ps(m, u + i), t)));
    }
}
#endif

static void kick_part(void *ctxp, int part, int b, int e)
{
    (void)part;
    move_ctx *ctx = ctxp;
    ms_volume *v = ctx->v;
    const float dt = ctx->dt;
#if MS_VOLUME_HAVE_AVX512
    if (v->isa == MS_VOLUME_ISA_AVX512) {
        axpy_avx512(v->vx, v->ax, dt, b, e);
        axpy_avx512(v->vy, v->ay, dt, b, e);
        axpy_avx512(v->vz, v->az, dt, b, e);
        return;
    }
#endif
    float *restrict vx = v->vx, *restrict vy = v->vy, *restrict vz = v->vz;
    const float *restrict ax = v->ax, *restrict ay = v->ay, *restrict az = v->az;
    for (int i = b; i < e; ++i) {
        vx[i] += ax[i] * dt;
        vy[i] += ay[i] * dt;
        vz[i] += az[i] * dt;
    }
}

static void drift_part(void *ctxp, int part, int b, int e)
{
    (void)part;
    move_ctx *ctx = ctxp;
    ms_volume *v = ctx->v;
    const float dt = ctx->dt;
#if MS_VOLUME_HAVE_AVX512
    if (v->isa == MS_VOLUME_ISA_AVX512) {
        drift_avx512(v->x, v->x2, v->vx, dt, b, e);
        drift_avx512(v->y, v->y2, v->vy, dt, b, e);
        drift_avx512(v->z, v->z2, v->vz, dt, b, e);
        return;
    }
#endif
    float *restrict x = v->x, *restrict y = v->y, *restrict z = v->z;
    float *restrict x0 = v->x2, *restrict y0 = v->y2, *restrict z0 = v->z2;
    const float *restrict vx = v->vx, *restrict vy = v->vy, *restrict vz = v->vz;
    for (int i = b; i < e; ++i) {
        x0[i] = x[i];
        y0[i] = y[i];
        z0[i] = z[i];
        x[i] += vx[i] * dt;
        y[i] += vy[i] * dt;
        z[i] += vz[i] * dt;
    }
}

/* Sound speed (m/s) at density rho. */
static float sound_speed_at(const ms_volume *v, float rho)
{
    if (v->desc.pressure == MS_PRESSURE_DFSPH)
        return 0.0f; /* incompressible: the velocity's CFL alone */
    if (v->desc.pressure == MS_PRESSURE_TAIT) {
        float r = fminf(fmaxf(rho / v->desc.rest_density, 1.0f), 2.0f);
        return v->c0 * r * r * r; /* c^2 = dp/drho = c0^2 (rho/rho0)^6 */
    }
    return v->c0;
}

/* The longest sub-step the state allows now: the CFL, force and viscous
 * bounds over all particles (the colliders' speed included), with the one
 * that wins named in v->dt_limit; MS_ERR_UNSTABLE if a particle's velocity
 * or acceleration is not finite. */
static ms_status substep_bound(ms_volume *v, int dfsph, float *out)
{
    const float lambda = v->desc.courant, h = v->K.h;
    float vcol = ms_volume_collider_speed(v);

    bounds_ctx bc = {.v = v};
    ms_vpool_run(v->pool, bounds_part, &bc, v->n);
    float vm2 = 0.0f, am2 = 0.0f, dm = 0.0f, rm = 0.0f;
    int bad = 0;
    for (int p = 0; p < MS_VOLUME_MAX_THREADS; ++p) {
        vm2 = fmaxf(vm2, bc.vmax2[p]);
        am2 = fmaxf(am2, bc.amax2[p]);
        dm = fmaxf(dm, bc.dmax[p]);
        rm = fmaxf(rm, bc.rhomax[p]);
        bad |= bc.bad[p];
    }
    if (bad)
        return ms_fail(MS_ERR_UNSTABLE,
                       "volume: a particle's velocity or acceleration is not finite at "
                       "t = %g s; the state cannot be advanced",
                       v->time);
    float vmax = sqrtf(vm2), amax = sqrtf(am2);
    float c = sound_speed_at(v, rm);
    float dt_cfl = lambda * h / (c + vmax + vcol);
    float dt_force = amax > 0.0f ? lambda * sqrtf(h / amax) : INFINITY;
    if (dfsph) {
        /* a particle moves at most lambda spacings a sub-step by its
         * velocity (SPlisHSPlasH's CFL, 0.4 d / v_max, at lambda = 0.4:
         * the peer's DamBreakModel steps 3.3 ms at d = 0.03 m), and by
         * its acceleration a dt^2 <= 0.16 lambda^2 spacing (the peer has
         * no such bound). The latter binds at rest (a = g) and as a column
         * starts to fall. At lambda^2/4 a corner particle of the 31k dam
         * break compressed 22 % and a settled tank missed rho0 g d by
         * 3.3 %. The factor f in dt = f lambda sqrt(d / a): the settled
         * tank of test_volume (d = 0.02 m, frames of 1/60 s) meets rho0 g d
         * within 2 % at 3 sub-steps a frame (f 0.31-0.46) and misses it at
         * 2 (f 0.5: 2.0 %, 0.75: 2.1 %, 1.0: 3.8 %, at viscosity 0.5-1),
         * so no f gives fig1 (d = 0.05 m) 1 sub-step (f >= 0.58) while that
         * test passes. f = 0.4 (rather than 0.25) keeps the tank at 3 sub-steps
         * for accelerations down to 0.75 g and gives fig1 2 sub-steps
         * instead of 3 (max compression 0.43 -> 0.54 %), glass (d = 0.01 m)
         * 4.1 instead of 6 (1.1 -> 1.5 %; at 0.45, 3.4 and 3.9 %), and the
         * peer's dam break kept its 0.10 % average compression. */
        const float s = v->desc.spacing;
        dt_cfl = lambda * s / (vmax + vcol);
        dt_force = amax > 0.0f ? 0.4f * lambda * sqrtf(s / amax) : INFINITY;
    }
    float dt_visc = dm > 0.0f ? lambda / dm : INFINITY;
    float bound = dt_cfl;
    v->dt_limit = "cfl";
    if (dt_force < bound) {
        bound = dt_force;
        v->dt_limit = "force";
    }
    if (dt_visc < bound) {
        bound = dt_visc;
        v->dt_limit = "viscous";
    }
    v->max_dt = bound;
    *out = bound;
    v->max_speed = vmax;
    return MS_OK;
}

/* The sub-steps of one step of dt on the threads running (ms_volume_step
 * starts the pool's own; ms_volume_settle, before the first step, runs
 * every chunk on the calling thread). */
static ms_status advance(ms_volume *v, float dt)
{
    ms_status st = MS_OK;
    const float lambda = v->desc.courant, h = v->K.h;
    const int dfsph = v->desc.pressure == MS_PRESSURE_DFSPH;
    double rest = dt, tau = 0.0;
    long taken = 0;
    /* Known before any work: no state allows a sub-step longer than
     * the CFL bound at rest, lambda h / c0 (the sound speed never falls
     * below c0 and speeds add to it), so a step needing more than
     * max_substeps of those is refused at once, not after max_substeps. */
    const double at_rest = (double)lambda * h / v->c0, least = ceil(dt / at_rest);
    if (v->n > 0 && least > v->desc.max_substeps)
        return ms_fail(MS_ERR_UNSTABLE,
                       "volume: a step of %g s needs at least %.3g sub-steps (courant %g: at "
                       "most %g s each even at rest), more than max_substeps %d",
                       dt, least, (double)lambda, at_rest, v->desc.max_substeps);
    if (dt > 0.0f)
        ms_volume_colliders_begin(v, dt);
    /* the first sub-step takes the pass the extraction left, if it holds */
    int counted = dt > 0.0f && v->n > 0 && ms_volume_take_counted_pass(v);
    v->pass_ready = 0;
    while (rest > 0.0 && v->n > 0) {
        if (atomic_exchange(&v->cancel, 0)) {
            st = ms_fail(MS_ERR_CANCELED,
                         "volume: step canceled after %ld sub-steps at t = %g s (the state "
                         "is valid at that time)",
                         taken, v->time);
            break;
        }
        if (!counted) {
            ms_volume_grid_build(v);
            ms_volume_boundary(v, tau);
            st = ms_volume_density(v);
            if (st != MS_OK)
                break;
        }
        counted = 0;
        if (dfsph) {
            st = ms_volume_dfsph_divergence(v, v->max_dt);
            if (st != MS_OK)
                break;
        }
        ms_volume_forces(v);
        ms_volume_actions_accel(v);
        float bound = 0.0f;
        st = substep_bound(v, dfsph, &bound);
        if (st != MS_OK)
            break;
        const float vmax = v->max_speed;
        if (taken >= v->desc.max_substeps) {
            st = ms_fail(MS_ERR_UNSTABLE,
                         "volume: a step of %g s needs more than max_substeps %d sub-steps: "
                         "%g s remain and the %s bound allows %g s per sub-step (fastest "
                         "particle %g m/s)",
                         dt, v->desc.max_substeps, rest, v->dt_limit, bound, vmax);
            break;
        }
        double parts = ceil(rest / bound);
        float sub = parts <= 1.0 ? (float)rest : (float)(rest / parts);

        move_ctx mc = {.v = v, .dt = sub};
        ms_vpool_run(v->pool, kick_part, &mc, v->n);
        ms_volume_collider_damp(v, tau, sub);
        ms_volume_actions_drag(v, sub);
        if (dfsph)
            ms_volume_dfsph_density(v, sub);
        ms_vpool_run(v->pool, drift_part, &mc, v->n);
        ms_volume_collider_resolve(v, tau, sub);

        rest = parts <= 1.0 ? 0.0 : rest - sub;
        tau += sub;
        v->time += sub;
        v->last_dt = sub;
        v->substeps++;
        v->counts_valid = 0;
        taken++;
    }
    if (dt > 0.0f)
        ms_volume_colliders_end(v, dt, v->n > 0 ? tau : (double)dt);
    if (v->n == 0)
        v->time += dt;
    if (taken > 0 || v->n == 0)
        v->steps++;
    v->nactions = 0;      /* drags and pushes last one step */
    ms_volume_publish(v); /* ms_volume_particles' views: this step's state */
    return st;
}

ms_status ms_volume_step(ms_volume *v, float dt)
{
    if (!v)
        return ms_fail(MS_ERR_INVALID_ARGUMENT, "volume: step of a NULL volume");
    if (!isfinite(dt) || dt < 0.0f || dt > 10.0f)
        return ms_fail(MS_ERR_INVALID_ARGUMENT, "volume: dt %g s is outside [0, 10] s", dt);
    ms_status st = ms_vpool_start(v->pool);
    if (st != MS_OK)
        return st;
    return advance(v, dt);
}

/* A particle's jitter along one axis: a uniform number in [-a, a] from a
 * 32-bit LCG (Numerical Recipes' constants) carried in *state, so the
 * settled packing is the same bytes on every run and machine. */
static float jitter(unsigned *state, float a)
{
    *state = *state * 1664525u + 1013904223u;
    return ((float)(*state >> 8) * (1.0f / 16777216.0f) - 0.5f) * 2.0f * a;
}

ms_status ms_volume_settle(ms_volume *v, float seconds)
{
    if (!v)
        return ms_fail(MS_ERR_INVALID_ARGUMENT, "volume: settle of a NULL volume");
    if (!isfinite(seconds) || seconds < 0.0f || seconds > MS_VOLUME_SETTLE_MAX_S)
        return ms_fail_key(MS_ERR_INVALID_ARGUMENT, "settle",
                           "volume: settle %g s is outside [0, %g] s", seconds,
                           MS_VOLUME_SETTLE_MAX_S);
    if (seconds == 0.0f || v->n == 0)
        return MS_OK;
    /* break the lattice: a tenth of a spacing each way, kept a hundredth
     * of a spacing inside the domain's walls */
    const float a = 0.1f * v->desc.spacing, margin = 0.01f * v->desc.spacing;
    unsigned state = 12345u;
    float *const axes[3] = {v->x, v->y, v->z};
    for (int i = 0; i < v->n; ++i)
        for (int k = 0; k < 3; ++k) {
            const float lo = v->desc.domain_min[k] + margin, hi = v->desc.domain_max[k] - margin;
            axes[k][i] = fminf(fmaxf(axes[k][i] + jitter(&state, a), lo), hi);
        }
    v->counts_valid = 0;
    /* damped steps: each sub-step of the longest length the state allows,
     * its velocities then scaled by SETTLE_DAMP, so the liquid slides into
     * its packing and no wave it makes survives to freeze into it */
    const double time = v->time;
    const long steps = v->steps, substeps = v->substeps;
    double t = 0.0;
    while (t < seconds) {
        const float dt = (float)fmin(v->max_dt, seconds - t);
        ms_status st = advance(v, dt);
        if (st != MS_OK)
            return st;
        t += dt;
        for (int i = 0; i < v->n; ++i) {
            v->vx[i] *= SETTLE_DAMP;
            v->vy[i] *= SETTLE_DAMP;
            v->vz[i] *= SETTLE_DAMP;
        }
    }
    for (int i = 0; i < v->n; ++i)
        v->vx[i] = v->vy[i] = v->vz[i] = 0.0f;
    v->time = time;
    v->steps = steps;
    v->substeps = substeps;
    ms_volume_publish(v);
    return MS_OK;
}

double ms_volume_kinetic_energy(const ms_volume *v)
{
    if (!v)
        return 0.0;
    double e = 0.0; /* eq. 18, summed in double in the internal order */
    for (int i = 0; i < v->n; ++i)
        e +=
            (double)v->vx[i] * v->vx[i] + (double)v->vy[i] * v->vy[i] + (double)v->vz[i] * v->vz[i];
    return 0.5 * v->mass * e;
}
