/* Collisions (paper 3.3.1) and the walls' share of the SPH sums.
 *
 * 1. The force field of eq. 15,   f_col ~ n_object / (d + 1),
 *    read with d in units of the field's reach r_c = spacing/2 (where a
 *    lattice fill puts the first layer) and shifted so that the field falls
 *    continuously to zero at the reach:
 *        a_col = A n (2 / (d/r_c + 1) - 1)   for 0 <= d < r_c,
 *        a_col = A n (1 - 2 d/r_c)           inside (d < 0: its tangent),
 *    A = c^2 / h (c the sound speed). The approach inside the field is
 *    damped implicitly (critical damping of the field's stiffness), relative
 *    to the object's velocity: an impact is inelastic and keeps the
 *    tangential momentum.
 *
 * 2. The liquid reflected by a wall: a particle within h of a wall sums
 *    over the images of its neighbours across the wall (density.c,
 *    forces.c), so it is not under-dense and the wall pushes back with the
 *    liquid's own pressure. Exact for the domain box (the classic mirror
 *    boundary, images across one, two or three walls); for a shape, across
 *    the tangent plane at the particle's closest point, with only the
 *    neighbours on the particle's side of that plane (the liquid beyond a
 *    thin wall is not mirrored), velocities mirrored in the shape's frame.
 *    Measured: without it, the layer of false "vacuum" at a wall sucked an
 *    8000-particle tank at rest into its walls at 2 m/s within 0.1 s; a
 *    mirrored lattice instead of the images pumped liquid up a glass's wall
 *    and over its rim.
 *
 * 3. No particle ends inside an object or outside the domain: the field
 *    cannot promise that against a 20 m/s obstacle, so after each drift a
 *    particle inside is put back on the surface and its velocity into the
 *    object (relative to it) removed; for shapes the test is swept along
 *    the particle's path in the object's frame, so a thin wall is never
 *    crossed between sub-steps. The domain box is always a collider: its
 *    six walls get all of the above, and positions are clamped into it.
 */
#include <math.h>
#include <string.h>

#include "shape/shape_internal.h"
#include "volume/volume_internal.h"

#if MS_VOLUME_HAVE_AVX512
#include <immintrin.h>

#include "volume/records_avx512.h"
#endif

/* eq. 15 field strength in units of A; q = d / r_c */
static inline float field(float q)
{
    return q >= 1.0f ? 0.0f : (q >= 0.0f ? 2.0f / (q + 1.0f) - 1.0f : 1.0f - 2.0f * q);
}

#if MS_VOLUME_HAVE_AVX512
/* field() of 16 lanes: the same operations (IEEE division, no fused
 * multiply-adds), so the same bits; a NaN q gives 1 - 2q, as field(). */
__attribute__((target("avx512f"), always_inline)) static inline __m512 field16(__m512 q)
{
    const __m512 one = _mm512_set1_ps(1.0f), two = _mm512_set1_ps(2.0f);
    const __m512 near = _mm512_sub_ps(_mm512_div_ps(two, _mm512_add_ps(q, one)), one);
    const __m512 inside = _mm512_sub_ps(one, _mm512_mul_ps(two, q));
    const __mmask16 far = _mm512_cmp_ps_mask(q, one, _CMP_GE_OQ);
    const __mmask16 ahead = _mm512_cmp_ps_mask(q, _mm512_setzero_ps(), _CMP_GE_OQ);
    return _mm512_maskz_mov_ps((__mmask16)~far, _mm512_mask_blend_ps(ahead, inside, near));
}

/* The domain walls' eq. 15 field along one axis, p[b..e) -> out[b..e):
 * A (field(d_lo / r_c) - field(d_hi / r_c)), boundary_part's first loop in
 * 16 lanes (the C loop is scalar, two divisions a particle and axis). Masked at the end: the next part's particles belong to
 * another thread. */
__attribute__((target("avx512f,bmi2"))) static void wall_field_avx512(const float *restrict p,
                                                                      float *restrict out, int b,
                                                                      int e, float lo, float hi,
                                                                      float inv_rc, float A)
{
    const __m512 vlo = _mm512_set1_ps(lo), vhi = _mm512_set1_ps(hi);
    const __m512 vr = _mm512_set1_ps(inv_rc), va = _mm512_set1_ps(A);
    for (int i = b; i < e; i += 16) {
        const unsigned rem = (unsigned)(e - i);
        const __mmask16 m = ms_lanes_left(rem);
        const __m512 x = _mm512_maskz_loadu_ps(m, p + i);
        const __m512 fl = field16(_mm512_mul_ps(_mm512_sub_ps(x, vlo), vr));
        const __m512 fh = field16(_mm512_mul_ps(_mm512_sub_ps(vhi, x), vr));
        _mm512_mask_storeu_ps(out + i, m, _mm512_mul_ps(va, _mm512_sub_ps(fl, fh)));
    }
}

/* damp_part's domain walls along one axis in 16 lanes (the same
 * operations: the same bits): u /= 1 + gdt w, w the field of the wall the
 * particle approaches. Only that wall's field is computed (the scalar
 * loop computed both): one division for the field, one for u. */
__attribute__((target("avx512f,bmi2"))) static void wall_damp_avx512(const float *restrict p,
                                                                     float *restrict u, int b,
                                                                     int e, float lo, float hi,
                                                                     float inv_rc, float gdt)
{
    const __m512 vlo = _mm512_set1_ps(lo), vhi = _mm512_set1_ps(hi);
    const __m512 vr = _mm512_set1_ps(inv_rc), vg = _mm512_set1_ps(gdt);
    const __m512 one = _mm512_set1_ps(1.0f);
    for (int i = b; i < e; i += 16) {
        const unsigned rem = (unsigned)(e - i);
        const __mmask16 m = ms_lanes_left(rem);
        const __m512 x = _mm512_maskz_loadu_ps(m, p + i), ui = _mm512_maskz_loadu_ps(m, u + i);
        /* approaching the low wall: u < 0 (a NaN u: the high wall, as the C loop) */
        const __mmask16 low = _mm512_cmp_ps_mask(ui, _mm512_setzero_ps(), _CMP_LT_OQ);
        const __m512 d = _mm512_mask_blend_ps(low, _mm512_sub_ps(vhi, x), _mm512_sub_ps(x, vlo));
        const __m512 w = field16(_mm512_mul_ps(d, vr));
        const __m512 den = _mm512_add_ps(one, _mm512_mul_ps(vg, w));
        _mm512_mask_storeu_ps(u + i, m, _mm512_div_ps(ui, den));
    }
}
#endif

/* A shape collider as seen during one pass: at time tau into the step it
 * has moved by shift = vel tau from its pose, so a world point x is at
 * x - shift in the shape's own frame. A turned shape (an orientation or an
 * angular velocity, ms_shape_set_orientation) is also rotated: x is at
 * q = R^T (x - o) in the plugin's frame, with the origin o and rotation R
 * at the pass's time (o0, R0) and at the end of the sub-step (o1, R1);
 * its material moves at vel + omega x (x - o). */
typedef struct collider_view {
    const ms_shape *s;
    float vel[3];       /* m/s */
    float shift[3];     /* m */
    float lo[3], hi[3]; /* m, world bounds at tau, widened by the pass's reach */
    int turned;
    float omega[3];     /* rad/s */
    float o0[3], o1[3]; /* m */
    float R0[9], R1[9];
} collider_view;

typedef struct collide_ctx {
    ms_volume *v;
    double tau;
    float dt;
    int ncol;
    collider_view col[MS_VOLUME_MAX_COLLIDERS];
} collide_ctx;

/* Views of the colliders at time t (s) into the step, bounds widened by
 * reach (m) and by the distance the shape moves in the next `ahead` s. */
static void view_colliders(collide_ctx *ctx, double t, float reach, float ahead)
{
    const ms_volume *v = ctx->v;
    ctx->ncol = v->ncolliders;
    for (int c = 0; c < v->ncolliders; ++c) {
        collider_view *cv = &ctx->col[c];
        float pos[3], jump[3] = {0.0f, 0.0f, 0.0f};
        cv->s = v->colliders[c];
        cv->turned = cv->s->turned;
        ms_shape_get_pose(cv->s, pos, cv->vel);
        if (cv->turned) /* bounds that hold it however it turns */
            ms_shape_bounds_any_turn(cv->s, cv->lo, cv->hi);
        else
            ms_shape_bounds(cv->s, cv->lo, cv->hi);
        if (v->in_step)
            for (int k = 0; k < 3; ++k) {
                cv->vel[k] = v->col_vel[c][k];
                jump[k] = v->col_jump[c][k];
            }
        for (int k = 0; k < 3; ++k) {
            /* at time t it is at pose - jump + vel t */
            cv->shift[k] = (float)(cv->vel[k] * t) - jump[k];
            float grow = reach + fabsf(cv->vel[k]) * ahead;
            cv->lo[k] += cv->shift[k] - grow;
            cv->hi[k] += cv->shift[k] + grow;
        }
        if (cv->turned) {
            ms_shape_get_orientation(cv->s, NULL, cv->omega);
            ms_shape_rotation_at(cv->s, (float)t, cv->R0);
            ms_shape_rotation_at(cv->s, (float)t + ahead, cv->R1);
            for (int k = 0; k < 3; ++k) {
                cv->o0[k] = pos[k] + cv->shift[k];
                cv->o1[k] = pos[k] + cv->shift[k] + cv->vel[k] * ahead;
            }
        }
    }
}

/* The velocity of the shape's material at q (its frame): the plugin's,
 * plus the sweep that carries it to where the caller moved it. */
static void shape_velocity(const collider_view *cv, const float q[3], float u[3])
{
    float pos[3], vel[3];
    ms_shape_velocity(cv->s, q, u);
    ms_shape_get_pose(cv->s, pos, vel);
    for (int k = 0; k < 3; ++k)
        u[k] += cv->vel[k] - vel[k];
}

static inline int in_view(const collider_view *cv, float x, float y, float z)
{
    return x >= cv->lo[0] && x <= cv->hi[0] && y >= cv->lo[1] && y <= cv->hi[1] && z >= cv->lo[2] &&
           z <= cv->hi[2];
}

static void boundary_part(void *ctxp, int part, int b, int e)
{
    (void)part;
    collide_ctx *ctx = ctxp;
    ms_volume *v = ctx->v;
    const float *pos[3] = {v->x, v->y, v->z};
    float *ba[3] = {v->b_ax, v->b_ay, v->b_az};
    const float inv_rc = 1.0f / v->col_range, A = v->col_accel, h = v->K.h;
    for (int k = 0; k < 3; ++k) {
        const float lo = v->desc.domain_min[k], hi = v->desc.domain_max[k];
#if MS_VOLUME_HAVE_AVX512
        if (v->isa == MS_VOLUME_ISA_AVX512) {
            wall_field_avx512(pos[k], ba[k], b, e, lo, hi, inv_rc, A);
            continue;
        }
#endif
        for (int i = b; i < e; ++i)
            ba[k][i] = A * (field((pos[k][i] - lo) * inv_rc) - field((hi - pos[k][i]) * inv_rc));
    }
    for (int i = b; i < e; ++i) {
        v->c_d[i] = INFINITY;
        v->c_w[i] = 0.0f;
    }
    for (int c = 0; c < ctx->ncol; ++c) {
        const collider_view *cv = &ctx->col[c];
        for (int i = b; i < e; ++i) {
            if (!in_view(cv, v->x[i], v->y[i], v->z[i]))
                continue;
            float q[3] = {v->x[i] - cv->shift[0], v->y[i] - cv->shift[1], v->z[i] - cv->shift[2]};
            float n[3];
            float d;
            if (cv->turned) {
                const float x[3] = {v->x[i], v->y[i], v->z[i]};
                float ql[3], nl[3];
                ms_rigid_to_local(cv->R0, cv->o0, x, ql);
                d = ms_shape_distance_local(cv->s, ql, nl);
                ms_rigid_to_world(cv->R0, nl, n);
            } else {
                d = ms_shape_distance(cv->s, q, n);
            }
            if (!(d < h))
                continue;
            float f = field(d * inv_rc); /* eq. 15 */
            for (int k = 0; k < 3; ++k)
                ba[k][i] += A * f * n[k];
            if (d < v->c_d[i]) { /* the nearest collider */
                float u[3];
                if (cv->turned) {
                    const float x[3] = {v->x[i], v->y[i], v->z[i]};
                    ms_rigid_velocity(cv->vel, cv->omega, cv->o0, x, u);
                } else {
                    shape_velocity(cv, q, u);
                }
                v->c_d[i] = d > 0.0f ? d : 0.0f; /* inside: the plane through it */
                v->c_w[i] = f;
                v->c_nx[i] = n[0];
                v->c_ny[i] = n[1];
                v->c_nz[i] = n[2];
                v->c_vx[i] = u[0];
                v->c_vy[i] = u[1];
                v->c_vz[i] = u[2];
            }
        }
    }
}

void ms_volume_boundary(ms_volume *v, double tau)
{
    collide_ctx ctx = {.v = v, .tau = tau};
    view_colliders(&ctx, tau, v->K.h, 0.0f);
    ms_vpool_run(v->pool, boundary_part, &ctx, v->n);
}

/* Move a view at tau = 0 (its pose) to where the last step left the
 * collider: origin e[0..2], rotation e[3..11]. Returns 0 (view untouched)
 * when that is its pose bit for bit: a collider at rest, or one the
 * caller has already put there. */
static int view_at_end(collider_view *cv, const float e[12])
{
    float pos[3], vel[3];
    ms_shape_get_pose(cv->s, pos, vel);
    if (!memcmp(e, pos, sizeof pos) && (!cv->turned || !memcmp(e + 3, cv->s->rot, 9 * sizeof e[0])))
        return 0;
    for (int k = 0; k < 3; ++k) {
        float shift = e[k] - pos[k];
        cv->lo[k] += shift - cv->shift[k];
        cv->hi[k] += shift - cv->shift[k];
        cv->shift[k] = shift;
    }
    if (cv->turned)
        for (int k = 0; k < 3; ++k) {
            cv->o0[k] = cv->o1[k] = e[k];
            for (int j = 0; j < 3; ++j)
                cv->R0[3 * k + j] = cv->R1[3 * k + j] = e[3 + 3 * k + j];
        }
    return 1;
}

int ms_volume_boundary_after_step(ms_volume *v)
{
    collide_ctx ctx = {.v = v, .tau = 0.0};
    view_colliders(&ctx, 0.0, v->K.h, 0.0f);
    int moved = 0;
    for (int c = 0; !v->in_step && c < ctx.ncol; ++c)
        if (v->col_expect_valid[c])
            moved |= view_at_end(&ctx.col[c], v->col_end[c]);
    ms_vpool_run(v->pool, boundary_part, &ctx, v->n);
    return moved;
}

static void damp_part(void *ctxp, int part, int b, int e)
{
    (void)part;
    collide_ctx *ctx = ctxp;
    ms_volume *v = ctx->v;
    float *pos[3] = {v->x, v->y, v->z};
    float *vel[3] = {v->vx, v->vy, v->vz};
    const float inv_rc = 1.0f / v->col_range, gdt = v->col_damp * ctx->dt;
    for (int k = 0; k < 3; ++k) {
        const float lo = v->desc.domain_min[k], hi = v->desc.domain_max[k];
        const float *restrict p = pos[k];
        float *restrict u = vel[k];
#if MS_VOLUME_HAVE_AVX512
        if (v->isa == MS_VOLUME_ISA_AVX512) {
            wall_damp_avx512(p, u, b, e, lo, hi, inv_rc, gdt);
            continue;
        }
#endif
        for (int i = b; i < e; ++i) {
            /* approaching the low wall: u < 0; the high wall: u > 0 */
            float wl = field((p[i] - lo) * inv_rc), wh = field((hi - p[i]) * inv_rc);
            float w = u[i] < 0.0f ? wl : wh;
            u[i] = u[i] / (1.0f + gdt * w);
        }
    }
    if (ctx->ncol == 0)
        return;
    for (int i = b; i < e; ++i) {
        if (!(v->c_w[i] > 0.0f))
            continue;
        /* approach relative to the collider, along its normal */
        float n[3] = {v->c_nx[i], v->c_ny[i], v->c_nz[i]};
        float rel[3] = {v->vx[i] - v->c_vx[i], v->vy[i] - v->c_vy[i], v->vz[i] - v->c_vz[i]};
        float un = rel[0] * n[0] + rel[1] * n[1] + rel[2] * n[2];
        if (un >= 0.0f)
            continue;
        float dun = un / (1.0f + gdt * v->c_w[i]) - un;
        v->vx[i] += dun * n[0];
        v->vy[i] += dun * n[1];
        v->vz[i] += dun * n[2];
    }
}

void ms_volume_collider_damp(ms_volume *v, double tau, float dt)
{
    collide_ctx ctx = {.v = v, .tau = tau, .dt = dt};
    ctx.ncol = v->ncolliders;
    ms_vpool_run(v->pool, damp_part, &ctx, v->n);
}

/* Put the particle (world position x, velocity u) that ended at q (the
 * shape's frame at the end of the sub-step) inside or across the shape
 * back on its surface, and take away its velocity into the shape relative
 * to the shape. */
/* Distance in the view's frame: q = x - shift (ms_shape_distance applies
 * the pose), or for a turned view the plugin's own frame. */
static inline float view_distance(const collider_view *cv, const float q[3], float n[3])
{
    return cv->turned ? ms_shape_distance_local(cv->s, q, n) : ms_shape_distance(cv->s, q, n);
}

static void push_out(const collider_view *cv, const float end_shift[3], float q[3], float skin,
                     float x[3], float u[3])
{
    float n[3] = {0.0f, 0.0f, 1.0f};
    for (int it = 0; it < 4; ++it) { /* the normal is smoothed: a few steps */
        float d = view_distance(cv, q, n);
        if (d >= skin)
            break;
        for (int k = 0; k < 3; ++k)
            q[k] += (skin - d) * n[k];
    }
    float w[3];
    if (cv->turned) { /* back to the world at the end of the sub-step */
        float nl[3] = {n[0], n[1], n[2]};
        ms_rigid_to_world(cv->R1, q, x);
        for (int k = 0; k < 3; ++k)
            x[k] += cv->o1[k];
        ms_rigid_to_world(cv->R1, nl, n);
        ms_rigid_velocity(cv->vel, cv->omega, cv->o1, x, w);
    } else {
        shape_velocity(cv, q, w);
        for (int k = 0; k < 3; ++k)
            x[k] = q[k] + end_shift[k];
    }
    float un = (u[0] - w[0]) * n[0] + (u[1] - w[1]) * n[1] + (u[2] - w[2]) * n[2];
    for (int k = 0; k < 3; ++k)
        if (un < 0.0f)
            u[k] -= un * n[k];
}

static void resolve_part(void *ctxp, int part, int b, int e)
{
    (void)part;
    collide_ctx *ctx = ctxp;
    ms_volume *v = ctx->v;
    const float skin = 1e-3f * v->col_range;
    for (int c = 0; c < ctx->ncol; ++c) {
        const collider_view *cv = &ctx->col[c];
        const float dts = ctx->dt;
        const float end_shift[3] = {cv->shift[0] + cv->vel[0] * dts,
                                    cv->shift[1] + cv->vel[1] * dts,
                                    cv->shift[2] + cv->vel[2] * dts};
        for (int i = b; i < e; ++i) {
            float x0[3] = {v->x2[i], v->y2[i], v->z2[i]}, x1[3] = {v->x[i], v->y[i], v->z[i]};
            if (!in_view(cv, x0[0], x0[1], x0[2]) && !in_view(cv, x1[0], x1[1], x1[2]))
                continue;
            /* the path in the shape's frame: from q0 (start) to q1 (end) */
            float q0[3], q1[3], dq[3], len2 = 0.0f;
            for (int k = 0; k < 3; ++k) {
                q0[k] = x0[k] - cv->shift[k];
                q1[k] = x1[k] - end_shift[k];
            }
            if (cv->turned) { /* the path relative to the turning shape */
                ms_rigid_to_local(cv->R0, cv->o0, x0, q0);
                ms_rigid_to_local(cv->R1, cv->o1, x1, q1);
            }
            for (int k = 0; k < 3; ++k) {
                dq[k] = q1[k] - q0[k];
                len2 += dq[k] * dq[k];
            }
            const float len = sqrtf(len2);
            float d0 = view_distance(cv, q0, NULL);
            if (d0 > len + skin)
                continue; /* a distance bound: the path cannot reach the shape */
            float u[3] = {v->vx[i], v->vy[i], v->vz[i]}, x[3];
            float q[3] = {q1[0], q1[1], q1[2]};
            if (d0 > skin) {
                /* sphere tracing along the path: never steps over the surface */
                float t = 0.0f, d = d0;
                int hit = 0;
                for (int it = 0; it < 64 && t < 1.0f; ++it) {
                    if (d < skin) {
                        hit = 1;
                        break;
                    }
                    t += d / len;
                    if (t >= 1.0f)
                        break;
                    float p[3] = {q0[0] + t * dq[0], q0[1] + t * dq[1], q0[2] + t * dq[2]};
                    d = view_distance(cv, p, NULL);
                }
                if (hit) /* stop where the path met the surface */
                    for (int k = 0; k < 3; ++k)
                        q[k] = q0[k] + t * dq[k];
                else if (view_distance(cv, q1, NULL) >= skin)
                    continue;
            } else if (view_distance(cv, q1, NULL) >= skin) {
                continue; /* started inside (pushed out by the field), ends outside */
            }
            push_out(cv, end_shift, q, skin, x, u);
            v->x[i] = x[0];
            v->y[i] = x[1];
            v->z[i] = x[2];
            v->vx[i] = u[0];
            v->vy[i] = u[1];
            v->vz[i] = u[2];
        }
    }
}

/* The scalar clamp of particle i along one axis (domain_resolve_part). */
static inline void clamp_axis(float *restrict p, float *restrict u, int i, float lo, float hi)
{
    if (p[i] < lo) {
        p[i] = lo;
        u[i] = fmaxf(u[i], 0.0f);
    } else if (p[i] > hi) {
        p[i] = hi;
        u[i] = fminf(u[i], 0.0f);
    }
}

#if MS_VOLUME_HAVE_AVX512
/* domain_resolve_part's axis: 16 positions compared at once, the scalar
 * clamp only for the lanes outside [lo, hi] (a few particles a sub-step;
 * a NaN position is neither, as in the scalar test): the same results. */
__attribute__((target("avx512f,bmi2"))) static void clamp_axis_avx512(float *restrict p,
                                                                      float *restrict u, int b,
                                                                      int e, float lo, float hi)
{
    const __m512 vlo = _mm512_set1_ps(lo), vhi = _mm512_set1_ps(hi);
    for (int i = b; i < e; i += 16) {
        const unsigned rem = (unsigned)(e - i);
        const __mmask16 m = ms_lanes_left(rem);
        const __m512 x = _mm512_maskz_loadu_ps(m, p + i);
        unsigned out = _cvtmask16_u32(_mm512_mask_cmp_ps_mask(m, x, vlo, _CMP_LT_OQ) |
                                      _mm512_mask_cmp_ps_mask(m, x, vhi, _CMP_GT_OQ));
        for (; out; out &= out - 1u)
            clamp_axis(p, u, i + __builtin_ctz(out), lo, hi);
    }
}
#endif

static void domain_resolve_part(void *ctxp, int part, int b, int e)
{
    (void)part;
    collide_ctx *ctx = ctxp;
    ms_volume *v = ctx->v;
    float *pos[3] = {v->x, v->y, v->z};
    float *vel[3] = {v->vx, v->vy, v->vz};
    const float skin = 1e-3f * v->col_range;
    for (int k = 0; k < 3; ++k) {
        const float lo = v->desc.domain_min[k] + skin, hi = v->desc.domain_max[k] - skin;
        float *restrict p = pos[k], *restrict u = vel[k];
#if MS_VOLUME_HAVE_AVX512
        if (ctx->v->isa == MS_VOLUME_ISA_AVX512) {
            clamp_axis_avx512(p, u, b, e, lo, hi);
            continue;
        }
#endif
        for (int i = b; i < e; ++i)
            clamp_axis(p, u, i, lo, hi);
    }
}

void ms_volume_collider_resolve(ms_volume *v, double tau, float dt)
{
    collide_ctx ctx = {.v = v, .tau = tau, .dt = dt};
    if (v->ncolliders > 0) {
        /* reach: the farthest a particle moved this sub-step */
        float reach = 0.0f;
        for (int i = 0; i < v->n; ++i) {
            float dx = v->x[i] - v->x2[i], dy = v->y[i] - v->y2[i], dz = v->z[i] - v->z2[i];
            float l = dx * dx + dy * dy + dz * dz;
            reach = l > reach ? l : reach;
        }
        view_colliders(&ctx, tau, sqrtf(reach) + v->col_range, dt);
        ms_vpool_run(v->pool, resolve_part, &ctx, v->n);
    }
    ms_vpool_run(v->pool, domain_resolve_part, &ctx, v->n);
}

float ms_volume_collider_speed(const ms_volume *v)
{
    float vmax = 0.0f;
    for (int c = 0; c < v->ncolliders; ++c) {
        const float *u = v->col_vel[c];
        float speed = sqrtf(u[0] * u[0] + u[1] * u[1] + u[2] * u[2]);
        const ms_shape *s = v->colliders[c];
        if (s->turned) { /* its farthest point turns at |omega| r */
            float lo[3], hi[3], w[3];
            ms_shape_bounds_any_turn(s, lo, hi);
            ms_shape_get_orientation(s, NULL, w);
            float r = 0.5f * (hi[0] - lo[0]);
            if (r < 1e29f)
                speed += sqrtf(w[0] * w[0] + w[1] * w[1] + w[2] * w[2]) * r;
        }
        vmax = fmaxf(vmax, speed);
    }
    return vmax;
}

/* A collider the caller moved somewhere else than its velocity took it in
 * the last step (a teleport, a pose set without a velocity) is swept from
 * there to its new place during this step, with the extra velocity
 * jump / dt: the liquid in the way is pushed (the CFL bound sees the
 * speed), never crushed into a jump or crossed. */
void ms_volume_colliders_begin(ms_volume *v, float dt)
{
    for (int c = 0; c < v->ncolliders; ++c) {
        float pos[3], vel[3];
        ms_shape_get_pose(v->colliders[c], pos, vel);
        for (int k = 0; k < 3; ++k) {
            float jump = v->col_expect_valid[c] ? pos[k] - v->col_expect[c][k] : 0.0f;
            v->col_jump[c][k] = jump;
            v->col_vel[c][k] = vel[k] + jump / dt;
        }
    }
    v->in_step = 1;
}

void ms_volume_colliders_end(ms_volume *v, float dt, double reached)
{
    for (int c = 0; c < v->ncolliders; ++c) {
        const ms_shape *s = v->colliders[c];
        float pos[3], vel[3];
        ms_shape_get_pose(s, pos, vel);
        for (int k = 0; k < 3; ++k) {
            v->col_expect[c][k] = pos[k] + vel[k] * dt;
            /* where the step's views had it at tau = reached (the jump
             * swept out by dt; less after a cancel) */
            v->col_end[c][k] = pos[k] + ((float)(v->col_vel[c][k] * reached) - v->col_jump[c][k]);
        }
        if (s->turned)
            ms_shape_rotation_at(s, (float)reached, v->col_end[c] + 3);
        else
            memcpy(v->col_end[c] + 3, s->rot, 9 * sizeof(float));
        v->col_expect_valid[c] = 1;
    }
    v->in_step = 0;
}
