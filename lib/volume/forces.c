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
 * liquid up with its own pressure. Colliders add the pressure force of a
 * mirrored lattice and the eq. 15 field (collide.c).
 *
 * Each particle gathers over its 27 neighbour cells in a fixed order; no
 * sum is shared between particles, so any thread split gives the same bytes.
 * Pairs closer than eps (coincident particles, where r_vec/r has no
 * direction) get a direction from a hash of the two particle ids, opposite
 * for the two, so coincident particles are pushed apart, deterministically.
 */
#include <math.h>
#include <stdint.h>

#include "volume/volume_impl.h"

typedef struct forces_ctx {
    ms_volume *v;
} forces_ctx;

/* Particle i's sums over its neighbour list: real neighbours in lanes
 * (a fixed order the compiler may vectorise), then the wall images. */
typedef struct pair_sums {
    float px, py, pz; /* pressure: sum (p_i + p_j)/rho_j (h - r)^2 / r (x_i - x_j) */
    float vx, vy, vz; /* viscosity: sum (h - r)/rho_j (v_j - v_i) */
    float d;          /* sum (h - r)/rho_j, for the viscous bound */
} pair_sums;

static inline int padded(int n)
{
    return (n + MS_VOLUME_LANES - 1) / MS_VOLUME_LANES * MS_VOLUME_LANES;
}

static pair_sums sums_of(const ms_volume *v, const ms_nlist *lst, const ms_nlist *gst, int i)
{
    enum { L = MS_VOLUME_LANES };
    const float *restrict x = v->x, *restrict y = v->y, *restrict z = v->z;
    const float *restrict vx = v->vx, *restrict vy = v->vy, *restrict vz = v->vz;
    const float *restrict prs = v->prs, *restrict inv_rho = v->inv_rho;
    const int *restrict idx = lst->idx + v->nl_begin[i];
    const float *restrict r2s = lst->r2 + v->nl_begin[i];
    const int n = padded(v->nl_count[i]);
    const float h = v->K.h, eps = sqrtf(v->eps2);
    const float xi = x[i], yi = y[i], zi = z[i], vxi = vx[i], vyi = vy[i], vzi = vz[i];
    const float pi = prs[i];
    pair_sums s = {0, 0, 0, 0, 0, 0, 0};
    float spx[L] = {0}, spy[L] = {0}, spz[L] = {0};
    float svx[L] = {0}, svy[L] = {0}, svz[L] = {0}, sd[L] = {0};
    for (int k = 0; k < n; k += L)
        for (int l = 0; l < L; ++l) {
            const int j = idx[k + l]; /* padding: i itself at r = h, adds 0 */
            float dx = xi - x[j], dyy = yi - y[j], dzz = zi - z[j];
            float r = sqrtf(r2s[k + l]);
            float hr = h - r;
            hr = hr > 0.0f ? hr : 0.0f;
            float fv = inv_rho[j] * hr;
            float fp = (pi + prs[j]) * fv * hr / (r > eps ? r : eps);
            spx[l] += fp * dx;
            spy[l] += fp * dyy;
            spz[l] += fp * dzz;
            svx[l] += fv * (vx[j] - vxi);
            svy[l] += fv * (vy[j] - vyi);
            svz[l] += fv * (vz[j] - vzi);
            sd[l] += fv;
        }
    for (int l = 0; l < L; ++l) {
        s.px += spx[l];
        s.py += spy[l];
        s.pz += spz[l];
        s.vx += svx[l];
        s.vy += svy[l];
        s.vz += svz[l];
        s.d += sd[l];
    }
    if (v->gl_count[i] == 0)
        return s;
    /* wall images: the neighbour reflected across the walls of its image
     * bits (position and velocity), same pressure and density */
    const int *gidx = gst->idx + v->gl_begin[i];
    const float *gr2 = gst->r2 + v->gl_begin[i];
    const int gn = v->gl_count[i];
    float wall[3];
    ms_volume_walls_near(v, xi, yi, zi, wall);
    for (int k = 0; k < gn; ++k) {
        const unsigned f = (unsigned)gidx[k] >> MS_VOLUME_IMAGE_SHIFT;
        const int j = gidx[k] & ((1 << MS_VOLUME_IMAGE_SHIFT) - 1);
        float pj[3] = {x[j], y[j], z[j]}, uj[3] = {vx[j], vy[j], vz[j]};
        for (int a = 0; a < 3; ++a)
            if (f & (1u << a)) {
                pj[a] = 2.0f * wall[a] - pj[a];
                uj[a] = -uj[a];
            }
        float dx = xi - pj[0], dyy = yi - pj[1], dzz = zi - pj[2];
        float r = sqrtf(gr2[k]);
        float hr = h - r;
        hr = hr > 0.0f ? hr : 0.0f;
        float fv = inv_rho[j] * hr;
        float fp = (pi + prs[j]) * fv * hr / (r > eps ? r : eps);
        s.px += fp * dx;
        s.py += fp * dyy;
        s.pz += fp * dzz;
        s.vx += fv * (uj[0] - vxi);
        s.vy += fv * (uj[1] - vyi);
        s.vz += fv * (uj[2] - vzi);
        s.d += fv;
    }
    return s;
}

static void forces_part(void *ctxp, int part, int b, int e)
{
    forces_ctx *ctx = ctxp;
    ms_volume *v = ctx->v;
    const ms_nlist *lst = &v->lists[part], *gst = &v->ghosts[part];
    const float cp = 0.5f * v->press_scale * v->mass * v->K.spiky_grad; /* eq. 13 */
    const float cv = 0.5f * v->mass * v->K.visc_lap * v->desc.viscosity; /* eq. 14 */
    const float gx = v->desc.gravity[0], gy = v->desc.gravity[1], gz = v->desc.gravity[2];
    for (int i = b; i < e; ++i) {
        pair_sums s = sums_of(v, lst, gst, i);
        const float ri = v->inv_rho[i], pi = v->prs[i];
        const float pw = v->press_scale * pi * ri * ri; /* colliders: p_i / rho_i^2 */
        v->ax[i] = cp * ri * s.px + cv * ri * s.vx + pw * v->b_gx[i] + v->b_ax[i] + gx;
        v->ay[i] = cp * ri * s.py + cv * ri * s.vy + pw * v->b_gy[i] + v->b_ay[i] + gy;
        v->az[i] = cp * ri * s.pz + cv * ri * s.vz + pw * v->b_gz[i] + v->b_az[i] + gz;
        v->visc_rate[i] = cv * ri * s.d;
    }
}

static uint64_t mix64(uint64_t z)
{
    z += 0x9e3779b97f4a7c15ull;
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    return z ^ (z >> 31);
}

/* A unit vector for the pair (a, b), a != b: dir(a, b) = -dir(b, a). */
static void pair_direction(int a, int b, float u[3])
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
            if (r2s[k] >= v->eps2)
                continue;
            const int j = idx[k];
            float u[3];
            pair_direction(v->id[i], v->id[j], u);
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
