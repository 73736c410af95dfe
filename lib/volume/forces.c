/* The internal forces of eqs. 13 and 14, as accelerations a_i = f_i / rho_i
 * (Mueller et al. 2003), plus gravity:
 *
 *   f_i^press = - kappa sum_j m (p_i + p_j) / (2 rho_j) grad W_press(x_i - x_j)   (eq. 13)
 *   f_i^visc  =   mu sum_j m (v_j - v_i) / (2 rho_j) lap W_visc(x_i - x_j)  (eq. 14)
 *
 * with grad W_press = -45/(pi h^6) (h - r)^2 r_vec/r (from eq. 11) and
 * lap W_visc = 45/(pi h^6) (h - r) (from eq. 12). The paper prints eq. 14
 * with a leading minus sign; since lap W_visc >= 0 that would push each
 * particle's velocity away from its neighbours' (anti-diffusion, unstable
 * at once), so the sign here is Mueller et al.'s. The paper's factor 1/2 is
 * kept, so mu means what it means in the paper: the continuum limit of
 * the sum is mu/2 lap v (the liquid's dynamic viscosity is mu/2).
 *
 * kappa = 2/M. The paper's symmetrisation (p_i + p_j)/2 halves the
 * continuum limit of the pressure force (sum_j m/rho_j p_i grad W is ~0,
 * sum_j m/rho_j p_j grad W is grad p, eq. 10), and the discrete first
 * moment M of the spiky gradient on the particle lattice (0.78 at h = 2
 * spacing) scales it again; measured, a settled tank held p = 2.58 rho0 g d
 * with eq. 13 as printed. kappa makes the force -grad p / rho, so the
 * pressure law's p is the pressure the liquid exerts (the hydrostatic
 * test), and sqrt(dp/drho) is its sound speed. The form of eq. 13 and
 * its symmetry in i and j are kept. Divided by rho_i, both
 * pair terms are symmetric in i and j: momentum is conserved pair by pair.
 *
 * A particle near the domain's walls also sums over the wall images of its
 * neighbours (density.c): their positions and velocities reflected, the
 * same pressure and density, so a wall is frictionless and holds the
 * liquid up with its own pressure; a particle at a shape collider likewise
 * over the images across the shape's tangent plane (velocities mirrored in
 * the shape's frame, so a moving shape pushes). The walls and colliders
 * add the eq. 15 field (collide.c).
 *
 * Each particle gathers over its 27 neighbour cells in a fixed order; no
 * sum is shared between particles, so any thread split gives the same bytes.
 * Pairs closer than eps (coincident particles, where r_vec/r has no
 * direction) get a direction from a hash of the two particle ids, opposite
 * for the two, so coincident particles are pushed apart, deterministically.
 */
#include <math.h>
#include <stdint.h>
#include <string.h>

#include "volume/passes.h"

typedef struct forces_ctx {
    ms_volume *v;
} forces_ctx;

/* The pair sums of a part's particles: the lane pass of the volume's
 * path (passes.c). */
static void forces_part(void *ctxp, int part, int b, int e)
{
    forces_ctx *ctx = ctxp;
    ms_volume_passes_of(ctx->v->isa)->forces(ctx->v, part, b, e);
}

static uint64_t mix64(uint64_t z)
{
    z += 0x9e3779b97f4a7c15ull;
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    return z ^ (z >> 31);
}

/* A unit vector for the pair (a, b), a != b: dir(a, b) = -dir(b, a).
 * Shared with dfsph.c (volume_internal.h). */
void ms_volume_pair_direction(int a, int b, float u[3])
{
    uint32_t lo = (uint32_t)(a < b ? a : b), hi = (uint32_t)(a < b ? b : a);
    uint64_t hsh = mix64(((uint64_t)lo << 32) | hi);
    double c[3], l2 = 0.0;
    for (int k = 0; k < 3; ++k) {
        c[k] = (double)((hsh >> (21 * k)) & 0x1fffff) / 1048575.5 - 1.0;
        l2 += c[k] * c[k];
    }
    if (l2 < 1e-6) {
        c[0] = 1.0;
        c[1] = c[2] = 0.0;
        l2 = 1.0;
    }
    double s = (a < b ? 1.0 : -1.0) / sqrt(l2);
    for (int k = 0; k < 3; ++k)
        u[k] = (float)(c[k] * s);
}

/* The pressure term of coincident pairs (r < eps), with r_vec / r taken
 * from pair_direction. Rare: only runs when the density pass found some. */
static void coincident_part(void *ctxp, int part, int b, int e)
{
    forces_ctx *ctx = ctxp;
    ms_volume *v = ctx->v;
    const ms_nlist *lst = &v->lists[part];
    const float h = v->K.h, cp = 0.5f * v->press_scale * v->mass * v->K.spiky_grad;
    for (int i = b; i < e; ++i) {
        const int *idx = lst->idx + v->nl_begin[i];
        const float *r2s = lst->r2 + v->nl_begin[i];
        float s[3] = {0.0f, 0.0f, 0.0f};
        int any = 0;
        for (int k = 0; k < v->nl_count[i]; ++k) {
            const int j = idx[k];
            if (r2s[k] >= v->eps2 || j == i)
                continue;
            float u[3];
            ms_volume_pair_direction(v->id[i], v->id[j], u);
            float fp = (v->prs[i] + v->prs[j]) * v->inv_rho[j] * h * h;
            for (int a = 0; a < 3; ++a)
                s[a] += fp * u[a];
            any = 1;
        }
        if (any) {
            float ri = cp * v->inv_rho[i];
            v->ax[i] += ri * s[0];
            v->ay[i] += ri * s[1];
            v->az[i] += ri * s[2];
        }
    }
}

void ms_volume_forces(ms_volume *v)
{
    forces_ctx ctx = {.v = v};
    ms_vpool_run(v->pool, forces_part, &ctx, v->n);
    if (v->coincident > 0)
        ms_vpool_run(v->pool, coincident_part, &ctx, v->n);
}
