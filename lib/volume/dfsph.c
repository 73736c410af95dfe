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

#include "volume/volume_internal.h"

#if MS_VOLUME_HAVE_AVX512
#include <immintrin.h>

#include "volume/records_avx512.h"
#endif

enum { LANES = MS_VOLUME_LANES };
/* The AVX-512 pair loops prefetch their streamed per-pair data (the
 * neighbour indices, and the pair terms or r^2) MS_PREFETCH_ENTRIES
 * entries ahead (ms_prefetch_ahead, records_avx512.h): a sub-step's pair
 * terms (19 MB on the peer's scene) live in the shared cache, not the
 * core's, and the hardware prefetchers do not keep up (an error pass's
 * pair loop took 0.84 ms without, 0.63-0.70 ms with its data in L2).
 * Measured on the peer's scene's 0.3 s, thread CPU of the phases, three
 * alternated runs: the density solve 0.96-0.97x at 128, 256 and 512
 * entries (1024: no gain), the factors and divergence solve 0.97x with
 * the factors loop's too. Hints only: the same bits. */

/* The pair loops are inlined into each clone of dfsph_part, so they are
 * compiled for its instruction set. */
#if defined(__GNUC__)
#define MS_DFSPH_INLINE __attribute__((always_inline))
#else
#define MS_DFSPH_INLINE
#endif
enum { MIN_DENSITY_ITERATIONS = 2, MIN_DIVERGENCE_ITERATIONS = 1 };
#define WARM_FACTOR 0.5f
/* The density solve's momentum (the header): the share of a particle's
 * last update s carried into its next. */
#define DENSITY_MOMENTUM 0.3f

typedef enum { F_FACTORS, F_DENSITY_ERROR, F_DIVERGENCE_ERROR, F_APPLY, F_PRESSURE } pass_kind;

typedef struct dfsph_ctx {
    ms_volume *v;
    pass_kind kind;
    float dt;    /* s, the sub-step (density) or the error's scale (divergence) */
    float scale; /* F_APPLY: 1/dt (density) or 1 (divergence), 1/s or 1; warm_kick:
                       the last solve's s rescaled to this dt, (dt / dt_last)^2 */
    float warm;  /* warm_kick: dt / dt_last^2 m G, the factor of df_wx..z */
    int64_t err[MS_VOLUME_MAX_THREADS]; /* sum of e_i / rho0 (or dt e_i / rho0), 2^-32 units */
    /* F_FACTORS: the gradient moments of the particles inside the liquid
     * (2^-32 units) and their count; F_PRESSURE: the moment M, the weight
     * of this sub-step in the step's mean and whether the mean restarts */
    int64_t mom[MS_VOLUME_MAX_THREADS];
    int nmom[MS_VOLUME_MAX_THREADS];
    float moment, weight;
    int restart;
    float momentum; /* F_DENSITY_ERROR: DENSITY_MOMENTUM, 0 at a solve's first error pass */
} dfsph_ctx;

static inline int padded(int n)
{
    return (n + LANES - 1) / LANES * LANES;
}

/* Entry g of particle i's image list: particle j's position and velocity
 * mirrored as density.c and forces.c mirror them (velocity in the shape's
 * frame at a shape). */
static inline MS_DFSPH_INLINE void image_of(const ms_volume *v, int i, int g, const float wall[3],
                                            float pj[3], float uj[3])
{
    const unsigned f = (unsigned)g >> MS_VOLUME_IMAGE_SHIFT;
    const int j = g & ((1 << MS_VOLUME_IMAGE_SHIFT) - 1);
    pj[0] = v->x[j];
    pj[1] = v->y[j];
    pj[2] = v->z[j];
    uj[0] = v->vx[j];
    uj[1] = v->vy[j];
    uj[2] = v->vz[j];
    if (f == MS_VOLUME_IMAGE_SHAPE) {
        const float dd = v->c_d[i];
        const float nn[3] = {v->c_nx[i], v->c_ny[i], v->c_nz[i]};
        const float c[3] = {v->x[i] - dd * nn[0], v->y[i] - dd * nn[1], v->z[i] - dd * nn[2]};
        float sp = (pj[0] - c[0]) * nn[0] + (pj[1] - c[1]) * nn[1] + (pj[2] - c[2]) * nn[2];
        const float vs[3] = {v->c_vx[i], v->c_vy[i], v->c_vz[i]};
        float su = (uj[0] - vs[0]) * nn[0] + (uj[1] - vs[1]) * nn[1] + (uj[2] - vs[2]) * nn[2];
        for (int a = 0; a < 3; ++a) {
            pj[a] -= 2.0f * sp * nn[a];
            uj[a] -= 2.0f * su * nn[a];
        }
    } else {
        for (int a = 0; a < 3; ++a)
            if (f & (1u << a)) {
                pj[a] = 2.0f * wall[a] - pj[a];
                uj[a] = -uj[a];
            }
    }
}

/* The velocity half of image_of (the same operations): the passes after
 * the factors read the image's g and x_i - x_j' from v->df_img. */
static inline MS_DFSPH_INLINE void image_velocity(const ms_volume *v, int i, int g, float uj[3])
{
    const unsigned f = (unsigned)g >> MS_VOLUME_IMAGE_SHIFT;
    const int j = g & ((1 << MS_VOLUME_IMAGE_SHIFT) - 1);
    uj[0] = v->vx[j];
    uj[1] = v->vy[j];
    uj[2] = v->vz[j];
    if (f == MS_VOLUME_IMAGE_SHAPE) {
        const float nn[3] = {v->c_nx[i], v->c_ny[i], v->c_nz[i]};
        const float vs[3] = {v->c_vx[i], v->c_vy[i], v->c_vz[i]};
        float su = (uj[0] - vs[0]) * nn[0] + (uj[1] - vs[1]) * nn[1] + (uj[2] - vs[2]) * nn[2];
        for (int a = 0; a < 3; ++a)
            uj[a] -= 2.0f * su * nn[a];
    } else {
        for (int a = 0; a < 3; ++a)
            if (f & (1u << a))
                uj[a] = -uj[a];
    }
}

/* grad W_ij = -G g (x_i - x_j), G = 45/(pi h^6), g = (h - r)^2 / r: the
 * factor g of an entry at r^2 (0 at and beyond h; a coincident pair,
 * r <= eps, has no direction and gets 0 here: see coincident()). */
static inline float grad_factor(float r2, float h, float eps)
{
    float r = sqrtf(r2);
    float hr = h - r;
    hr = hr > 0.0f ? hr : 0.0f;
    return r > eps ? hr * hr / r : 0.0f;
}

/* Coincident pairs (r <= eps, which density.c counts): the lanes give them
 * no term, so particles at one point could never be pushed apart (300 at
 * one point fell as one lump, each sub-step's density solve at its cap of
 * 100 iterations over 90 000 pairs to no effect: 83 s for one second).
 * They take the limit of g (x_i - x_j) as r -> 0, h^2, along the pair's
 * direction from forces.c (as the weakly compressible laws' pressure
 * does). Entry k of i's list is coincident when this returns 1, with
 * w = h^2 dir(i, j). */
static inline int coincident(const ms_volume *v, int i, int j, float r2, float w[3])
{
    if (!(r2 <= v->eps2) || j == i)
        return 0;
    ms_volume_pair_direction(v->id[i], v->id[j], w);
    for (int a = 0; a < 3; ++a)
        w[a] *= v->K.h2;
    return 1;
}

static inline void mirror(const ms_volume *v, int i, unsigned f, float u[3])
{
    if (f == MS_VOLUME_IMAGE_SHAPE) {
        const float nn[3] = {v->c_nx[i], v->c_ny[i], v->c_nz[i]};
        float un = u[0] * nn[0] + u[1] * nn[1] + u[2] * nn[2];
        for (int a = 0; a < 3; ++a)
            u[a] -= 2.0f * un * nn[a];
    } else {
        for (int a = 0; a < 3; ++a)
            if (f & (1u << a))
                u[a] = -u[a];
    }
}

/* Particle i's share of its last total s in the warm start (see the
 * header): 0 at the surface, WARM_FACTOR inside. */
static inline float warm_share(const ms_volume *v, int i)
{
    return ms_volume_is_surface(v, i) ? 0.0f : WARM_FACTOR;
}

/* The Jacobi diagonal of particle i: how much rho*_i falls per unit of s_i
 * when i moves by -(s_i/dt) G_i (G_i = sum_k m grad W_ik over the real
 * neighbours and the images) and each real neighbour j answers with
 * +(s_i/dt) m grad W_ij (Bender & Koschier 2017, eq. 9):
 *     |G_i|^2 + sum_j |m grad W_ij|^2
 * An image moves as the mirror M of its particle: an image of i itself
 * adds -m (M G_i) . grad W_ii'; an image j' of a real neighbour j adds
 * m^2 (M grad W_ij) . grad W_ij' twice (j' follows j's answer, and j
 * answers to i's image in its own list at the same distance). Without
 * them a particle in a corner (seven images of itself) had its diagonal
 * underestimated several times over and a tank at rest blew up.
 * Returns sum_k g_ik r_ik^2 over the same entries: the trace of i's
 * gradient moment in units of 1 / (m G) (the pressure read-out's M).
 * Also sums the warm start's sum_k (w_i + w_k) g_ik (x_i - x_k) into
 * df_wx..z (w: df_sum, set by warm_weights; the header). */
#if MS_VOLUME_HAVE_AVX512
__attribute__((target("avx512f"))) static inline void factors_real_avx512(
    const float *pk, const int *idx, const float *r2s, int n, float h, float eps, float xi,
    float yi, float zi, float *cgx, float *cgy, float *cgz, float wi, float out[8]);
#endif

static inline MS_DFSPH_INLINE float factors_of(ms_volume *v, const ms_nlist *lst,
                                               const ms_nlist *gst, float *restrict cgx,
                                               float *restrict cgy, float *restrict cgz,
                                               float *restrict img, int i)
{
    const float *restrict x = v->x, *restrict y = v->y, *restrict z = v->z;
    const int *restrict idx = lst->idx + v->nl_begin[i];
    const float *restrict r2s = lst->r2 + v->nl_begin[i];
    const int n = padded(v->nl_count[i]);
    const float h = v->K.h, h2 = v->K.h2, eps = sqrtf(v->eps2);
    const float xi = x[i], yi = y[i], zi = z[i];
    cgx += v->nl_begin[i];
    cgy += v->nl_begin[i];
    cgz += v->nl_begin[i];
    const float *restrict w = v->df_sum; /* the warm start's s (warm_weights) */
    const float wi = w[i];
    float gx, gy, gz, q; /* in units of (m G)^2: grad W = -G g d */
    float mom;           /* sum_j g r^2: the gradient moment's trace */
    float ax, ay, az;    /* the warm start's sum */
#if MS_VOLUME_HAVE_AVX512
    if (v->isa == MS_VOLUME_ISA_AVX512) {
        float o[8];
        factors_real_avx512(v->pk, idx, r2s, n, h, eps, xi, yi, zi, cgx, cgy, cgz, wi, o);
        gx = o[0];
        gy = o[1];
        gz = o[2];
        q = o[3];
        mom = o[4];
        ax = o[5];
        ay = o[6];
        az = o[7];
    } else
#endif
    {
        float sx[LANES] = {0}, sy[LANES] = {0}, sz[LANES] = {0}, sq[LANES] = {0}, sm[LANES] = {0};
        float wx[LANES] = {0}, wy[LANES] = {0}, wz[LANES] = {0};
        for (int k = 0; k < n; k += LANES)
            for (int l = 0; l < LANES; ++l) {
                const int j = idx[k + l];
                float g = grad_factor(r2s[k + l], h, eps);
                const float dx = g * (xi - x[j]), dy = g * (yi - y[j]), dz = g * (zi - z[j]);
                cgx[k + l] = dx;
                cgy[k + l] = dy;
                cgz[k + l] = dz;
                sx[l] += dx;
                sy[l] += dy;
                sz[l] += dz;
                sq[l] += g * g * r2s[k + l];
                sm[l] += g * r2s[k + l];
                const float f = wi + w[j];
                wx[l] += f * dx;
                wy[l] += f * dy;
                wz[l] += f * dz;
            }
        gx = ms_lanes_sum(sx);
        gy = ms_lanes_sum(sy);
        gz = ms_lanes_sum(sz);
        q = ms_lanes_sum(sq);
        mom = ms_lanes_sum(sm);
        ax = ms_lanes_sum(wx);
        ay = ms_lanes_sum(wy);
        az = ms_lanes_sum(wz);
    }
    if (v->coincident > 0)
        for (int k = 0; k < v->nl_count[i]; ++k) {
            float u[3];
            if (coincident(v, i, idx[k], r2s[k], u)) {
                cgx[k] = u[0]; /* the cached pair term of the solves' passes */
                cgy[k] = u[1];
                cgz[k] = u[2];
                gx += u[0];
                gy += u[1];
                gz += u[2];
                q += h2 * h2;
                const float f = wi + w[idx[k]];
                ax += f * u[0];
                ay += f * u[1];
                az += f * u[2];
            }
        }
    float qm = 0.0f; /* the images' mirror terms */
    const int gn = v->gl_count[i];
    if (gn) {
        const int *gidx = gst->idx + v->gl_begin[i];
        const float *gr2 = gst->r2 + v->gl_begin[i];
        float wall[3];
        ms_volume_walls_near(v, xi, yi, zi, wall);
        float *c = img + 4 * (size_t)v->gl_begin[i];
        for (int k = 0; k < gn; ++k) {
            float pj[3], uj[3];
            image_of(v, i, gidx[k], wall, pj, uj);
            float g = grad_factor(gr2[k], h, eps);
            c[4 * k] = g; /* the image's terms for the solves' passes */
            c[4 * k + 1] = xi - pj[0];
            c[4 * k + 2] = yi - pj[1];
            c[4 * k + 3] = zi - pj[2];
            gx += g * (xi - pj[0]);
            gy += g * (yi - pj[1]);
            gz += g * (zi - pj[2]);
            /* the warm start's term as apply_of takes an image's */
            const float f = (wi + w[gidx[k] & ((1 << MS_VOLUME_IMAGE_SHIFT) - 1)]) * g;
            ax += f * c[4 * k + 1];
            ay += f * c[4 * k + 2];
            az += f * c[4 * k + 3];
            mom += g * (c[4 * k + 1] * c[4 * k + 1] + c[4 * k + 2] * c[4 * k + 2] +
                        c[4 * k + 3] * c[4 * k + 3]);
        }
        for (int k = 0; k < gn; ++k) {
            const int j = gidx[k] & ((1 << MS_VOLUME_IMAGE_SHIFT) - 1);
            const unsigned f = (unsigned)gidx[k] >> MS_VOLUME_IMAGE_SHIFT;
            /* the image's g and x_i - x_j' as the first loop stored them
             * (the same values; image_of and grad_factor once an image) */
            const float g = c[4 * k];
            const float d[3] = {c[4 * k + 1], c[4 * k + 2], c[4 * k + 3]};
            float u[3];
            float wt;
            if (j == i) { /* i's own image moves as M dv_i */
                u[0] = gx;
                u[1] = gy;
                u[2] = gz;
                wt = -1.0f;
            } else { /* j answers to i, and to i's image in j's list */
                u[0] = xi - x[j];
                u[1] = yi - y[j];
                u[2] = zi - z[j];
                float r2 = u[0] * u[0] + u[1] * u[1] + u[2] * u[2];
                if (!(r2 < h2))
                    continue;
                wt = 2.0f * grad_factor(r2, h, eps);
            }
            mirror(v, i, f, u);
            qm += wt * g * (u[0] * d[0] + u[1] * d[1] + u[2] * d[2]);
        }
    }
    const float mg = v->mass * v->K.spiky_grad;
    /* the mirror terms only ever stiffen the diagonal: a negative sum
     * (a particle pressed onto a wall, its own image nearly on it) would
     * shrink it towards 0 and blow the update up */
    float den = mg * mg * (gx * gx + gy * gy + gz * gz + q + (qm > 0.0f ? qm : 0.0f));
    v->df_inv_diag[i] = den > 0.0f ? 1.0f / den : 0.0f;
    v->df_wx[i] = ax;
    v->df_wy[i] = ay;
    v->df_wz[i] = az;
    return mom;
}

#if MS_VOLUME_HAVE_AVX512
/* The real-neighbour loops of divergence_sum and apply_of in AVX-512
 * intrinsics: the same operations per lane in the same order, no fused
 * multiply-adds, into the same lane accumulators, so the same bits as the
 * C loops. During the solves the packed copy v->pk holds (p, vx, vy, vz)
 * at floats 3..6 of each 8-float record (pk[3], the pressure slot, is not
 * read here: the update pass gathers s), so the 16 neighbours' data
 * are sixteen 16-byte loads and a 4 x 4 transpose in each 128-bit lane, in
 * place of gathers (AVX-512 gathers were 35 % of a 32k dam break's
 * sub-step; forces.c measured the same technique). Vector a[k] holds the
 * records of j[k], j[k+4], j[k+8], j[k+12], so that the transpose leaves
 * the lanes in order. Values are moved, never computed: the same bits
 * (ms_load_quads, records_avx512.h). */

/* s (the slot, unused), vx, vy, vz of the 16 neighbours j[0..15] */
__attribute__((target("avx512f"), always_inline)) static inline void load_svel(
    const float *pk, const int *restrict j, __m512 *s, __m512 *u, __m512 *w, __m512 *t)
{
    ms_load_quads(pk + 3, j, s, u, w, t);
}

/* factors_of's real-neighbour loop: the same operations per lane as the C
 * loop (IEEE square root and division, no fused multiply-adds), the
 * neighbours' positions as the 16-byte records x, y, z, p of v->pk (which
 * the density pass filled from the positions the solves use) in place of
 * three gathers: the same bits. The fourth float of each record holds the
 * warm start's s then (warm_weights), summed as the C loop sums w_j. */
__attribute__((target("avx512f"))) static inline void factors_real_avx512(
    const float *pk, const int *idx, const float *r2s, int n, float h, float eps, float xi,
    float yi, float zi, float *cgx, float *cgy, float *cgz, float wi, float out[8])
{
    const __m512 hv = _mm512_set1_ps(h), ev = _mm512_set1_ps(eps), zero = _mm512_setzero_ps();
    const __m512 xv = _mm512_set1_ps(xi), yv = _mm512_set1_ps(yi), zv = _mm512_set1_ps(zi);
    const __m512 wv = _mm512_set1_ps(wi);
    __m512 sx = zero, sy = zero, sz = zero, sq = zero, sm = zero, wx = zero, wy = zero, wz = zero;
    for (int k = 0; k < n; k += LANES) {
        __m512 xj, yj, zj, pj;
        ms_prefetch_ahead(r2s + k);
        ms_prefetch_ahead(idx + k);
        ms_load_quads(pk, idx + k, &xj, &yj, &zj, &pj);
        const __m512 r2 = _mm512_loadu_ps(r2s + k);
        const __m512 r = _mm512_sqrt_ps(r2);
        __m512 hr = _mm512_sub_ps(hv, r);
        hr = _mm512_maskz_mov_ps(_mm512_cmp_ps_mask(hr, zero, _CMP_GT_OQ), hr);
        const __m512 g =
            _mm512_maskz_div_ps(_mm512_cmp_ps_mask(r, ev, _CMP_GT_OQ), _mm512_mul_ps(hr, hr), r);
        const __m512 dx = _mm512_mul_ps(g, _mm512_sub_ps(xv, xj)),
                     dy = _mm512_mul_ps(g, _mm512_sub_ps(yv, yj)),
                     dz = _mm512_mul_ps(g, _mm512_sub_ps(zv, zj));
        _mm512_storeu_ps(cgx + k, dx);
        _mm512_storeu_ps(cgy + k, dy);
        _mm512_storeu_ps(cgz + k, dz);
        sx = _mm512_add_ps(sx, dx);
        sy = _mm512_add_ps(sy, dy);
        sz = _mm512_add_ps(sz, dz);
        sq = _mm512_add_ps(sq, _mm512_mul_ps(_mm512_mul_ps(g, g), r2));
        sm = _mm512_add_ps(sm, _mm512_mul_ps(g, r2));
        /* the warm start's w_j, the records' fourth float (warm_weights
         * put it there: no gather) */
        const __m512 f = _mm512_add_ps(wv, pj);
        wx = _mm512_add_ps(wx, _mm512_mul_ps(f, dx));
        wy = _mm512_add_ps(wy, _mm512_mul_ps(f, dy));
        wz = _mm512_add_ps(wz, _mm512_mul_ps(f, dz));
    }
    out[0] = ms_lanes_sum16(sx);
    out[1] = ms_lanes_sum16(sy);
    out[2] = ms_lanes_sum16(sz);
    out[3] = ms_lanes_sum16(sq);
    out[4] = ms_lanes_sum16(sm);
    out[5] = ms_lanes_sum16(wx);
    out[6] = ms_lanes_sum16(wy);
    out[7] = ms_lanes_sum16(wz);
}

__attribute__((target("avx512f"))) static inline float divergence_real_avx512(
    const ms_volume *v, const int *idx, const float *gx, const float *gy, const float *gz, int n,
    float ui, float wi, float ti)
{
    const __m512 u = _mm512_set1_ps(ui), w = _mm512_set1_ps(wi), t = _mm512_set1_ps(ti);
    __m512 a = _mm512_setzero_ps();
    for (int k = 0; k < n; k += LANES) {
        __m512 sj, uj, wj, tj;
        ms_prefetch_ahead(gx + k);
        ms_prefetch_ahead(gy + k);
        ms_prefetch_ahead(gz + k);
        ms_prefetch_ahead(idx + k);
        load_svel(v->pk, idx + k, &sj, &uj, &wj, &tj);
        __m512 d = _mm512_mul_ps(_mm512_sub_ps(u, uj), _mm512_loadu_ps(gx + k));
        d = _mm512_add_ps(d, _mm512_mul_ps(_mm512_sub_ps(w, wj), _mm512_loadu_ps(gy + k)));
        d = _mm512_add_ps(d, _mm512_mul_ps(_mm512_sub_ps(t, tj), _mm512_loadu_ps(gz + k)));
        a = _mm512_add_ps(a, d);
    }
    return ms_lanes_sum16(a);
}

/* The update pass reads only s of each neighbour: one gather of 16 floats
 * (from v->df_s, which pk[3] copies) in place of sixteen 16-byte record
 * loads and their transpose, three of whose four values it never used.
 * Measured in one process, the two alternating on the same state (fig1
 * under DFSPH, 2500 update passes): 0.88x the time of
 * the record loads. Values are moved, never computed: the same bits.
 * Inline, so that GCC inlines it into dfsph_part's AVX-512 clone (it
 * cannot into the others), which is flattened (below). */
__attribute__((target("avx512f"))) static inline void apply_real_avx512(
    const float *s, const int *idx, const float *gx, const float *gy, const float *gz, int n,
    float si, float out[3])
{
    const __m512 sv = _mm512_set1_ps(si);
    __m512 a = _mm512_setzero_ps(), b = a, c = a;
    for (int k = 0; k < n; k += LANES) {
        ms_prefetch_ahead(gx + k);
        ms_prefetch_ahead(gy + k);
        ms_prefetch_ahead(gz + k);
        ms_prefetch_ahead(idx + k);
        const __m512 sj = _mm512_i32gather_ps(_mm512_loadu_si512(idx + k), s, 4);
        const __m512 f = _mm512_add_ps(sv, sj);
        a = _mm512_add_ps(a, _mm512_mul_ps(f, _mm512_loadu_ps(gx + k)));
        b = _mm512_add_ps(b, _mm512_mul_ps(f, _mm512_loadu_ps(gy + k)));
        c = _mm512_add_ps(c, _mm512_mul_ps(f, _mm512_loadu_ps(gz + k)));
    }
    out[0] = ms_lanes_sum16(a);
    out[1] = ms_lanes_sum16(b);
    out[2] = ms_lanes_sum16(c);
}
#endif

/* sum_j (v_i - v_j) . (x_i - x_j) g_ij over real neighbours and images:
 * D rho_i/Dt = -m G times it. */
static inline MS_DFSPH_INLINE float divergence_sum(const ms_volume *v, const ms_nlist *lst,
                                                   const ms_nlist *gst, const float *restrict cgx,
                                                   const float *restrict cgy,
                                                   const float *restrict cgz,
                                                   const float *restrict img, int i)
{
    const float *restrict vx = v->vx, *restrict vy = v->vy, *restrict vz = v->vz;
    const int *restrict idx = lst->idx + v->nl_begin[i];
    const int n = padded(v->nl_count[i]);
    const float ui = vx[i], wi = vy[i], ti = vz[i];
    cgx += v->nl_begin[i];
    cgy += v->nl_begin[i];
    cgz += v->nl_begin[i];
    float s;
#if MS_VOLUME_HAVE_AVX512
    if (v->isa == MS_VOLUME_ISA_AVX512)
        s = divergence_real_avx512(v, idx, cgx, cgy, cgz, n, ui, wi, ti);
    else
#endif
    {
        float acc[LANES] = {0};
        for (int k = 0; k < n; k += LANES)
            for (int l = 0; l < LANES; ++l) {
                const int j = idx[k + l];
                acc[l] += (ui - vx[j]) * cgx[k + l] + (wi - vy[j]) * cgy[k + l] +
                          (ti - vz[j]) * cgz[k + l];
            }
        s = ms_lanes_sum(acc);
    }
    const int gn = v->gl_count[i];
    if (gn) {
        const int *gidx = gst->idx + v->gl_begin[i];
        const float *c = img + 4 * (size_t)v->gl_begin[i];
        for (int k = 0; k < gn; ++k) {
            float uj[3];
            image_velocity(v, i, gidx[k], uj);
            s += c[4 * k] * ((ui - uj[0]) * c[4 * k + 1] + (wi - uj[1]) * c[4 * k + 2] +
                             (ti - uj[2]) * c[4 * k + 3]);
        }
    }
    return s;
}

/* v_i = (nx, ny, nz), an update of the pressure solve or the warm start.
 * The pressure makes no particle faster than the sound speed (or than it
 * was): a liquid of sound speed c0 expands from a compression at about
 * c0, never faster. Measured: without it a box packed at twice rest
 * density (every particle's target out of reach in one sub-step) reached
 * 150 m/s, then non-finite velocities; with it the kinetic energy stays
 * below the elastic energy of the compression. Only binds far from any
 * state the shipped scenes reach. */
static inline void set_capped(ms_volume *v, int i, float nx, float ny, float nz)
{
    const float ux = v->vx[i], uy = v->vy[i], uz = v->vz[i];
    const float n2 = nx * nx + ny * ny + nz * nz, o2 = ux * ux + uy * uy + uz * uz;
    const float lim2 = o2 > v->c0 * v->c0 ? o2 : v->c0 * v->c0;
    if (n2 > lim2) {
        const float f = sqrtf(lim2 / n2);
        nx *= f;
        ny *= f;
        nz *= f;
    }
    v->vx[i] = nx;
    v->vy[i] = ny;
    v->vz[i] = nz;
}

/* i's velocity into the packed copy the AVX-512 error loops read (floats
 * 4..6 of its record) */
static inline void pack_velocity(ms_volume *v, int i)
{
    float *pk = v->pk + 8 * (size_t)i;
    pk[4] = v->vx[i];
    pk[5] = v->vy[i];
    pk[6] = v->vz[i];
}

/* v_i += scale m G sum_j (s_i + s_j) g_ij (x_i - x_j): the pressure term. */
static inline MS_DFSPH_INLINE void apply_of(ms_volume *v, const ms_nlist *lst, const ms_nlist *gst,
                                            const float *restrict cgx, const float *restrict cgy,
                                            const float *restrict cgz, const float *restrict img,
                                            int i, float scale)
{
    const float *restrict s = v->df_s;
    const int *restrict idx = lst->idx + v->nl_begin[i];
    const int n = padded(v->nl_count[i]);
    const float si = s[i];
    cgx += v->nl_begin[i];
    cgy += v->nl_begin[i];
    cgz += v->nl_begin[i];
    float sum[3];
#if MS_VOLUME_HAVE_AVX512
    if (v->isa == MS_VOLUME_ISA_AVX512)
        apply_real_avx512(s, idx, cgx, cgy, cgz, n, si, sum);
    else
#endif
    {
        float ax[LANES] = {0}, ay[LANES] = {0}, az[LANES] = {0};
        for (int k = 0; k < n; k += LANES)
            for (int l = 0; l < LANES; ++l) {
                const float f = si + s[idx[k + l]];
                ax[l] += f * cgx[k + l];
                ay[l] += f * cgy[k + l];
                az[l] += f * cgz[k + l];
            }
        sum[0] = ms_lanes_sum(ax);
        sum[1] = ms_lanes_sum(ay);
        sum[2] = ms_lanes_sum(az);
    }
    float sx = sum[0], sy = sum[1], sz = sum[2];
    const int gn = v->gl_count[i];
    if (gn) {
        const int *gidx = gst->idx + v->gl_begin[i];
        const float *c = img + 4 * (size_t)v->gl_begin[i];
        for (int k = 0; k < gn; ++k) {
            const int j = gidx[k] & ((1 << MS_VOLUME_IMAGE_SHIFT) - 1);
            float sb = si + s[j];
            float f = sb * c[4 * k];
            sx += f * c[4 * k + 1];
            sy += f * c[4 * k + 2];
            sz += f * c[4 * k + 3];
        }
    }
    const float c = scale * v->mass * v->K.spiky_grad;
    set_capped(v, i, v->vx[i] + c * sx, v->vy[i] + c * sy, v->vz[i] + c * sz);
    /* the running total of s, and the new velocity into the packed copy
     * the AVX-512 error loops read: no pass of an update reads pk (the
     * update gathers s from df_s), so i's record may change under it:
     * one per-particle pass fewer an iteration */
    v->df_sum[i] += si;
    pack_velocity(v, i);
}

/* e / rho0 in units of 2^-32, clamped to [0, 64] (NaN counts as 64) so
 * that 2^24 particles cannot overflow the sum. */
static inline int64_t quantise(float e_rel)
{
    float c = e_rel < 64.0f ? e_rel : 64.0f;
    c = c > 0.0f ? c : 0.0f;
    return (int64_t)((double)c * 4294967296.0);
}

/* The divergence error of particle i (D rho_i/Dt, 0 at the surface and
 * where the liquid expands) into its iterate s_i; returns dt e_i / rho0
 * quantised. */
static inline MS_DFSPH_INLINE int64_t divergence_error_of(ms_volume *v, const ms_nlist *lst,
                                                          const ms_nlist *gst, const float *cgx,
                                                          const float *cgy, const float *cgz,
                                                          const float *restrict img, int i,
                                                          float dt)
{
    float ei = 0.0f;
    if (!ms_volume_is_surface(v, i)) {
        const float mg = v->mass * v->K.spiky_grad;
        ei = -mg * divergence_sum(v, lst, gst, cgx, cgy, cgz, img, i); /* D rho_i/Dt */
        ei = ei > 0.0f ? ei : 0.0f;
    }
    v->df_s[i] = ei * v->df_inv_diag[i];
    return quantise(dt * ei / v->desc.rest_density);
}

/* Built for AVX-512, AVX2 and the baseline as density.c's weight_sum: the
 * lanes loops vectorise (gathers), with no fused multiply-adds under
 * -std=c11 and IEEE sqrt and division, so every clone gives the same bits.
 * Flattened: the AVX-512 clone inlines the AVX-512 pair
 * loops (the other clones cannot, and call them), so no call per
 * particle and the loops' constants stay in registers; measured on the
 * peer's scene (thread CPU of the phases, four alternated runs, against
 * the update loop alone inlined): the factors and divergence solve 0.945x,
 * the density solve 0.98x; the same bits. */
#if MS_VOLUME_HAVE_AVX512
__attribute__((target_clones("avx512f", "avx2", "default"), flatten))
#endif
static void
dfsph_part(void *ctxp, int part, int b, int e)
{
    dfsph_ctx *ctx = ctxp;
    ms_volume *v = ctx->v;
    const ms_nlist *lst = &v->lists[part], *gst = &v->ghosts[part];
    float *cgx = v->df_grad[part], *cgy = cgx + v->df_grad_cap[part],
          *cgz = cgy + v->df_grad_cap[part];
    float *img = v->df_img[part];
    const float rho0 = v->desc.rest_density, mg = v->mass * v->K.spiky_grad, dt = ctx->dt;
    int64_t err = 0;
    switch (ctx->kind) {
    case F_FACTORS: { /* and the divergence solve's first error, while i's terms are hot */
        /* M_i = V G sum_k g r^2 / 3, V = m / rho0: i's gradient moment
         * (the trace's third), as volume.c's lattice M */
        const float mvol = mg / (3.0f * rho0);
        int64_t mom = 0;
        int nmom = 0;
        for (int i = b; i < e; ++i) {
            const float mi = mvol * factors_of(v, lst, gst, cgx, cgy, cgz, img, i);
            err += divergence_error_of(v, lst, gst, cgx, cgy, cgz, img, i, dt);
            if (!ms_volume_is_surface(v, i)) {
                mom += quantise(mi);
                nmom++;
            }
        }
        ctx->mom[part] = mom;
        ctx->nmom[part] = nmom;
        break;
    }
    case F_DENSITY_ERROR: {
        /* The compression one sub-step may remove, rho0 c0 dt / h: a
         * compressed liquid of sound speed c0 relaxes at about c0, one
         * kernel radius in h / c0. Without it a sub-step tries to remove
         * all of it at once, whatever dt: 300 particles at one point (179
         * times rest density) left at 136 m/s with 3800 J; with it, at
         * most 10 m/s and 65 J (the ideal-gas law: 39 m/s, 1278 J). It
         * only binds when rho/rho0 - 1 > c0 dt / h, near 1 for the
         * shipped scenes' sub-steps, so never in their flows. */
        const float cap = rho0 * v->c0 * dt / v->K.h;
        for (int i = b; i < e; ++i) {
            /* rho*_i - rho0 = rho_i - rho0 + dt D rho_i/Dt */
            float ci = v->rho[i] - rho0;
            ci = ci < cap ? ci : cap;
            float ei = ci - dt * mg * divergence_sum(v, lst, gst, cgx, cgy, cgz, img, i);
            ei = ei > 0.0f ? ei : 0.0f;
            /* the Jacobi update plus, while i is still compressed, the
             * momentum share of its last one (df_s still holds it; both
             * >= 0: the total only grows; the header) */
            v->df_s[i] = ei > 0.0f ? ei * v->df_inv_diag[i] + ctx->momentum * v->df_s[i] : 0.0f;
            err += quantise(ei / rho0); /* compression only: quantise clamps at 0 */
        }
        break;
    }
    case F_DIVERGENCE_ERROR:
        for (int i = b; i < e; ++i)
            err += divergence_error_of(v, lst, gst, cgx, cgy, cgz, img, i, dt);
        break;
    case F_APPLY:
        for (int i = b; i < e; ++i)
            apply_of(v, lst, gst, cgx, cgy, cgz, img, i, ctx->scale);
        break;
    case F_PRESSURE: {
        /* the pressure the liquid exerts (eq. 13's convention): both
         * solves' impulses of this sub-step as a pressure over it, its
         * mean over the step's sub-steps so far into prs (see the header) */
        const float inv_dt2 = 1.0f / (dt * dt), inv_dt = 1.0f / dt, w = ctx->weight;
        for (int i = b; i < e; ++i) {
            const float p = ctx->moment * (v->df_sum[i] * inv_dt2 + v->df_div_sum[i] * inv_dt) *
                            v->rho[i] * v->rho[i];
            float *mean = &v->df_pmean[v->id[i]];
            *mean = ctx->restart ? p : *mean + w * (p - *mean);
            v->prs[i] = *mean;
            v->pk[8 * (size_t)i + 3] = v->prs[i];
            v->df_warm[v->id[i]] = v->df_sum[i]; /* the next sub-step's start */
        }
        break;
    }
    }
    ctx->err[part] = err;
}

/* One pass of kind over all particles; the average error of an error pass. */
static float run(ms_volume *v, dfsph_ctx *ctx, pass_kind kind)
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
    ms_volume *v = ((dfsph_ctx *)ctxp)->v;
    for (int i = b; i < e; ++i)
        v->df_div_sum[i] = v->df_sum[i];
}

/* Before the factors pass: each particle's warm-start s at the last
 * sub-step's dt (its share of the last total s; 0 with no warm start)
 * into df_sum, which the factors pass reads (the divergence solve
 * zeroes it after), and into the packed copy's pressure slot, which the
 * AVX-512 factors loop loads with each neighbour's position (the density
 * pass wrote prs there and unpack_s writes it back before the force pass:
 * nothing reads the slot in between). */
static void warm_weights(void *ctxp, int part, int b, int e)
{
    (void)part;
    ms_volume *v = ((dfsph_ctx *)ctxp)->v;
    for (int i = b; i < e; ++i) {
        v->df_sum[i] = v->df_warm_on ? warm_share(v, i) * v->df_warm[v->id[i]] : 0.0f;
        v->pk[8 * (size_t)i + 3] = v->df_sum[i]; /* until unpack_s: the AVX-512 loop's */
    }
}

/* The warm start, after the kick (the header): v += dt / dt_last^2 m G
 * times the factors pass's sum, capped as an update (apply_of); the
 * density solve's running total starts at the warm s rescaled to this
 * dt; the packed copy's velocities for the AVX-512 loops. */
static void warm_kick(void *ctxp, int part, int b, int e)
{
    (void)part;
    const dfsph_ctx *ctx = ctxp;
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
    ms_volume *v = ((dfsph_ctx *)ctxp)->v;
    for (int i = b; i < e; ++i)
        v->df_sum[i] = 0.0f;
}

/* The packed copy's pressure slot set to prs for the force pass after the
 * divergence solve: the factors pass read the warm start's s there
 * (warm_weights). */
static void unpack_s(void *ctxp, int part, int b, int e)
{
    (void)part;
    ms_volume *v = ((dfsph_ctx *)ctxp)->v;
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
static int solve(ms_volume *v, dfsph_ctx *ctx, pass_kind error, float eta, int least, int cap,
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
    dfsph_ctx ctx = {.v = v, .dt = dt_scale, .scale = 1.0f};
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
    dfsph_ctx ctx = {.v = v, .dt = dt, .scale = 1.0f / dt};
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
