/* Density and pressure. Density is eq. 9 with A = rho, rho_i = sum_j m
 * W(x_i - x_j), self included, with the kernel of desc.density_kernel:
 *   MS_DENSITY_SPIKY  W_press of eq. 11 (the default), the kernel whose
 *                     gradient eq. 13 uses, so the pressure force does the
 *                     work the density change stores: energy-consistent;
 *   MS_DENSITY_POLY6  Mueller et al. 2003's poly6. With the spiky gradient
 *                     of eq. 13 the pair is not energy-consistent; measured
 *                     here, an 8000-particle tank settling under gravity
 *                     with mu = 0 went from 1 J to 250 J of kinetic energy
 *                     in 2 s with poly6 and stayed below 1 J with spiky.
 *                     Poly6 needs mu of about 0.01 rho0 c h to stay still. The domain's walls reflect the liquid: a particle within h of
 * a wall also sums the wall images of its neighbours (the ghost particles
 * of the classic mirror boundary: the real particles reflected across the
 * wall, across two walls at an edge, three at a corner), so it is not taken
 * for an under-dense one and the wall pushes back with the liquid's own
 * pressure. A particle within h of a shape collider sums in the same way
 * the images, across the shape's tangent plane at its closest point, of
 * the neighbours on its side of that plane. Pressure from the equation of state of desc.pressure:
 *   MS_PRESSURE_IDEAL_GAS  p = k (rho - rho0)                    (the paper's)
 *   MS_PRESSURE_TAIT       p = B ((rho/rho0)^7 - 1), B = rho0 c0^2 / 7,
 *                          continued along its tangent beyond rho = 2 rho0
 *                          (a float overflows at (rho/rho0)^7 for degenerate
 *                          layouts such as all particles at one point).
 * Both laws are clamped at p >= 0. The paper's law gives negative pressure
 * wherever rho < rho0, i.e. in the under-sampled layers at the free surface
 * and the walls, and with negative pressure the spiky kernel of eq. 11 is
 * tensile-unstable (Swegle et al. 1995: W'' > 0 under tension): measured
 * here, a 1000-particle block at rest with k = 400 m^2/s^2 and no gravity
 * went from 0 to 90 J of kinetic energy in 0.04 s, its surface layer pulled
 * in at 1100 m/s^2. Mueller et al. used k = 3 m^2/s^2 with mu = 3.5 Pa s,
 * a liquid too soft and too viscous for the paper's water. Clamping is the
 * usual remedy for weakly compressible free-surface SPH; it removes the
 * cohesion of the surface layer and nothing else.
 */
#include <math.h>
#include <stdint.h>
#include <string.h>

#include "volume/law.h"
#include "volume/passes.h"

float ms_volume_pressure(const ms_volume *v, float rho)
{
    return ms_law_pressure(v, rho);
}

/* The lists, density and pressure of a part's particles: the lane pass
 * of the volume's path (passes.c). */
static void density_part(void *ctxp, int part, int b, int e)
{
    ms_density_ctx *ctx = ctxp;
    ms_volume_passes_of(ctx->v->isa)->density(ctx, part, b, e);
}

/* The packed copy's positions and velocities (v->pk: x, y, z, -, vx, vy,
 * vz, -), for the record loads of the force pass (forces.c);
 * density_part adds p and 1/rho. */
static void pack_part(void *ctxp, int part, int b, int e)
{
    (void)part;
    const ms_volume *v = ((ms_density_ctx *)ctxp)->v;
    float *restrict pk = v->pk;
    for (int i = b; i < e; ++i) {
        pk[8 * (size_t)i] = v->x[i];
        pk[8 * (size_t)i + 1] = v->y[i];
        pk[8 * (size_t)i + 2] = v->z[i];
        pk[8 * (size_t)i + 4] = v->vx[i];
        pk[8 * (size_t)i + 5] = v->vy[i];
        pk[8 * (size_t)i + 6] = v->vz[i];
    }
}

ms_status ms_volume_density(ms_volume *v)
{
    ms_density_ctx ctx = {.v = v};
    ms_vpool_run(v->pool, pack_part, &ctx, v->n);
    ms_vpool_run(v->pool, density_part, &ctx, v->n);
    int coincident = 0, surface = 0;
    float max_err = 0.0f;
    double pairs = 0.0;
    int failed = 0;
    for (int p = 0; p < MS_VOLUME_MAX_THREADS; ++p) { /* integer sums, a max: order-free */
        coincident += ctx.coincident[p];
        surface += ctx.surface[p];
        max_err = ctx.max_err[p] > max_err ? ctx.max_err[p] : max_err;
        pairs += ctx.pairs[p];
        failed |= v->list_failed[p];
    }
    if (failed)
        return ms_fail(MS_ERR_OUT_OF_MEMORY, "volume: out of memory for the neighbour lists");
    v->lists_reserved = 1;
    v->surface_count = surface;
    v->pairs = pairs;
    v->counts_valid = 1;
    v->coincident = coincident;
    v->max_density_error = max_err;
    return MS_OK;
}

/* A collider's pose as the boundary pass outside a step sees it. */
static void collider_pose(const ms_shape *s, float out[13])
{
    ms_shape_get_pose(s, out, out + 3);
    ms_shape_get_orientation(s, out + 6, out + 10);
}

ms_status ms_volume_count_neighbours(ms_volume *v)
{
    /* the particles are where the last step left them, and so are the
     * colliders they met (a moving glass seen at its pose, the step's
     * start, read its leading wall's particles 25-35 % compressed) */
    int moved = ms_volume_boundary_after_step(v);
    ms_status st = ms_volume_density(v);
    v->pass_ready = st == MS_OK && !moved; /* the next step starts at the poses */
    v->pass_ncol = v->ncolliders;
    for (int c = 0; c < v->ncolliders; ++c) {
        v->pass_col[c] = v->colliders[c];
        collider_pose(v->colliders[c], v->pass_pose[c]);
    }
    return st;
}

/* After the step's last drift the extraction (and the coupling
 * to the waves) rebuilt the grid and ran a density pass at the end-of-step
 * positions; the next step's first sub-step would build the same again:
 * the sort of particles already in cell order is the identity, and the
 * boundary terms at tau = 0 are those of the step's view of the colliders
 * when none jumped (col_jump 0: shift 0, col_vel the shape's own velocity,
 * compared bit for bit). Nothing else the pass reads can change between
 * steps without clearing counts_valid (positions, count, order) or
 * showing in the colliders' poses; the velocities can (ms_volume_adapt_to
 * _waves), so the packed copy of them is refreshed. */
int ms_volume_take_counted_pass(ms_volume *v)
{
    int ok = v->pass_ready && v->counts_valid && v->pass_ncol == v->ncolliders;
    v->pass_ready = 0;
    for (int c = 0; ok && c < v->ncolliders; ++c) {
        float now[13];
        collider_pose(v->colliders[c], now);
        ok = v->pass_col[c] == v->colliders[c] && !memcmp(now, v->pass_pose[c], sizeof now);
        for (int k = 0; ok && k < 3; ++k) {
            const float zero = 0.0f;
            ok = !memcmp(&v->col_jump[c][k], &zero, sizeof zero) &&
                 !memcmp(&v->col_vel[c][k], &now[3 + k], sizeof zero);
        }
    }
    if (ok) {
        ms_density_ctx ctx = {.v = v};
        ms_vpool_run(v->pool, pack_part, &ctx, v->n);
    }
    return ok;
}
