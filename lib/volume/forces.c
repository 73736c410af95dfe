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

#include "volume/volume_internal.h"

#if MS_VOLUME_HAVE_AVX512
#include <immintrin.h>

#include "volume/records_avx512.h"
#endif

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

#if MS_VOLUME_HAVE_AVX512
/* The 8-float records pk[8 j] (x, y, z, p, vx, vy, vz, 1/rho) of the 16
 * particles j[0..16) as eight vectors of 16 lanes (lane l: particle
 * j[l], vector f: field f): sixteen 32-byte loads and an 8 x 8 transpose
 * in each 256-bit half, in place of eight 64-bit gathers (measured on a
 * Zen 4 CPU, the force pass's share of a 32k
 * sub-step went from 30 % to 20 %; with arrays in place of the written-out
 * temporaries GCC spilled them to the stack and there was no gain).
 * Vector a[k] holds the records of j[k] | j[k+4] (k < 4) or j[k+4] |
 * j[k+8] (k >= 4), so that the last lane shuffle puts the lanes in order.
 * Values are moved, never computed: the same bits as the gathers. */
__attribute__((target("avx512f,avx512dq"), always_inline)) static inline __m512 record_pair(
    const float *pk, int lo, int hi)
{
    return _mm512_insertf32x8(_mm512_castps256_ps512(_mm256_loadu_ps(pk + 8 * (size_t)lo)),
                              _mm256_loadu_ps(pk + 8 * (size_t)hi), 1);
}

/* Written out (no arrays): with arrays GCC kept the vectors on the stack. */
#define TRANSPOSE4(a0, a1, a2, a3, s0, s1, s2, s3)                                       \
    do {                                                                                 \
        const __m512 t0_ = _mm512_unpacklo_ps(a0, a1), t1_ = _mm512_unpackhi_ps(a0, a1); \
        const __m512 t2_ = _mm512_unpacklo_ps(a2, a3), t3_ = _mm512_unpackhi_ps(a2, a3); \
        s0 = _mm512_shuffle_ps(t0_, t2_, 0x44);                                          \
        s1 = _mm512_shuffle_ps(t0_, t2_, 0xee);                                          \
        s2 = _mm512_shuffle_ps(t1_, t3_, 0x44);                                          \
        s3 = _mm512_shuffle_ps(t1_, t3_, 0xee);                                          \
    } while (0)

__attribute__((target("avx512f,avx512dq"), always_inline)) static inline void load_records(
    const float *pk, const int *restrict j, __m512 *o0, __m512 *o1, __m512 *o2, __m512 *o3,
    __m512 *o4, __m512 *o5, __m512 *o6, __m512 *o7)
{
    const __m512 a0 = record_pair(pk, j[0], j[4]), a1 = record_pair(pk, j[1], j[5]);
    const __m512 a2 = record_pair(pk, j[2], j[6]), a3 = record_pair(pk, j[3], j[7]);
    const __m512 a4 = record_pair(pk, j[8], j[12]), a5 = record_pair(pk, j[9], j[13]);
    const __m512 a6 = record_pair(pk, j[10], j[14]), a7 = record_pair(pk, j[11], j[15]);
    __m512 s0, s1, s2, s3, s4, s5, s6, s7;
    TRANSPOSE4(a0, a1, a2, a3, s0, s1, s2, s3);
    TRANSPOSE4(a4, a5, a6, a7, s4, s5, s6, s7);
    *o0 = _mm512_shuffle_f32x4(s0, s4, 0x88);
    *o4 = _mm512_shuffle_f32x4(s0, s4, 0xdd);
    *o1 = _mm512_shuffle_f32x4(s1, s5, 0x88);
    *o5 = _mm512_shuffle_f32x4(s1, s5, 0xdd);
    *o2 = _mm512_shuffle_f32x4(s2, s6, 0x88);
    *o6 = _mm512_shuffle_f32x4(s2, s6, 0xdd);
    *o3 = _mm512_shuffle_f32x4(s3, s7, 0x88);
    *o7 = _mm512_shuffle_f32x4(s3, s7, 0xdd);
}
#undef TRANSPOSE4

#endif

/* Each particle's seven sums are 16 lane
 * accumulators each; entry k of its real run goes to lane k % 16, then
 * entry k of its image run (both runs padded with zero terms) to lane
 * k % 16, and the lanes are summed once in ms_lanes_sum's order. Adding
 * the images one by one to the real run's lane sums instead is a serial
 * chain of 7 scalar adds an image through a store of the vector terms:
 * this order makes a fig1 frame about 2 % and a fig4c_x10 frame about 3 %
 * faster (volume_ab, one process). */
typedef struct pair_lanes {
    float px[16], py[16], pz[16], vx[16], vy[16], vz[16], d[16];
} pair_lanes;

static pair_sums lanes_sum(const pair_lanes *a)
{
    pair_sums s = {ms_lanes_sum(a->px), ms_lanes_sum(a->py), ms_lanes_sum(a->pz),
                   ms_lanes_sum(a->vx), ms_lanes_sum(a->vy), ms_lanes_sum(a->vz),
                   ms_lanes_sum(a->d)};
    return s;
}

#if MS_VOLUME_HAVE_AVX512
/* The seven lane accumulators of sums_avx512, named (no array): with
 * a[7] and loops over its index GCC kept them on the stack once the pass
 * was flattened, and the image terms added to them through memory. */
typedef struct lanes7 {
    __m512 px, py, pz, vx, vy, vz, d;
} lanes7;

/* An image's position p and velocity u along axis k: reflected (2 wall - p,
 * a sign flip of u) in the lanes whose image bits f have bit k. */
__attribute__((target("avx512f,avx512dq"), always_inline)) static inline void reflect_axis(
    __m512i f, int k, float wall, __m512 *p, __m512 *u)
{
    const __mmask16 m = _mm512_test_epi32_mask(f, _mm512_set1_epi32(1 << k));
    *p = _mm512_mask_sub_ps(*p, m, _mm512_set1_ps(2.0f * wall), *p);
    *u = _mm512_castsi512_ps(_mm512_mask_xor_epi32(
        _mm512_castps_si512(*u), m, _mm512_castps_si512(*u), _mm512_set1_epi32((int)0x80000000u)));
}

/* The wall-image terms of entries [k, k + 16) of the image list (no shape
 * images), in AVX-512: per entry the same operations as the C loop
 * (reflection as 2 wall - x and a sign flip, IEEE sqrt and division, no
 * fused multiply-adds), so the same seven terms, bit for bit, added to
 * the lane accumulators a (entry k + l to lane l, as the C loop). */
__attribute__((target("avx512f,avx512dq"), always_inline)) static inline void image_terms_avx512(
    const ms_volume *v, const int *restrict gidx, const float *restrict gr2, int i,
    const float wall[3], int pressure, lanes7 *a)
{
    const float *pi8 = v->pk + 8 * (size_t)i;
    const __m512 zero = _mm512_setzero_ps(), h = _mm512_set1_ps(v->K.h);
    const __m512 eps = _mm512_set1_ps(sqrtf(v->eps2)), pi = _mm512_set1_ps(pi8[3]);
    const __m512i g = _mm512_loadu_si512((const void *)gidx);
    const __m512i f = _mm512_srli_epi32(g, MS_VOLUME_IMAGE_SHIFT);
    int j[16];
    _mm512_storeu_si512((void *)j,
                        _mm512_and_si512(g, _mm512_set1_epi32((1 << MS_VOLUME_IMAGE_SHIFT) - 1)));
    __m512 px, py, pz, pj, ux, uy, uz, irj;
    load_records(v->pk, j, &px, &py, &pz, &pj, &ux, &uy, &uz, &irj);
    reflect_axis(f, 0, wall[0], &px, &ux);
    reflect_axis(f, 1, wall[1], &py, &uy);
    reflect_axis(f, 2, wall[2], &pz, &uz);
    __m512 r = _mm512_sqrt_ps(_mm512_loadu_ps(gr2));
    __m512 hr = _mm512_max_ps(_mm512_sub_ps(h, r), zero);
    __m512 fv = _mm512_mul_ps(irj, hr);
    if (pressure) { /* see sums_avx512 */
        __m512 fp = _mm512_div_ps(_mm512_mul_ps(_mm512_mul_ps(_mm512_add_ps(pi, pj), fv), hr),
                                  _mm512_max_ps(r, eps));
        a->px = _mm512_add_ps(a->px, _mm512_mul_ps(fp, _mm512_sub_ps(_mm512_set1_ps(pi8[0]), px)));
        a->py = _mm512_add_ps(a->py, _mm512_mul_ps(fp, _mm512_sub_ps(_mm512_set1_ps(pi8[1]), py)));
        a->pz = _mm512_add_ps(a->pz, _mm512_mul_ps(fp, _mm512_sub_ps(_mm512_set1_ps(pi8[2]), pz)));
    }
    a->vx = _mm512_add_ps(a->vx, _mm512_mul_ps(fv, _mm512_sub_ps(ux, _mm512_set1_ps(pi8[4]))));
    a->vy = _mm512_add_ps(a->vy, _mm512_mul_ps(fv, _mm512_sub_ps(uy, _mm512_set1_ps(pi8[5]))));
    a->vz = _mm512_add_ps(a->vz, _mm512_mul_ps(fv, _mm512_sub_ps(uz, _mm512_set1_ps(pi8[6]))));
    a->d = _mm512_add_ps(a->d, fv);
}

/* The sums of sums_of in AVX-512 intrinsics: the same operations per lane
 * in the same order as the C loops (no fused multiply-adds, IEEE sqrt and
 * division) and the same lane sum, so the same bits. The neighbours' data
 * come from the packed copy v->pk (x, y, z, p, vx, vy, vz, 1/rho per
 * particle), sixteen records at a time by load_records. The wall images'
 * gn entries (padded to 16) are added here when gn > 0; with out, the
 * lanes are stored there instead of summed (the C loop then adds shape
 * images).
 *
 * Under DFSPH (pressure 0) the pressure terms are skipped: the law's p is
 * 0 in this pass (ms_volume_pressure; the solves of dfsph.c act on the
 * velocities), so each term fp (x_i - x_j) is +0 or -0 and the lanes stay
 * +0 (they start at +0, and +0 + -0 = +0): skipping them gives the same
 * bits, without the pass's only division, and the real neighbours' loop
 * loads the records' velocity halves alone (ms_load_quads: 16-byte
 * loads, a 4 x 4 transpose instead of 8 x 8).
 * The C loops still compute them (the same +0). */
__attribute__((target("avx512f,avx512dq"), always_inline)) static inline pair_sums sums_avx512(
    const ms_volume *v, const int *restrict idx, const float *restrict r2s, int n, int i,
    const int *restrict gidx, const float *restrict gr2, int gn, const float wall[3],
    pair_lanes *out)
{
    const int pressure = v->desc.pressure != MS_PRESSURE_DFSPH;
    const float *pi8 = v->pk + 8 * (size_t)i;
    const __m512 xi = _mm512_set1_ps(pi8[0]), yi = _mm512_set1_ps(pi8[1]),
                 zi = _mm512_set1_ps(pi8[2]);
    const __m512 uxi = _mm512_set1_ps(pi8[4]), uyi = _mm512_set1_ps(pi8[5]),
                 uzi = _mm512_set1_ps(pi8[6]);
    const __m512 pi = _mm512_set1_ps(pi8[3]), h = _mm512_set1_ps(v->K.h);
    const __m512 eps = _mm512_set1_ps(sqrtf(v->eps2)), zero = _mm512_setzero_ps();
    lanes7 a = {zero, zero, zero, zero, zero, zero, zero};
    for (int k = 0; k < n && !pressure; k += MS_VOLUME_LANES) { /* DFSPH: the viscosity */
        __m512 uxj, uyj, uzj, irj;
        /* the streamed r^2 and indices 512 entries ahead, as dfsph.c's
         * loops (hints: the same bits; the phase 0.96x on the peer's
         * scene, three alternated runs) */
        ms_prefetch_ahead(r2s + k);
        ms_prefetch_ahead(idx + k);
        ms_load_quads(v->pk + 4, idx + k, &uxj, &uyj, &uzj, &irj); /* vx, vy, vz, 1/rho */
        __m512 r = _mm512_sqrt_ps(_mm512_loadu_ps(r2s + k));
        __m512 hr = _mm512_max_ps(_mm512_sub_ps(h, r), zero);
        __m512 fv = _mm512_mul_ps(irj, hr);
        a.vx = _mm512_add_ps(a.vx, _mm512_mul_ps(fv, _mm512_sub_ps(uxj, uxi)));
        a.vy = _mm512_add_ps(a.vy, _mm512_mul_ps(fv, _mm512_sub_ps(uyj, uyi)));
        a.vz = _mm512_add_ps(a.vz, _mm512_mul_ps(fv, _mm512_sub_ps(uzj, uzi)));
        a.d = _mm512_add_ps(a.d, fv);
    }
    for (int k = 0; k < n && pressure; k += MS_VOLUME_LANES) {
        __m512 xj, yj, zj, pj, uxj, uyj, uzj, irj;
        load_records(v->pk, idx + k, &xj, &yj, &zj, &pj, &uxj, &uyj, &uzj, &irj);
        __m512 dx = _mm512_sub_ps(xi, xj);
        __m512 dy = _mm512_sub_ps(yi, yj);
        __m512 dz = _mm512_sub_ps(zi, zj);
        __m512 r = _mm512_sqrt_ps(_mm512_loadu_ps(r2s + k));
        __m512 hr = _mm512_max_ps(_mm512_sub_ps(h, r), zero);
        __m512 fv = _mm512_mul_ps(irj, hr);
        __m512 pp = _mm512_add_ps(pi, pj);
        __m512 fp = _mm512_div_ps(_mm512_mul_ps(_mm512_mul_ps(pp, fv), hr), _mm512_max_ps(r, eps));
        a.px = _mm512_add_ps(a.px, _mm512_mul_ps(fp, dx));
        a.py = _mm512_add_ps(a.py, _mm512_mul_ps(fp, dy));
        a.pz = _mm512_add_ps(a.pz, _mm512_mul_ps(fp, dz));
        a.vx = _mm512_add_ps(a.vx, _mm512_mul_ps(fv, _mm512_sub_ps(uxj, uxi)));
        a.vy = _mm512_add_ps(a.vy, _mm512_mul_ps(fv, _mm512_sub_ps(uyj, uyi)));
        a.vz = _mm512_add_ps(a.vz, _mm512_mul_ps(fv, _mm512_sub_ps(uzj, uzi)));
        a.d = _mm512_add_ps(a.d, fv);
    }
    for (int k = 0; k < gn; k += MS_VOLUME_LANES) /* the image list is padded to 16 */
        image_terms_avx512(v, gidx + k, gr2 + k, i, wall, pressure, &a);
    if (out) {
        _mm512_storeu_ps(out->px, a.px);
        _mm512_storeu_ps(out->py, a.py);
        _mm512_storeu_ps(out->pz, a.pz);
        _mm512_storeu_ps(out->vx, a.vx);
        _mm512_storeu_ps(out->vy, a.vy);
        _mm512_storeu_ps(out->vz, a.vz);
        _mm512_storeu_ps(out->d, a.d);
        pair_sums none = {0};
        return none;
    }
    pair_sums s = {ms_lanes_sum16(a.px), ms_lanes_sum16(a.py), ms_lanes_sum16(a.pz),
                   ms_lanes_sum16(a.vx), ms_lanes_sum16(a.vy), ms_lanes_sum16(a.vz),
                   ms_lanes_sum16(a.d)};
    return s;
}
#endif

/* The real-neighbour terms in plain C lanes (vectorised by the compiler),
 * into a (zeroed by the caller). */
static void real_lanes_c(const ms_volume *v, const int *restrict idx, const float *restrict r2s,
                         int n, int i, pair_lanes *restrict a)
{
    enum { L = MS_VOLUME_LANES };
    const float *restrict x = v->x, *restrict y = v->y, *restrict z = v->z;
    const float *restrict vx = v->vx, *restrict vy = v->vy, *restrict vz = v->vz;
    const float *restrict prs = v->prs, *restrict inv_rho = v->inv_rho;
    const float h = v->K.h, eps = sqrtf(v->eps2);
    const float xi = x[i], yi = y[i], zi = z[i], vxi = vx[i], vyi = vy[i], vzi = vz[i];
    const float pi = prs[i];
    for (int k = 0; k < n; k += L)
        for (int l = 0; l < L; ++l) {
            const int j = idx[k + l]; /* padding: i itself at r = h, adds 0 */
            float dx = xi - x[j], dyy = yi - y[j], dzz = zi - z[j];
            float r = sqrtf(r2s[k + l]);
            float hr = h - r;
            hr = hr > 0.0f ? hr : 0.0f;
            float fv = inv_rho[j] * hr;
            float fp = (pi + prs[j]) * fv * hr / (r > eps ? r : eps);
            a->px[l] += fp * dx;
            a->py[l] += fp * dyy;
            a->pz[l] += fp * dzz;
            a->vx[l] += fv * (vx[j] - vxi);
            a->vy[l] += fv * (vy[j] - vyi);
            a->vz[l] += fv * (vz[j] - vzi);
            a->d[l] += fv;
        }
}

/* The seven terms t of entry k of particle i's image list (a wall image
 * or a shape image), in plain C: the same operations as the AVX-512 terms. */
static inline void image_term(const ms_volume *v, int gk, float r2, int i, const float wall[3],
                              float t[7])
{
    const float h = v->K.h, eps = sqrtf(v->eps2);
    const float xi = v->x[i], yi = v->y[i], zi = v->z[i];
    const unsigned f = (unsigned)gk >> MS_VOLUME_IMAGE_SHIFT;
    const int j = gk & ((1 << MS_VOLUME_IMAGE_SHIFT) - 1);
    float pj[3] = {v->x[j], v->y[j], v->z[j]}, uj[3] = {v->vx[j], v->vy[j], v->vz[j]};
    if (f == MS_VOLUME_IMAGE_SHAPE) {
        /* across the tangent plane (point c, normal nn) of the nearest
         * shape; velocity mirrored in the shape's frame */
        const float dd = v->c_d[i];
        const float nn[3] = {v->c_nx[i], v->c_ny[i], v->c_nz[i]};
        const float vs[3] = {v->c_vx[i], v->c_vy[i], v->c_vz[i]};
        const float c[3] = {xi - dd * nn[0], yi - dd * nn[1], zi - dd * nn[2]};
        float sp = (pj[0] - c[0]) * nn[0] + (pj[1] - c[1]) * nn[1] + (pj[2] - c[2]) * nn[2];
        float su = (uj[0] - vs[0]) * nn[0] + (uj[1] - vs[1]) * nn[1] + (uj[2] - vs[2]) * nn[2];
        for (int q = 0; q < 3; ++q) {
            pj[q] -= 2.0f * sp * nn[q];
            uj[q] -= 2.0f * su * nn[q];
        }
    } else {
        for (int q = 0; q < 3; ++q)
            if (f & (1u << q)) {
                pj[q] = 2.0f * wall[q] - pj[q];
                uj[q] = -uj[q];
            }
    }
    float r = sqrtf(r2);
    float hr = h - r;
    hr = hr > 0.0f ? hr : 0.0f;
    float fv = v->inv_rho[j] * hr;
    float fp = (v->prs[i] + v->prs[j]) * fv * hr / (r > eps ? r : eps);
    t[0] = fp * (xi - pj[0]);
    t[1] = fp * (yi - pj[1]);
    t[2] = fp * (zi - pj[2]);
    t[3] = fv * (uj[0] - v->vx[i]);
    t[4] = fv * (uj[1] - v->vy[i]);
    t[5] = fv * (uj[2] - v->vz[i]);
    t[6] = fv;
}

/* The image terms of entries [0, gn) of the image list, gn padded to 16,
 * entry k into lane k % 16. */
static void image_lanes_c(const ms_volume *v, const int *restrict gidx, const float *restrict gr2,
                          int gn, int i, const float wall[3], pair_lanes *restrict a)
{
    for (int k = 0; k < gn; ++k) {
        const int l = k % MS_VOLUME_LANES;
        float t[7];
        image_term(v, gidx[k], gr2[k], i, wall, t);
        a->px[l] += t[0];
        a->py[l] += t[1];
        a->pz[l] += t[2];
        a->vx[l] += t[3];
        a->vy[l] += t[4];
        a->vz[l] += t[5];
        a->d[l] += t[6];
    }
}

/* Particle i's runs: its real list (n entries, padded) and its image
 * list (gn, padded; the neighbour reflected across the walls of its image
 * bits, position and velocity, or across the nearest shape's tangent
 * plane, same pressure and density), and the walls it is near. */
typedef struct runs_of_i {
    const int *idx, *gidx;
    const float *r2s, *gr2;
    int n, gn;
    float wall[3];
} runs_of_i;

static inline runs_of_i runs_of(const ms_volume *v, const ms_nlist *lst, const ms_nlist *gst, int i)
{
    runs_of_i r = {lst->idx + v->nl_begin[i], gst->idx + v->gl_begin[i], lst->r2 + v->nl_begin[i],
                   gst->r2 + v->gl_begin[i],  padded(v->nl_count[i]),    padded(v->gl_count[i]),
                   {0.0f, 0.0f, 0.0f}};
    if (r.gn)
        ms_volume_walls_near(v, v->x[i], v->y[i], v->z[i], r.wall);
    return r;
}

static pair_sums sums_c(const ms_volume *v, const ms_nlist *lst, const ms_nlist *gst, int i)
{
    const runs_of_i r = runs_of(v, lst, gst, i);
    pair_lanes a;
    memset(&a, 0, sizeof a);
    real_lanes_c(v, r.idx, r.r2s, r.n, i, &a);
    if (r.gn)
        image_lanes_c(v, r.gidx, r.gr2, r.gn, i, r.wall, &a);
    return lanes_sum(&a);
}

/* Particle i's acceleration from its sums (eqs. 13, 14), the boundary
 * field and gravity; its viscous rate for the time-step bound. */
static inline void accel_of(ms_volume *v, int i, pair_sums s, float cp, float cv)
{
    const float ri = v->inv_rho[i];
    s.d -= ri * v->K.h; /* the list holds the particle itself: not a neighbour */
    v->ax[i] = cp * ri * s.px + cv * ri * s.vx + v->b_ax[i] + v->desc.gravity[0];
    v->ay[i] = cp * ri * s.py + cv * ri * s.vy + v->b_ay[i] + v->desc.gravity[1];
    v->az[i] = cp * ri * s.pz + cv * ri * s.vz + v->b_az[i] + v->desc.gravity[2];
    v->visc_rate[i] = cv * ri * (s.d > 0.0f ? s.d : 0.0f);
}

#if MS_VOLUME_HAVE_AVX512
/* The force pass of particles [b, e) on AVX-512, sums_avx512 inlined: no
 * call a particle, the loop's constants and the seven accumulators kept in
 * registers (as dfsph.c's flattened dfsph_part).
 * A particle at a shape adds its shape images in the C loop. The same
 * operations: the same bits. */
__attribute__((target("avx512f,avx512dq"))) static void forces_range_avx512(ms_volume *v, int part,
                                                                            int b, int e)
{
    const ms_nlist *lst = &v->lists[part], *gst = &v->ghosts[part];
    const float cp = 0.5f * v->press_scale * v->mass * v->K.spiky_grad;  /* eq. 13 */
    const float cv = 0.5f * v->mass * v->K.visc_lap * v->desc.viscosity; /* eq. 14 */
    for (int i = b; i < e; ++i) {
        const runs_of_i r = runs_of(v, lst, gst, i);
        if (!r.gn || !(v->c_d[i] < v->K.h)) { /* wall images only */
            accel_of(v, i, sums_avx512(v, r.idx, r.r2s, r.n, i, r.gidx, r.gr2, r.gn, r.wall, NULL),
                     cp, cv);
            continue;
        }
        pair_lanes a;
        sums_avx512(v, r.idx, r.r2s, r.n, i, r.gidx, r.gr2, 0, r.wall, &a);
        image_lanes_c(v, r.gidx, r.gr2, r.gn, i, r.wall, &a);
        accel_of(v, i, lanes_sum(&a), cp, cv);
    }
}
#endif

static void forces_part(void *ctxp, int part, int b, int e)
{
    forces_ctx *ctx = ctxp;
    ms_volume *v = ctx->v;
#if MS_VOLUME_HAVE_AVX512
    if (v->isa == MS_VOLUME_ISA_AVX512) {
        forces_range_avx512(v, part, b, e);
        return;
    }
#endif
    const ms_nlist *lst = &v->lists[part], *gst = &v->ghosts[part];
    const float cp = 0.5f * v->press_scale * v->mass * v->K.spiky_grad;  /* eq. 13 */
    const float cv = 0.5f * v->mass * v->K.visc_lap * v->desc.viscosity; /* eq. 14 */
    for (int i = b; i < e; ++i)
        accel_of(v, i, sums_c(v, lst, gst, i), cp, cv);
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
