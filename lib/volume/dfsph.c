/* MS_PRESSURE_DFSPH: incompressible SPH by the divergence-free solver of
 * Bender & Koschier (SCA 2015; TVCG 2017). No equation of state: each
 * sub-step the pressure is solved for, twice, by Jacobi iterations on the
 * velocities (docs/dfsph.md gives the measurements behind each choice):
 *
 *   divergence-free solve (start of the sub-step, on v):
 *       D rho_i/Dt = sum_j m (v_i - v_j) . grad W_ij         -> 0
 *   constant-density solve (after the kick by the other forces, on v*):
 *       rho*_i = rho_i + dt sum_j m (v*_i - v*_j) . grad W_ij -> rho0
 *
 * Both change the velocities by dv_i = -(1/dt) sum_j m (s_i + s_j) grad W_ij
 * (2017, eqs. 11, 13). Jacobi on i alone gives
 *       s_i = e_i / (|sum_j m grad W_ij|^2 + sum_j |m grad W_ij|^2)
 * with e_i = rho*_i - rho0 (or D rho_i/Dt), clamped at 0: the solve only
 * pushes compressed liquid apart, so the free surface has no tension. An
 * image counts in the diagonal as the mirror of its particle (factors_of):
 * without that a corner particle's update overshoots and a tank at rest
 * blows up. Surface particles (under 3/4 of an inside particle's
 * neighbours) have no divergence error: their missing neighbours would
 * read as expansion the solve cannot mend.
 *
 * Stop rule: the average of e_i / rho0 <= desc.max_density_error (and
 * dt e_i / rho0 <= max_divergence_error) after at least
 * MIN_DENSITY_ITERATIONS and MIN_DIVERGENCE_ITERATIONS (SPlisHSPlasH's
 * minima; without them a splash that dilutes the average gets no pressure
 * and blows up), or the desc's cap. The averages are summed as integers
 * (units of 2^-32), so iteration counts and bytes do not depend on how the
 * particles are split among threads.
 *
 * Warm start: the density solve starts from WARM_FACTOR of the last
 * sub-step's total (rescaled to this dt) inside the liquid and from 0 at
 * surface particles: the clamp never takes back a push that overshoots
 * into expansion, so a stale pressure at the surface pumps energy in (half
 * everywhere doubled the 2k dam break's fastest particle). Its velocity
 * change depends on the positions alone, so the factors pass sums it with
 * the pair terms it computes anyway (warm_kick applies it). The remaining
 * swing of the iteration count at rest (2, 18, 2, 19, ...) is half the
 * hydrostatic pressure rebuilt each sub-step; larger shares steady it but
 * break the hydrostatic and extraction bars of tests/test_volume.c.
 *
 * Momentum: after a solve's first update, a particle still compressed adds
 * DENSITY_MOMENTUM of its last update, s_i = e_i / diag_i + 0.3 s_i,last
 * (e_i > 0), else 0. Both terms are >= 0, so the clamp holds. The share is
 * bounded by the tests: 0.4 leaves glass where the band search misses a
 * root, 0.6 the hydrostatic tank 2.2 % low; carried where e_i = 0 it pumps
 * energy into test_stability's one-particle sheet.
 *
 * Each sub-step the factors pass computes every pair's g_ij (x_i - x_j)
 * (images included) once, and every iteration reads them. The boundary is
 * density.c's images as mirrored particles carrying their particle's s and
 * mirrored velocity (in the shape's frame, so a moving shape pushes).
 * Far from rest: a coincident pair takes forces.c's pair direction, a
 * sub-step removes at most rho0 c0 dt / h of a compression, and the solves
 * make no particle faster than max(c0, its speed) (c0 = desc.sound_speed).
 *
 * prs is an output (no pass of the dynamics reads it): the pressure the
 * liquid exerts, p_i = M rho_i^2 (S_i / dt^2 + D_i / dt) from the two
 * solves' totals, averaged over the step's sub-steps by dt, with M the
 * gradient moment measured on the inside particles each sub-step (a
 * settled column is no lattice: 0.752 against the lattice's 0.774). */
#include <math.h>
#include <stdint.h>

#include "volume/dfsph_pass.h"
#include "volume/passes.h"

/* One pass of a part: the lane pass of the volume's path (passes.c). */
static void dfsph_part(void *ctxp, int part, int b, int e)
{
    ms_dfsph_ctx *ctx = ctxp;
    ms_volume_passes_of(ctx->v->isa)->dfsph(ctx, part, b, e);
}
/* One pass of kind over all particles; the average error of an error pass. */
static float run(ms_volume *v, ms_dfsph_ctx *ctx, pass_kind kind)
{
    ctx->kind = kind;
    for (int p = 0; p < MS_VOLUME_MAX_THREADS; ++p) {
        ctx->err[p] = ctx->mom[p] = 0;
        ctx->nmom[p] = 0;
    }
    ms_vpool_run(v->pool, dfsph_part, ctx, v->n);
    int64_t err = 0;
    for (int p = 0; p < MS_VOLUME_MAX_THREADS; ++p) /* integers: order-free */
        err += ctx->err[p];
    return v->n > 0 ? (float)((double)err / 4294967296.0 / v->n) : 0.0f;
}

/* The divergence solve's total s, kept for the read-out (the density
 * solve reuses df_sum). */
static void keep_div(void *ctxp, int part, int b, int e)
{
    (void)part;
    ms_volume *v = ((ms_dfsph_ctx *)ctxp)->v;
    for (int i = b; i < e; ++i)
        v->df_div_sum[i] = v->df_sum[i];
}

/* Before the factors pass: each particle's warm-start s at the last
 * sub-step's dt (its share of the last total s; 0 with no warm start)
 * into df_sum, which the factors pass reads (the divergence solve
 * zeroes it after), and into the packed copy's pressure slot, which the
 * factors loop (passes.c) loads with each neighbour's position (the density
 * pass wrote prs there and unpack_s writes it back before the force pass:
 * nothing reads the slot in between). */
static void warm_weights(void *ctxp, int part, int b, int e)
{
    (void)part;
    ms_volume *v = ((ms_dfsph_ctx *)ctxp)->v;
    for (int i = b; i < e; ++i) {
        v->df_sum[i] = v->df_warm_on ? warm_share(v, i) * v->df_warm[v->id[i]] : 0.0f;
        v->pk[8 * (size_t)i + 3] = v->df_sum[i]; /* until unpack_s: the factors loop's */
    }
}

/* The warm start, after the kick (the header): v += dt / dt_last^2 m G
 * times the factors pass's sum, capped as an update (apply_of); the
 * density solve's running total starts at the warm s rescaled to this
 * dt; the packed copy's velocities for the error loops. */
static void warm_kick(void *ctxp, int part, int b, int e)
{
    (void)part;
    const ms_dfsph_ctx *ctx = ctxp;
    ms_volume *v = ctx->v;
    const float c = ctx->warm, r2 = ctx->scale;
    for (int i = b; i < e; ++i) {
        if (v->df_warm_on) {
            set_capped(v, i, v->vx[i] + c * v->df_wx[i], v->vy[i] + c * v->df_wy[i],
                       v->vz[i] + c * v->df_wz[i]);
            v->df_sum[i] = r2 * (warm_share(v, i) * v->df_warm[v->id[i]]);
        } else {
            v->df_sum[i] = 0.0f;
        }
        pack_velocity(v, i);
    }
}

static void zero_sum(void *ctxp, int part, int b, int e)
{
    (void)part;
    ms_volume *v = ((ms_dfsph_ctx *)ctxp)->v;
    for (int i = b; i < e; ++i)
        v->df_sum[i] = 0.0f;
}

/* The packed copy's pressure slot set to prs for the force pass after the
 * divergence solve: the factors pass read the warm start's s there
 * (warm_weights). */
static void unpack_s(void *ctxp, int part, int b, int e)
{
    (void)part;
    ms_volume *v = ((ms_dfsph_ctx *)ctxp)->v;
    for (int i = b; i < e; ++i)
        v->pk[8 * (size_t)i + 3] = v->prs[i];
}

/* Room for the pair terms of every list the density pass filled. */
static ms_status reserve_terms(ms_volume *v)
{
    /* room for the pair terms of every list the density pass filled */
    for (int p = 0; p < MS_VOLUME_MAX_THREADS; ++p) {
        const size_t need = v->lists[p].len;
        if (need == 0 || need <= v->df_grad_cap[p])
            continue;
        const size_t cap = v->lists[p].cap > need ? v->lists[p].cap : need;
        float *g = ms_alloc_array(3 * cap, sizeof(float));
        if (!g)
            return ms_fail(MS_ERR_OUT_OF_MEMORY,
                           "volume: no memory for the DFSPH pair terms (%zu pairs)", cap);
        ms_free(v->df_grad[p]);
        v->df_grad[p] = g;
        v->df_grad_cap[p] = cap;
    }
    for (int p = 0; p < MS_VOLUME_MAX_THREADS; ++p) { /* and of every image list */
        const size_t need = v->ghosts[p].len;
        if (need == 0 || need <= v->df_img_cap[p])
            continue;
        const size_t cap = v->ghosts[p].cap > need ? v->ghosts[p].cap : need;
        float *g = ms_alloc_array(4 * cap, sizeof(float));
        if (!g)
            return ms_fail(MS_ERR_OUT_OF_MEMORY,
                           "volume: no memory for the DFSPH image terms (%zu images)", cap);
        ms_free(v->df_img[p]);
        v->df_img[p] = g;
        v->df_img_cap[p] = cap;
    }
    return MS_OK;
}

/* The Jacobi loop shared by both solves: error and update passes until
 * the average error is at most eta after at least least iterations, or
 * the cap. first: the first error pass is done already (its average).
 *
 * An update whose error (the one it was computed from) already met eta
 * ends the solve once the minimum is done, with no error pass after it:
 * that pass would only confirm what the error before it said, the
 * update moving the iterate towards the solution. Measured (the error
 * before and after each iteration, 120 frames a scene): the
 * divergence solve's first error met eta before its one obligatory
 * update in 90 % of fig1's sub-steps (69 % stir, 41 % fig4c), the
 * density solve's second in 57 % (99 % stir, 95 % fig4c); over about
 * 4000 such solves (150 frames each of fig1, fig4c, fig9a, fig10,
 * default, glass, stir) every confirming pass met eta too, so the
 * updates, and the bytes, are those of the loop with the check. Each was
 * one of the 9 neighbour passes of a sub-step: about 1.5 fewer a
 * sub-step on those scenes. What the check would catch and this does
 * not: an update that raises the average error past eta again (a
 * Jacobi step can overshoot); none was seen. *reached is then the error
 * before the last update. */
static int solve(ms_volume *v, ms_dfsph_ctx *ctx, pass_kind error, float eta, int least, int cap,
                 const float *first, float *reached)
{
    int it = 0;
    ctx->momentum = 0.0f; /* no last update yet */
    float avg = first ? *first : run(v, ctx, error);
    for (;;) {
        *reached = avg;
        if ((avg <= eta && it >= least) || it >= cap)
            break;
        run(v, ctx, F_APPLY);
        it++;
        if (avg <= eta && it >= least)
            break; /* met before this update: no confirming pass */
        ctx->momentum = error == F_DENSITY_ERROR ? DENSITY_MOMENTUM : 0.0f;
        avg = run(v, ctx, error);
    }
    return it;
}

ms_status ms_volume_dfsph_divergence(ms_volume *v, float dt_scale)
{
    v->df_divergence_iters = 0;
    if (v->n == 0)
        return MS_OK;
    MS_TRY(reserve_terms(v));
    ms_dfsph_ctx ctx = {.v = v, .dt = dt_scale, .scale = 1.0f};
    /* the warm start of this sub-step's density solve (the last one's
     * pressure, kept by id) is summed by the factors pass */
    v->df_warm_on = v->df_warm_n == v->n && v->df_warm_dt > 0.0f;
    ms_vpool_run(v->pool, warm_weights, &ctx, v->n);
    const float first = run(v, &ctx, F_FACTORS);
    int64_t mom = 0; /* integers: order-free */
    long nmom = 0;
    for (int p = 0; p < MS_VOLUME_MAX_THREADS; ++p) {
        mom += ctx.mom[p];
        nmom += ctx.nmom[p];
    }
    /* no particle inside the liquid (a splash): the lattice's moment */
    v->df_moment =
        nmom > 0 ? (float)((double)mom / 4294967296.0 / (double)nmom) : 2.0f / v->press_scale;
    ms_vpool_run(v->pool, zero_sum, &ctx, v->n);
    if (v->desc.max_divergence_iterations == 0) {
        ms_vpool_run(v->pool, keep_div, &ctx, v->n);
        ms_vpool_run(v->pool, unpack_s, &ctx, v->n);
        return MS_OK;
    }
    float reached = 0.0f;
    int it = solve(v, &ctx, F_DIVERGENCE_ERROR, v->desc.max_divergence_error,
                   MIN_DIVERGENCE_ITERATIONS, v->desc.max_divergence_iterations, &first, &reached);
    ms_vpool_run(v->pool, keep_div, &ctx, v->n);
    ms_vpool_run(v->pool, unpack_s, &ctx, v->n);
    v->df_divergence_iters = it;
    v->df_divergence_total += it;
    v->df_divergence_err = reached;
    return MS_OK;
}

void ms_volume_dfsph_density(ms_volume *v, float dt)
{
    v->df_density_iters = 0;
    if (v->n == 0 || !(dt > 0.0f))
        return;
    ms_dfsph_ctx ctx = {.v = v, .dt = dt, .scale = 1.0f / dt};
    /* warm start (2017, section 4.4): the last sub-step's pressure,
     * kappa_i = s_i rho_i / dt^2 kept, applied before the first error;
     * its sum over the neighbours came with the factors (the header).
     * With none, the running total starts at 0. Either way the packed
     * copy takes the velocities the kick changed. */
    if (v->df_warm_on) {
        const float r = dt / v->df_warm_dt;
        ctx.scale = r * r;
        ctx.warm = dt / (v->df_warm_dt * v->df_warm_dt) * v->mass * v->K.spiky_grad;
    }
    ms_vpool_run(v->pool, warm_kick, &ctx, v->n);
    v->df_warm_on = 0;
    ctx.scale = 1.0f / dt;
    float reached = 0.0f;
    int it = solve(v, &ctx, F_DENSITY_ERROR, v->desc.max_density_error, MIN_DENSITY_ITERATIONS,
                   v->desc.max_density_iterations, NULL, &reached);
    /* the step's mean restarts at its first sub-step (or after anything
     * that moved the particles' ids or the clock: add, remove, restore) */
    ctx.restart = !(v->df_pmean_n == v->n && v->df_pmean_step == v->steps &&
                    v->df_pmean_until == v->time && v->df_pmean_t > 0.0f);
    v->df_pmean_t = ctx.restart ? dt : v->df_pmean_t + dt;
    ctx.weight = dt / v->df_pmean_t;
    ctx.moment = v->df_moment;
    run(v, &ctx, F_PRESSURE);
    v->df_pmean_n = v->n;
    v->df_pmean_step = v->steps;
    v->df_pmean_until = v->time + dt;
    v->df_warm_n = v->n;
    v->df_warm_dt = dt;
    v->df_density_iters = it;
    v->df_density_total += it;
    v->df_density_err = reached;
}
