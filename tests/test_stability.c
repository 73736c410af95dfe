/* The stability suite: named hard cases, each asserting no NaN or Inf
 * anywhere, energy bounded by what entered the system, no particle lost
 * and none inside a collider, and the same bytes when run twice.
 *
 * Waves (eq. 2), SPH (eqs. 9-15) with every pressure solver the library
 * has (a solver this build refuses with MS_ERR_UNSUPPORTED is reported as
 * skipped, never passed), and the refusals: a parameter set no sub-stepping
 * can make stable is refused with MS_ERR_UNSTABLE and a sentence naming
 * the value and the bound, one test per bound.
 *
 * The coupled long runs (fig1 and fig10 at the top of the coupling gains'
 * documented range for 10 simulated minutes; every shipped scene at 1 and
 * 2 threads) are registered only with MS_TEST_LONG=1, which `make
 * check-long` sets: they are not part of `make check`, and never pass by
 * returning early.
 */
#include <check.h>
#include <dirent.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "modesplit/modesplit.h"
#include "support.h"
#include "volume/volume_internal.h"

/* ---- helpers ---------------------------------------------------------- */

static uint64_t fnv(uint64_t h, const void *p, size_t n)
{
    const unsigned char *b = p;
    for (size_t i = 0; i < n; ++i)
        h = (h ^ b[i]) * 1099511628211ull;
    return h;
}

static void assert_finite(const float *a, size_t n, const char *what)
{
    for (size_t i = 0; i < n; ++i)
        ck_assert_msg(isfinite(a[i]), "%s[%zu] = %g", what, i, a[i]);
}

/* ---- waves -------------------------------------------------------------- */

static ms_surface *wave(int n, float c, float damping, ms_boundary b)
{
    ms_surface_desc d = ms_surface_desc_default();
    d.nx = d.ny = n;
    d.dx = 1.0f / n;
    d.wave_speed = c;
    d.damping = damping;
    d.boundary = b;
    ms_surface *s = NULL;
    ms_status st = ms_surface_create(&d, &s);
    ck_assert_msg(st == MS_OK, "%s", ms_last_error());
    return s;
}

/* A smooth bump of height a at the centre (m), deterministic. */
static void bump(ms_surface *s, int n, float a)
{
    float *h = malloc(sizeof(float) * (size_t)n * n);
    for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x) {
            double dx = (x + 0.5) / n - 0.5, dy = (y + 0.5) / n - 0.5;
            h[y * n + x] = (float)(a * exp(-(dx * dx + dy * dy) / (2 * 0.05 * 0.05)));
        }
    ck_assert_int_eq(ms_surface_set_height(s, h), MS_OK);
    free(h);
}

static uint64_t wave_hash(const ms_surface *s)
{
    int nx, ny;
    const float *h = ms_surface_height(s, &nx, &ny);
    assert_finite(h, (size_t)nx * ny, "height");
    return fnv(1469598103934665603ull, h, sizeof(float) * (size_t)nx * ny);
}

/* Each wave case runs twice and must give the same bytes. */
typedef uint64_t wave_case(void);

static void twice(wave_case *f)
{
    uint64_t a = f(), b = f();
    ck_assert_msg(a == b, "two runs differ: %016llx %016llx", (unsigned long long)a,
                  (unsigned long long)b);
}

static uint64_t largest_courant(void)
{
    ms_surface *s = wave(48, 1.0f, 1.0f, MS_BOUNDARY_REFLECT);
    bump(s, 48, 0.01f);
    ms_surface_info in = ms_surface_info_init();
    ms_surface_get_info(s, &in);
    const float dt = in.max_dt; /* exactly the bound: one sub-step a call */
    const double e0 = ms_surface_energy(s);
    for (int k = 0; k < 100000; ++k) {
        ck_assert_int_eq(ms_surface_step(s, dt), MS_OK);
        if (k % 1000 == 999) {
            double e = ms_surface_energy(s);
            ck_assert_msg(e <= 1.02 * e0, "step %d: energy %g J over %g J", k, e, e0);
        }
    }
    ms_surface_get_info(s, &in);
    ck_assert_int_eq(in.substeps, 100000);
    uint64_t h = wave_hash(s);
    ms_surface_destroy(s);
    return h;
}

START_TEST(waves_100000_steps_at_exactly_the_largest_stable_courant)
{
    twice(largest_courant);
}
END_TEST

static uint64_t hundredfold(void)
{
    ms_surface *s = wave(64, 1.0f, 1.0f, MS_BOUNDARY_REFLECT);
    bump(s, 64, 0.01f);
    ms_surface_info in = ms_surface_info_init();
    ms_surface_get_info(s, &in);
    const double e0 = ms_surface_energy(s);
    for (int k = 0; k < 20; ++k)
        ck_assert_int_eq(ms_surface_step(s, 100 * in.max_dt), MS_OK);
    ms_surface_info after = ms_surface_info_init();
    ms_surface_get_info(s, &after);
    ck_assert_int_ge(after.substeps, 20 * 100); /* sub-stepped, not unstable */
    ck_assert_msg(ms_surface_energy(s) <= 1.02 * e0, "energy %g over %g", ms_surface_energy(s), e0);
    uint64_t h = wave_hash(s);
    ms_surface_destroy(s);
    return h;
}

START_TEST(waves_a_step_100x_over_the_bound_is_substepped)
{
    twice(hundredfold);
}
END_TEST

static uint64_t drop_every_step(void)
{
    const int n = 64;
    ms_surface *s = wave(n, 1.0f, 0.5f, MS_BOUNDARY_REFLECT);
    ms_surface_info in = ms_surface_info_init();
    ms_surface_get_info(s, &in);
    double entered = 0;
    for (int k = 0; k < 10000; ++k) {
        double before = ms_surface_energy(s);
        /* one cell wide, on the same cell every step */
        ck_assert_int_eq(ms_surface_add_drop(s, 0.5f + 0.5f / n, 0.5f + 0.5f / n, 0.5f / n, 0.001f),
                         MS_OK);
        double after = ms_surface_energy(s);
        entered += fmax(after - before, 0);
        ck_assert_int_eq(ms_surface_step(s, in.max_dt), MS_OK);
        ck_assert_msg(ms_surface_energy(s) <= entered * 1.02 + 1e-12,
                      "step %d: energy %g J over the %g J the drops brought", k,
                      ms_surface_energy(s), entered);
    }
    uint64_t h = wave_hash(s);
    ms_surface_destroy(s);
    return h;
}

START_TEST(waves_a_drop_on_one_cell_every_step_for_10000_steps)
{
    twice(drop_every_step);
}
END_TEST

static uint64_t speed_jump(void)
{
    const int n = 64;
    ms_surface *s = wave(n, 1.0f, 1.0f, MS_BOUNDARY_REFLECT);
    float *c = malloc(sizeof(float) * n * n);
    for (int i = 0; i < n * n; ++i)
        c[i] = (i % n) < n / 2 ? 1.0f : 0.01f; /* 100:1 across x = 0.5 m */
    ck_assert_int_eq(ms_surface_set_speed_map(s, c), MS_OK);
    free(c);
    bump(s, n, 0.01f);
    const double e0 = ms_surface_energy(s);
    for (int k = 0; k < 300; ++k) {
        ck_assert_int_eq(ms_surface_step(s, 1.0f / 60), MS_OK);
        ck_assert_msg(ms_surface_energy(s) <= 1.02 * e0, "frame %d: energy %g over %g", k,
                      ms_surface_energy(s), e0);
    }
    uint64_t h = wave_hash(s);
    ms_surface_destroy(s);
    return h;
}

START_TEST(waves_a_speed_map_with_a_100_to_1_jump)
{
    twice(speed_jump);
}
END_TEST

static uint64_t damping_sides(void)
{
    const int n = 64;
    ms_surface *s = wave(n, 1.0f, 1.0f, MS_BOUNDARY_REFLECT);
    float *d = malloc(sizeof(float) * n * n);
    /* the smallest damping factor the map allows (0 is outside (0, 1])
     * beside none at all */
    for (int i = 0; i < n * n; ++i)
        d[i] = (i % n) < n / 2 ? 1e-30f : 1.0f;
    ck_assert_int_eq(ms_surface_set_damping_map(s, d), MS_OK);
    d[0] = 0.0f;
    MS_ASSERT_REFUSED(ms_surface_set_damping_map(s, d), MS_ERR_INVALID_ARGUMENT, "damping");
    free(d);
    bump(s, n, 0.01f);
    const double e0 = ms_surface_energy(s);
    for (int k = 0; k < 300; ++k) {
        ck_assert_int_eq(ms_surface_step(s, 1.0f / 60), MS_OK);
        ck_assert_msg(ms_surface_energy(s) <= 1.02 * e0, "frame %d: energy %g over %g", k,
                      ms_surface_energy(s), e0);
    }
    uint64_t h = wave_hash(s);
    ms_surface_destroy(s);
    return h;
}

START_TEST(waves_a_damping_map_with_full_and_no_damping_side_by_side)
{
    twice(damping_sides);
}
END_TEST

static uint64_t isolated_obstacles(void)
{
    const int n = 64;
    ms_surface *s = wave(n, 1.0f, 1.0f, MS_BOUNDARY_REFLECT);
    unsigned char *m = calloc((size_t)n * n, 1);
    for (int y = 1; y < n; y += 3)
        for (int x = 1; x < n; x += 3)
            m[y * n + x] = 1; /* single solid cells, none touching */
    ck_assert_int_eq(ms_surface_set_obstacle_mask(s, m), MS_OK);
    bump(s, n, 0.01f);
    const double e0 = ms_surface_energy(s);
    for (int k = 0; k < 300; ++k) {
        ck_assert_int_eq(ms_surface_step(s, 1.0f / 60), MS_OK);
        ck_assert_msg(ms_surface_energy(s) <= 1.02 * e0, "frame %d: energy %g over %g", k,
                      ms_surface_energy(s), e0);
    }
    const float *h = ms_surface_height(s, NULL, NULL);
    for (int i = 0; i < n * n; ++i)
        if (m[i])
            ck_assert_msg(h[i] == 0.0f, "solid cell %d moved: %g", i, h[i]);
    free(m);
    uint64_t r = wave_hash(s);
    ms_surface_destroy(s);
    return r;
}

START_TEST(waves_an_obstacle_mask_of_isolated_single_cells)
{
    twice(isolated_obstacles);
}
END_TEST

/* ---- SPH, every pressure solver ------------------------------------------ */

static const char *const law_name[3] = {"ideal gas", "Tait", "DFSPH"};

/* A volume of law in an L x L x H box; NULL (and a skip recorded by the
 * caller) when the build refuses the solver. */
static ms_volume *sph(int law, float L, float H, float spacing, float courant)
{
    ms_volume_desc d = ms_volume_desc_default();
    d.domain_max[0] = d.domain_max[1] = L;
    d.domain_max[2] = H;
    d.spacing = spacing;
    d.smoothing_length = 2 * spacing;
    d.pressure = (ms_pressure)law;
    if (courant > 0)
        d.courant = courant;
    ms_volume *v = NULL;
    ms_status st = ms_volume_create(&d, &v);
    if (st == MS_ERR_UNSUPPORTED)
        return NULL;
    ck_assert_msg(st == MS_OK, "%s: %s", law_name[law], ms_last_error());
    return v;
}

typedef struct sph_check {
    double e_max;          /* J, the bound of kinetic + potential energy above the floor */
    int n;                 /* particles that must remain */
    const ms_shape *shape; /* a collider none may be inside (NULL: only the box) */
    float tol;             /* m, how far inside a wall or collider a particle may be */
} sph_check;

/* No NaN, none lost, none outside the box or inside the collider, energy
 * within its bound; returns the hash of the state. */
static uint64_t check_state(const ms_volume *v, const sph_check *c)
{
    int n = ms_volume_count(v);
    ck_assert_int_eq(n, c->n);
    ms_volume_desc d = ms_volume_get_desc(v);
    float *p = malloc(sizeof(float) * 3 * (size_t)n), *u = malloc(sizeof(float) * 3 * (size_t)n);
    ck_assert_int_eq(ms_volume_get_particles(v, p, u), MS_OK);
    assert_finite(p, 3 * (size_t)n, "position");
    assert_finite(u, 3 * (size_t)n, "velocity");
    ms_volume_info in = ms_volume_info_init();
    ms_volume_get_info(v, &in);
    double pe = 0;
    for (int i = 0; i < n; ++i) {
        for (int k = 0; k < 3; ++k)
            ck_assert_msg(p[3 * i + k] >= d.domain_min[k] - c->tol &&
                              p[3 * i + k] <= d.domain_max[k] + c->tol,
                          "particle %d at %g on axis %d is outside the box", i, p[3 * i + k], k);
        if (c->shape) {
            float nrm[3];
            float dist = ms_shape_distance(c->shape, p + 3 * i, nrm);
            ck_assert_msg(dist >= -c->tol, "particle %d is %g m inside the collider", i, -dist);
        }
        pe += in.particle_mass * 9.81 * (p[3 * i + 2] - d.domain_min[2]);
    }
    double e = ms_volume_kinetic_energy(v) + pe;
    ck_assert_msg(e <= c->e_max, "energy %g J over the %g J that entered", e, c->e_max);
    uint64_t h = fnv(fnv(1469598103934665603ull, p, sizeof(float) * 3 * (size_t)n), u,
                     sizeof(float) * 3 * (size_t)n);
    free(p);
    free(u);
    return h;
}

static double potential(const ms_volume *v)
{
    int n = ms_volume_count(v);
    float *p = malloc(sizeof(float) * 3 * (size_t)n);
    ms_volume_get_particles(v, p, NULL);
    ms_volume_info in = ms_volume_info_init();
    ms_volume_get_info(v, &in);
    double pe = 0;
    for (int i = 0; i < n; ++i)
        pe += in.particle_mass * 9.81 * p[3 * i + 2];
    free(p);
    return pe;
}

/* Elastic energy per kg stored at density ratio x = rho / rho0 (J/kg):
 * the integral of p / rho^2 of the law (ideal gas p = c^2 (rho - rho0);
 * Tait p = rho0 c^2 / 7 ((rho/rho0)^7 - 1)). */
static double elastic(int law, double c, double x)
{
    if (x <= 1)
        return 0;
    if (law == 0)
        return c * c * (log(x) + 1 / x - 1);
    return c * c / 7 * (pow(x, 6) / 6 + 1 / x - 7.0 / 6);
}

typedef uint64_t sph_case(int law, int *skipped);

static void sph_twice(sph_case *f, int law)
{
    int skipped = 0;
    uint64_t a = f(law, &skipped);
    if (skipped) {
        char why[160];
        snprintf(why, sizeof why, "pressure solver %s is not in this build (MS_ERR_UNSUPPORTED)",
                 law_name[law]);
        MS_SKIP(why);
    }
    uint64_t b = f(law, &skipped);
    ck_assert_msg(a == b, "%s: two runs differ", law_name[law]);
}

#define SOUND 20.0 /* m/s, the default sound speed of both laws */

static uint64_t dam_break(int law, int *skipped)
{
    /* the largest step the bounds allow: courant at the top of (0, 0.5] */
    ms_volume *v = sph(law, 0.5f, 0.3f, 0.025f, 0.5f);
    if (!v)
        return (uint64_t)(*skipped = 1);
    ck_assert_int_eq(ms_volume_fill_box(v, (float[3]){0, 0, 0}, (float[3]){0.15f, 0.2f, 0.25f}),
                     MS_OK);
    sph_check c = {.e_max = 1.02 * potential(v), .n = ms_volume_count(v), .tol = 1e-4f};
    for (int f = 0; f < 60; ++f) {
        ck_assert_int_eq(ms_volume_step(v, 1.0f / 60), MS_OK);
        check_state(v, &c);
    }
    uint64_t h = check_state(v, &c);
    ms_volume_destroy(v);
    return h;
}

START_TEST(sph_dam_break_at_the_largest_step_the_bounds_allow)
{
    sph_twice(dam_break, _i);
}
END_TEST

static uint64_t one_point(int law, int *skipped)
{
    ms_volume *v = sph(law, 0.6f, 0.6f, 0.03f, 0);
    if (!v)
        return (uint64_t)(*skipped = 1);
    enum { N = 300 };
    float p[3 * N];
    for (int i = 0; i < 3 * N; ++i)
        p[i] = 0.3f;
    ck_assert_int_eq(ms_volume_add_particles(v, N, p, NULL), MS_OK);
    ms_volume_info in = ms_volume_info_init();
    ms_volume_get_info(v, &in);
    const double h = 0.06, rho = N * in.particle_mass * 15 / (3.14159265358979 * h * h * h);
    const double mass = (double)N * in.particle_mass;
    sph_check c = {.e_max = potential(v) + mass * elastic(law, SOUND, rho / 1000) * 1.02,
                   .n = N,
                   .tol = 1e-4f};
    for (int f = 0; f < 60; ++f)
        ck_assert_int_eq(ms_volume_step(v, 1.0f / 60), MS_OK);
    uint64_t r = check_state(v, &c);
    ms_volume_destroy(v);
    return r;
}

START_TEST(sph_all_particles_at_one_point)
{
    sph_twice(one_point, _i);
}
END_TEST

static uint64_t packed_twice(int law, int *skipped)
{
    /* At rest density the lattice below fills 0.3 m. The weakly
     * compressible laws get a 0.3 m box: they settle compressed (the
     * elastic energy bound below holds because the box keeps them so).
     * DFSPH gets 0.6 m: in a 0.3 m box it could never reach rest density,
     * its constant-density target is unreachable and its solve pushed at
     * the c0 cap every sub-step, sloshing at ~c0 without decay (measured:
     * KE 1800 J at frame 30 as at frame 1). */
    const float tall = law == MS_PRESSURE_DFSPH ? 0.6f : 0.3f;
    ms_volume *v = sph(law, 0.3f, tall, 0.03f, 0);
    if (!v)
        return (uint64_t)(*skipped = 1);
    /* a lattice at spacing s / 2^(1/3): twice the particles per volume */
    const float s = 0.03f / cbrtf(2.0f);
    int n = 0;
    float *p = malloc(sizeof(float) * 3 * 20000);
    for (float z = 0.5f * s; z < 0.15f; z += s)
        for (float y = 0.5f * s; y < 0.3f; y += s)
            for (float x = 0.5f * s; x < 0.3f; x += s) {
                p[3 * n] = x;
                p[3 * n + 1] = y;
                p[3 * n + 2] = z;
                ++n;
            }
    ck_assert_int_eq(ms_volume_add_particles(v, n, p, NULL), MS_OK);
    free(p);
    ms_volume_info in = ms_volume_info_init();
    ms_volume_get_info(v, &in);
    const double mass = (double)n * in.particle_mass;
    sph_check c = {
        .e_max = 1.02 * (potential(v) + mass * elastic(law, SOUND, 2.0)), .n = n, .tol = 1e-4f};
    /* the released energy is dissipated: kinetic energy after half a
     * second under a tenth of the first frame's (measured 0.3-4.5 %) */
    const int frames = 30;
    double ke_first = 0.0;
    for (int f = 0; f < frames; ++f) {
        ck_assert_int_eq(ms_volume_step(v, 1.0f / 60), MS_OK);
        check_state(v, &c);
        if (f == 0)
            ke_first = ms_volume_kinetic_energy(v);
    }
    ck_assert_msg(ms_volume_kinetic_energy(v) < 0.1 * ke_first,
                  "%s: kinetic energy %g J after %d frames, %g J after the first", law_name[law],
                  ms_volume_kinetic_energy(v), frames, ke_first);
    /* it relaxes toward rest density: max rho/rho0 - 1 is 2.86 at the
     * first density pass (the lattice and its wall images) */
    ms_volume_get_info(v, &in);
    ck_assert_msg(in.max_density_error < 0.5f, "%s: max compression %g after %d frames",
                  law_name[law], in.max_density_error, frames);
    uint64_t r = check_state(v, &c);
    ms_volume_destroy(v);
    return r;
}

START_TEST(sph_a_box_packed_at_twice_the_rest_density)
{
    sph_twice(packed_twice, _i);
}
END_TEST

static uint64_t fast_obstacle(int law, int *skipped)
{
    ms_volume *v = sph(law, 1.0f, 0.4f, 0.04f, 0);
    if (!v)
        return (uint64_t)(*skipped = 1);
    ck_assert_int_eq(ms_volume_fill_box(v, (float[3]){0, 0.3f, 0}, (float[3]){1, 0.7f, 0.2f}),
                     MS_OK);
    ms_shape *ball = NULL;
    ck_assert_int_eq(ms_shape_create("sphere", "{\"radius\": 0.08}", &ball), MS_OK);
    float pos[3] = {-0.1f, 0.5f, 0.1f}, vel[3] = {20, 0, 0};
    ck_assert_int_eq(ms_shape_set_pose(ball, pos, vel), MS_OK);
    ck_assert_int_eq(ms_volume_add_collider(v, ball), MS_OK);
    /* energy enters through the obstacle: bounded by the work of a ball
     * ploughing at 20 m/s through water filling its whole path, generously
     * the kinetic energy of the water it sweeps taken to 2 x 20 m/s */
    const double swept = 3.14159 * 0.08 * 0.08 * 1.2 * 1000;
    sph_check c = {.e_max = potential(v) + 0.5 * swept * 40 * 40,
                   .n = ms_volume_count(v),
                   .shape = ball,
                   .tol = 0.02f};
    for (int f = 0; f < 4; ++f) { /* 1.2 m across in 60 ms, 15 ms frames */
        ck_assert_int_eq(ms_volume_step(v, 0.015f), MS_OK);
        pos[0] += 20 * 0.015f;
        ck_assert_int_eq(ms_shape_set_pose(ball, pos, vel), MS_OK);
        check_state(v, &c);
    }
    vel[0] = 0;
    ck_assert_int_eq(ms_shape_set_pose(ball, pos, vel), MS_OK);
    for (int f = 0; f < 20; ++f)
        ck_assert_int_eq(ms_volume_step(v, 1.0f / 60), MS_OK);
    uint64_t r = check_state(v, &c);
    ms_volume_destroy(v);
    ms_shape_destroy(ball);
    return r;
}

START_TEST(sph_an_obstacle_at_20_m_s)
{
    sph_twice(fast_obstacle, _i);
}
END_TEST

static uint64_t hitch(int law, int *skipped)
{
    ms_volume *v = sph(law, 0.4f, 0.4f, 0.025f, 0);
    if (!v)
        return (uint64_t)(*skipped = 1);
    ck_assert_int_eq(ms_volume_fill_box(v, (float[3]){0, 0, 0}, (float[3]){0.15f, 0.4f, 0.3f}),
                     MS_OK);
    sph_check c = {.e_max = 1.02 * potential(v), .n = ms_volume_count(v), .tol = 1e-4f};
    ck_assert_int_eq(ms_volume_step(v, 1.0f / 60), MS_OK);
    ck_assert_int_eq(ms_volume_step(v, 1.0f), MS_OK); /* the frame hitch */
    ms_volume_info in = ms_volume_info_init();
    ms_volume_get_info(v, &in);
    ck_assert_int_gt(in.substeps, 10);
    uint64_t r = check_state(v, &c);
    ms_volume_destroy(v);
    return r;
}

START_TEST(sph_a_one_second_frame_hitch)
{
    sph_twice(hitch, _i);
}
END_TEST

static uint64_t jerk(int law, int *skipped)
{
    ms_volume *v = sph(law, 0.5f, 0.4f, 0.04f, 0);
    if (!v)
        return (uint64_t)(*skipped = 1);
    ck_assert_int_eq(ms_volume_fill_box(v, (float[3]){0, 0, 0}, (float[3]){0.5f, 0.5f, 0.15f}),
                     MS_OK);
    /* in the container's frame a jerk at 10 g is a body force of 10 g on
     * the liquid: a push far wider than the box (w >= 0.98 inside it) */
    const float centre[3] = {0.25f, 0.25f, 0.1f}, accel[3] = {98.1f, 0, 0};
    ms_volume_info in = ms_volume_info_init();
    ms_volume_get_info(v, &in);
    const double mass = ms_volume_count(v) * (double)in.particle_mass;
    /* the work of 10 g over the box's width, plus the potential energy */
    sph_check c = {
        .e_max = potential(v) + mass * 98.1 * 0.5 * 1.02, .n = ms_volume_count(v), .tol = 1e-4f};
    for (int f = 0; f < 6; ++f) { /* 0.1 s of jerk */
        ck_assert_int_eq(ms_volume_push(v, centre, 100.0f, accel), MS_OK);
        ck_assert_int_eq(ms_volume_step(v, 1.0f / 60), MS_OK);
        check_state(v, &c);
    }
    for (int f = 0; f < 30; ++f)
        ck_assert_int_eq(ms_volume_step(v, 1.0f / 60), MS_OK);
    uint64_t r = check_state(v, &c);
    ms_volume_destroy(v);
    return r;
}

START_TEST(sph_the_container_jerked_at_10_g)
{
    sph_twice(jerk, _i);
}
END_TEST

static uint64_t sheet(int law, int *skipped)
{
    ms_volume *v = sph(law, 0.5f, 0.3f, 0.025f, 0);
    if (!v)
        return (uint64_t)(*skipped = 1);
    /* one particle thick, raised: it falls and lands */
    enum { SIDE = 20 };
    float p[3 * SIDE * SIDE];
    for (int j = 0; j < SIDE; ++j)
        for (int i = 0; i < SIDE; ++i) {
            p[3 * (j * SIDE + i)] = (i + 0.5f) * 0.025f;
            p[3 * (j * SIDE + i) + 1] = (j + 0.5f) * 0.025f;
            p[3 * (j * SIDE + i) + 2] = 0.1f;
        }
    ck_assert_int_eq(ms_volume_add_particles(v, SIDE * SIDE, p, NULL), MS_OK);
    sph_check c = {.e_max = 1.02 * potential(v), .n = ms_volume_count(v), .tol = 1e-4f};
    for (int f = 0; f < 30; ++f) {
        ck_assert_int_eq(ms_volume_step(v, 1.0f / 60), MS_OK);
        check_state(v, &c);
    }
    uint64_t r = check_state(v, &c);
    ms_volume_destroy(v);
    return r;
}

START_TEST(sph_a_sheet_one_particle_thick)
{
    sph_twice(sheet, _i);
}
END_TEST

static uint64_t top_viscosity(int law, int *skipped)
{
    ms_volume *v = sph(law, 0.3f, 0.3f, 0.03f, 0);
    if (!v)
        return (uint64_t)(*skipped = 1);
    ck_assert_int_eq(ms_volume_fill_box(v, (float[3]){0, 0, 0}, (float[3]){0.1f, 0.3f, 0.2f}),
                     MS_OK);
    /* the top of the documented range (desc.c: viscosity in [0, 1e6] Pa s):
     * the viscous bound takes the step down, it never blows up */
    ck_assert_int_eq(ms_volume_set_viscosity(v, 1e6f), MS_OK);
    sph_check c = {.e_max = 1.02 * potential(v), .n = ms_volume_count(v), .tol = 1e-4f};
    /* the viscous bound is then ~1e-6 s: 2 ms of simulated time is a few
     * thousand sub-steps (a 1/60 s frame would be ~20000) */
    for (int f = 0; f < 5; ++f) {
        ck_assert_msg(ms_volume_step(v, 4e-4f) == MS_OK, "%s", ms_last_error());
        check_state(v, &c);
    }
    ms_volume_info in = ms_volume_info_init();
    ms_volume_get_info(v, &in);
    ck_assert_str_eq(in.dt_limit, "viscous");
    uint64_t r = check_state(v, &c);
    ms_volume_destroy(v);
    return r;
}

START_TEST(sph_viscosity_at_its_top_bound)
{
    sph_twice(top_viscosity, _i);
}
END_TEST

/* ---- refusals: one test per bound -------------------------------------- */

START_TEST(refuse_a_wave_grid_of_zero_cell_size)
{
    ms_surface_desc d = ms_surface_desc_default();
    ms_surface *s = NULL;
    /* a value outside its domain: MS_ERR_INVALID_ARGUMENT (the library's rule) */
    d.dx = 0;
    MS_ASSERT_REFUSED(ms_surface_create(&d, &s), MS_ERR_INVALID_ARGUMENT, "dx 0 m");
    d.dx = NAN;
    MS_ASSERT_REFUSED(ms_surface_create(&d, &s), MS_ERR_INVALID_ARGUMENT, "dx");
    ck_assert_ptr_null(s);
}
END_TEST

START_TEST(refuse_a_wave_speed_that_is_not_positive)
{
    ms_surface_desc d = ms_surface_desc_default();
    ms_surface *s = NULL;
    /* a value outside its domain: MS_ERR_INVALID_ARGUMENT (the library's rule) */
    d.wave_speed = 0;
    MS_ASSERT_REFUSED(ms_surface_create(&d, &s), MS_ERR_INVALID_ARGUMENT, "wave_speed 0 m/s");
    d.wave_speed = INFINITY;
    MS_ASSERT_REFUSED(ms_surface_create(&d, &s), MS_ERR_INVALID_ARGUMENT, "wave_speed");
    ck_assert_ptr_null(s);
}
END_TEST

START_TEST(refuse_a_wave_step_over_max_substeps)
{
    ms_surface_desc d = ms_surface_desc_default();
    d.max_substeps = 10;
    ms_surface *s = NULL;
    ck_assert_int_eq(ms_surface_create(&d, &s), MS_OK);
    ms_surface_info in = ms_surface_info_init();
    ms_surface_get_info(s, &in);
    MS_ASSERT_REFUSED(ms_surface_step(s, 11 * in.max_dt), MS_ERR_UNSTABLE, "max_substeps 10");
    ck_assert_int_eq(ms_surface_step(s, 9.5f * in.max_dt), MS_OK); /* the state is intact */
    ms_surface_destroy(s);
}
END_TEST

START_TEST(refuse_an_sph_step_over_max_substeps)
{
    ms_volume_desc d = ms_volume_desc_default();
    d.max_substeps = 3;
    ms_volume *v = NULL;
    ck_assert_int_eq(ms_volume_create(&d, &v), MS_OK);
    ck_assert_int_eq(ms_volume_fill_box(v, (float[3]){0, 0, 0}, (float[3]){0.3f, 1, 0.5f}), MS_OK);
    MS_ASSERT_REFUSED(ms_volume_step(v, 1.0f), MS_ERR_UNSTABLE, "max_substeps 3");
    ms_volume_destroy(v);
}
END_TEST

START_TEST(refuse_an_n_time_below_the_cfl_bound)
{
    /* 256 cells over 1 m at 2 m/s: wave steps of at most 1.37 ms, so a
     * 1/60 s frame needs n_time >= 13; 1 is refused at creation */
    static const char json[] =
        "{\"domain\": {\"min\": [0,0,0], \"max\": [1,1,0.5]},"
        " \"volume\": {\"spacing\": 0.1, \"fill\": [{\"min\": [0,0,0], \"max\": [1,1,0.2]}]},"
        " \"surface\": {\"cells\": [256, 256], \"wave_speed\": 2.0},"
        " \"coupling\": {\"n_time\": 1}}";
    ms_scene *sc = NULL;
    ck_assert_int_eq(ms_scene_parse(json, strlen(json), &sc), MS_OK);
    ms_sim *sim = NULL;
    MS_ASSERT_REFUSED(ms_sim_create_from_scene(sc, 1, &sim), MS_ERR_UNSTABLE, "n_time 1");
    ck_assert_ptr_null(sim);
    ck_assert_ptr_nonnull(strstr(ms_last_error(), "n_time >= 13"));
    ms_scene_destroy(sc);

    /* ms_sim_create knows no frame: the first step refuses it, before any
     * state moves; a frame the bound allows then runs */
    ms_surface_desc sd = ms_surface_desc_default();
    sd.nx = sd.ny = 256;
    sd.dx = 1.0f / 256;
    sd.wave_speed = 2.0f;
    ms_sim_desc d = ms_sim_desc_default();
    d.surface = &sd;
    d.surface_substeps = 1;
    ck_assert_int_eq(ms_sim_create(&d, &sim), MS_OK);
    MS_ASSERT_REFUSED(ms_sim_step(sim, 1.0f / 60), MS_ERR_UNSTABLE, "n_time 1");
    ck_assert_int_eq(ms_sim_step(sim, 1e-3f), MS_OK);
    ms_sim_destroy(sim);
}
END_TEST

START_TEST(refuse_an_sph_frame_over_max_substeps_at_creation)
{
    /* courant 0.4, h 0.2 m, c0 20 m/s: sub-steps of at most 4 ms even at
     * rest, so a 1 s frame needs 250; max_substeps 100 cannot make it */
    static const char json[] =
        "{\"frame_dt\": 1.0, \"domain\": {\"min\": [0,0,0], \"max\": [1,1,1]},"
        " \"volume\": {\"spacing\": 0.1, \"smoothing_length\": 0.2, \"max_substeps\": 100,"
        "   \"fill\": [{\"min\": [0,0,0], \"max\": [1,1,0.3]}]}}";
    ms_scene *sc = NULL;
    ck_assert_int_eq(ms_scene_parse(json, strlen(json), &sc), MS_OK);
    ms_sim *sim = NULL;
    MS_ASSERT_REFUSED(ms_sim_create_from_scene(sc, 1, &sim), MS_ERR_UNSTABLE, "max_substeps 100");
    ck_assert_ptr_null(sim);
    ck_assert_ptr_nonnull(strstr(ms_last_error(), "250"));
    ms_scene_destroy(sc);
}
END_TEST

/* ---- coupled long runs (MS_TEST_LONG=1: make check-long) ------------------ */

static int long_tests(void)
{
    const char *e = getenv("MS_TEST_LONG");
    return e && e[0] == '1';
}

/* Top of the documented range of a coupling gain, read from the library
 * itself: the refusal of a value past every plausible top names the range
 * "[lo, hi]" (the sim's desc check, quoted by the scene reader). */
static double coupling_top(const char *key)
{
    char json[256];
    snprintf(json, sizeof json, "{\"surface\": {}, \"coupling\": {\"%s\": 1e30}}", key);
    ms_scene *sc = NULL;
    ck_assert_int_ne(ms_scene_parse(json, strlen(json), &sc), MS_OK);
    const char *msg = strrchr(ms_last_error(), '[');
    ck_assert_msg(msg != NULL, "no range in \"%s\"", ms_last_error());
    const char *comma = strchr(msg, ',');
    ck_assert_ptr_nonnull(comma);
    double top = strtod(comma + 1, NULL);
    ck_assert_msg(top > 0 && isfinite(top), "no top in \"%s\"", ms_last_error());
    return top;
}

static ms_scene *load_scene(const char *path, int n, const char *const *sets)
{
    ms_scene *sc = NULL;
    ms_status st = ms_scene_load_with_overrides(path, n, sets, &sc);
    ck_assert_msg(st == MS_OK, "%s", ms_last_error());
    return sc;
}

/* What a run may not do, checked once a simulated second:
 *  - a height outside the domain: the combined field within [0, domain
 *    height] (0: a dry floor; with a volume, waves add at most 0.8 of the
 *    local depth, so where the SPH field holds liquid the combined field
 *    stays above the floor);
 *  - a hole: a column of the SPH field that holds a particle a spacing or
 *    more above the floor extracts as dry (eq. 16's iso-spheres of radius
 *    h = 2 spacings around it reach the column's centre: it is wet);
 *  - lose a particle;
 *  - more kinetic energy than lifting all the liquid through the domain's
 *    height would take (M g H_domain: no effect of a shipped scene puts in
 *    a tenth of it), and, in a run of 30 s or more of a scene where nothing
 *    drives the liquid (no pointer, no moved container or obstacle, no
 *    boat or rain), any growth: the energy of the last tenth of the run no
 *    more than of the first.
 * Returns the hash of the last combined field. */
/* A hole: a column of the SPH field extracted dry although eq. 16 makes it
 * wet. phi (eq. 16, without the wall images, so never more than the
 * extraction's) is evaluated at the column's centre at the height of each
 * particle standing in the column; where it reaches the iso-level T the
 * column holds liquid by eq. 16 itself, and the field there must be > 0.
 * (A lone drop's sphere alone never reaches T: no liquid, not a hole.) */
static void assert_no_hole(const char *name, double t, const ms_volume *v, const float *H, int fx,
                           int fy, const ms_grid *g, int np, const float *const pos[3])
{
    const double R = v->K.h, T = v->iso_level;
    int *head = malloc(sizeof(int) * (size_t)fx * fy), *next = malloc(sizeof(int) * (size_t)np);
    ck_assert(head && next);
    for (int c = 0; c < fx * fy; ++c)
        head[c] = -1;
    for (int k = 0; k < np; ++k) {
        const int i = (int)((pos[0][k] - g->origin[0]) / g->dx);
        const int j = (int)((pos[1][k] - g->origin[1]) / g->dy);
        next[k] = -1;
        if (i < 0 || j < 0 || i >= fx || j >= fy)
            continue;
        next[k] = head[j * fx + i];
        head[j * fx + i] = k;
    }
    const int rx = (int)ceil(R / g->dx), ry = (int)ceil(R / g->dy);
    for (int j = 0; j < fy; ++j)
        for (int i = 0; i < fx; ++i) {
            if (head[j * fx + i] < 0 || H[j * fx + i] > 0.0f)
                continue;
            const double px = g->origin[0] + (i + 0.5) * g->dx;
            const double py = g->origin[1] + (j + 0.5) * g->dy;
            for (int k = head[j * fx + i]; k >= 0; k = next[k]) {
                double phi = 0.0;
                for (int b = MS_MAX(j - ry, 0); b <= MS_MIN(j + ry, fy - 1); ++b)
                    for (int a = MS_MAX(i - rx, 0); a <= MS_MIN(i + rx, fx - 1); ++a)
                        for (int q = head[b * fx + a]; q >= 0; q = next[q]) {
                            const double dx = pos[0][q] - px, dy = pos[1][q] - py;
                            const double dz = pos[2][q] - pos[2][k];
                            const double u = 1.0 - (dx * dx + dy * dy + dz * dz) / (R * R);
                            if (u > 0.0)
                                phi += sqrt(u);
                        }
                ck_assert_msg(phi < T,
                              "%s t=%.1f s: SPH cell (%d, %d) is dry, but eq. 16 at its centre "
                              "at z = %.3f m gives phi %.2f >= T %.2f",
                              name, t, i, j, pos[2][k], phi, T);
            }
        }
    free(head);
    free(next);
}

typedef struct run_limits {
    double h_max; /* m, the combined field's top bound */
    int driven;   /* the scene moves the liquid all along */
} run_limits;

/* The whole state at a check point: the combined field and every
 * particle's position and velocity. */
static uint64_t state_hash(const ms_sim *sim)
{
    int nx, ny, np;
    const float *h = ms_sim_height(sim, &nx, &ny);
    uint64_t hash = fnv(1469598103934665603ull, h, sizeof(float) * (size_t)nx * ny);
    const float *pos[3], *vel[3];
    if (ms_sim_particles(sim, &np, pos, vel) == MS_OK)
        for (int a = 0; a < 3; ++a) {
            hash = fnv(hash, pos[a], sizeof(float) * (size_t)np);
            hash = fnv(hash, vel[a], sizeof(float) * (size_t)np);
        }
    return hash;
}

/* Runs SECONDS of the scene on THREADS threads with the checks above;
 * states[k], when given, receives the state's hash at the k-th check point
 * (every 60 frames and the last frame), at most n_states of them. */
static void run_scene(const ms_scene *sc, int threads, double seconds, run_limits lim,
                      uint64_t *states, int n_states)
{
    ms_sim *sim = NULL;
    ck_assert_int_eq(ms_sim_create_from_scene(sc, threads, &sim), MS_OK);
    const char *name = ms_scene_name(sc);
    float dt = ms_scene_frame_dt(sc);
    long frames = lround(seconds / dt);
    ms_volume *vol = ms_sim_volume(sim);
    int n0 = vol ? ms_volume_count(vol) : 0;
    ms_volume_desc vd = vol ? ms_volume_get_desc(vol) : ms_volume_desc_default();
    const double mass =
        vol ? (double)vd.rest_density * vd.spacing * vd.spacing * vd.spacing * n0 : 0.0;
    const double ke_budget = mass * 9.81 * (vd.domain_max[2] - vd.domain_min[2]);
    const long tenth = frames / 10;
    double ke_first = 0.0, ke_last = 0.0, ke_max = 0.0;
    int checkpoint = 0;
    for (long f = 0; f < frames; ++f) {
        ms_status st = ms_sim_step(sim, dt);
        ck_assert_msg(st == MS_OK, "%s frame %ld: %s", name, f, ms_last_error());
        if (vol) {
            const double ke = ms_volume_kinetic_energy(vol);
            ke_max = fmax(ke_max, ke);
            if (f < tenth)
                ke_first += ke;
            if (f >= frames - tenth)
                ke_last += ke;
        }
        if (f % 60 != 59 && f != frames - 1)
            continue;
        const double t = (f + 1) * dt;
        int nx, ny;
        const float *h = ms_sim_height(sim, &nx, &ny);
        for (int i = 0; i < nx * ny; ++i)
            ck_assert_msg(isfinite(h[i]) && h[i] >= 0.0f && h[i] <= lim.h_max,
                          "%s t=%.1f s: combined height %g m outside [0, %g] m", name, t, h[i],
                          lim.h_max);
        if (vol) {
            int fx, fy, np;
            const float *H = ms_sim_volume_height(sim, &fx, &fy);
            const float *pos[3], *vel[3];
            ck_assert_int_eq(ms_sim_particles(sim, &np, pos, vel), MS_OK);
            ms_grid g;
            ck_assert_int_eq(ms_sim_field_grid(sim, MS_FIELD_VOLUME, &g), MS_OK);
            assert_no_hole(name, t, vol, H, fx, fy, &g, np, pos);
            ck_assert_msg(ke_max <= ke_budget, "%s t=%.1f s: kinetic energy %g J over M g H %g J",
                          name, t, ke_max, ke_budget);
        }
        if (states && checkpoint < n_states)
            states[checkpoint] = state_hash(sim);
        ++checkpoint;
    }
    if (vol) {
        ck_assert_int_eq(ms_volume_count(vol), n0);
        if (!lim.driven && seconds >= 30.0) /* the liquid has had time to settle */
            ck_assert_msg(ke_last <= ke_first,
                          "%s: nothing drives it, yet the kinetic energy grew from %g J (first "
                          "tenth) to %g J (last tenth)",
                          name, ke_first / tenth, ke_last / tenth);
        printf("%s, %d thread(s), %.0f s: E_kin max %.3g J (budget %.3g J), first tenth %.3g J, "
               "last tenth %.3g J\n",
               name, threads, seconds, ke_max, ke_budget, ke_first / (tenth ? tenth : 1),
               ke_last / (tenth ? tenth : 1));
    }
    ms_sim_destroy(sim);
}

/* The scene's domain height (m) and whether something drives its liquid,
 * from the scene text: a pointer (effects.drag), a container or an
 * obstacle with a path or a spin, or a boat or rain, whose waves move the
 * particles through the coupling. */
static run_limits scene_limits(const ms_scene *sc)
{
    const char *t = ms_scene_text(sc);
    run_limits lim = {.h_max = 1e9, .driven = 0};
    const char *dom = strstr(t, "\"domain\"");
    ck_assert_ptr_nonnull(dom);
    const char *mn = strstr(dom, "\"min\""), *mx = strstr(dom, "\"max\"");
    ck_assert(mn && mx);
    double a[3], b[3];
    ck_assert_int_eq(sscanf(strchr(mn, '['), "[%lf , %lf , %lf", &a[0], &a[1], &a[2]), 3);
    ck_assert_int_eq(sscanf(strchr(mx, '['), "[%lf , %lf , %lf", &b[0], &b[1], &b[2]), 3);
    lim.h_max = b[2] - a[2];
    lim.driven = strstr(t, "\"drag\"") || strstr(t, "\"container\"") || strstr(t, "\"spin\"") ||
                 strstr(t, "\"boat\"") || strstr(t, "\"rain\"") ||
                 (strstr(t, "\"obstacles\"") && strstr(t, "\"path\""));
    return lim;
}

static void top_gains(const char *path)
{
    char a[96], b[96];
    snprintf(a, sizeof a, "coupling.surface_from_volume=%.9g", coupling_top("surface_from_volume"));
    snprintf(b, sizeof b, "coupling.volume_from_surface=%.9g", coupling_top("volume_from_surface"));
    const char *sets[] = {a, b};
    ms_scene *sc = load_scene(path, 2, sets);
    run_scene(sc, 2, 600.0, scene_limits(sc), NULL, 0);
    ms_scene_destroy(sc);
}

START_TEST(coupled_fig1_top_gains_10_minutes)
{
    top_gains("data/scenes/fig1.json");
}
END_TEST

START_TEST(coupled_fig10_top_gains_10_minutes)
{
    top_gains("data/scenes/fig10.json");
}
END_TEST

/* Every shipped scene at 1 and 2 threads: the same bytes. The *_x10
 * scenes run 2 s (60 s of one takes over 10 min on 2 cores); the rest 60 s,
 * with the checks of run_scene, on two threads. One thread gives the same
 * bytes (test_determinism, every frame of an every-effect scene), so its
 * run repeats the two-thread one: it runs the first SAME_BYTES_S of each
 * scene (all of a *_x10 one), and its whole state (combined field,
 * particles) is the two-thread run's at every check point of that span. */
#define SAME_BYTES_S 10.0
#define MAX_CHECKPOINTS 64
START_TEST(coupled_every_shipped_scene_at_1_and_2_threads)
{
    DIR *d = opendir("data/scenes");
    ck_assert_ptr_nonnull(d);
    struct dirent *e;
    int n = 0;
    while ((e = readdir(d)) != NULL) {
        size_t len = strlen(e->d_name);
        if (len < 6 || strcmp(e->d_name + len - 5, ".json"))
            continue;
        char path[512];
        snprintf(path, sizeof path, "data/scenes/%s", e->d_name);
        ms_scene *sc = load_scene(path, 0, NULL);
        double secs = strstr(e->d_name, "_x10") ? 2.0 : 60.0;
        const run_limits lim = scene_limits(sc);
        uint64_t one[MAX_CHECKPOINTS], two[MAX_CHECKPOINTS];
        run_scene(sc, 2, secs, lim, two, MAX_CHECKPOINTS);
        /* whole blocks of 60 frames, so its check points are the other's */
        const double dt = ms_scene_frame_dt(sc);
        const long blocks = lround(ceil(SAME_BYTES_S / dt / 60.0 - 1e-6));
        const double same_s = fmin(secs, (double)blocks * 60.0 * dt);
        run_scene(sc, 1, same_s, lim, one, MAX_CHECKPOINTS);
        const long frames = lround(same_s / dt);
        const int points = (int)MS_MIN((frames + 59) / 60, MAX_CHECKPOINTS);
        ck_assert_int_gt(points, 0);
        for (int k = 0; k < points; ++k)
            ck_assert_msg(one[k] == two[k], "%s: 1 and 2 threads differ at frame %ld", e->d_name,
                          MS_MIN(60L * (k + 1), frames));
        ms_scene_destroy(sc);
        ++n;
    }
    closedir(d);
    ck_assert_int_ge(n, 15);
}
END_TEST

/* A pool at rest stays at rest: 2000 particles filled level to 0.25 m in
 * a 1 m box (fig1's pool without the pointer), a 50 x 50 SPH field under
 * a 200 x 200 wave grid, both couplings at fig1's gains, one thread (the
 * two-thread split gives the same bytes: test_determinism), for each
 * pressure law, 10 simulated minutes. The fill's cubic lattice is not the
 * liquid's resting packing: unstable under its own hydrostatic pressure,
 * it collapses into a disordered packing in the first seconds, sloshing
 * as it does. The scene starts it settled instead (volume.settle, 5 s of
 * ms_volume_settle's damped steps before the first frame). SETTLE_S is
 * when the checks start. From then on, every second: no cell of the
 * combined field below 0.9 of the settled level L (a hole), the mean
 * within 1 % of L, the spread (highest - lowest cell) under
 * spread_max; and the volume's kinetic energy averaged over the last
 * minute no higher than over the first minute after SETTLE_S. The spread
 * left is the settled packing's own, frozen: the height of a column's
 * particles (their volume over a 0.2 m disc) varies by 0.84 mm rms, and
 * eq. 16's field follows it (correlation 0.84) at wavelengths of 0.3 m
 * and more (0.79 of its 0.85 mm rms), so neither the iso-level nor eq.
 * 18's smoothing could take it out without taking out waves the SPH field
 * resolves. Measured worst spreads: 5.3 mm (ideal gas), 6.0 mm (Tait),
 * 4.7 mm (DFSPH), against 9.1, 6.1 and 7.9-9.9 mm from the lattice as
 * filled; the bounds leave about 1 mm. */
#define SETTLE_S 3.0
static const char still_pool_scene[] =
    "{\"name\": \"still_pool\", \"frame_dt\": 0.016667, \"duration\": 600,\n"
    " \"domain\": {\"min\": [0, 0, 0], \"max\": [1, 1, 0.5]},\n"
    " \"volume\": {\"spacing\": 0.05, \"gas_constant\": 100, \"viscosity\": 0.5,\n"
    "   \"pressure\": \"%s\", \"settle\": 5,\n"
    "   \"fill\": [{\"min\": [0, 0, 0], \"max\": [1, 1, 0.25]}], \"field\": [50, 50]},\n"
    " \"surface\": {\"cells\": [200, 200], \"wave_speed\": 0.2, \"damping\": 0.8},\n"
    " \"coupling\": {\"n_time\": 0, \"surface_from_volume\": 0.05,\n"
    "   \"volume_from_surface\": 0.3},\n"
    " \"effects\": {\"spray\": {}}}";

START_TEST(a_pool_at_rest_stays_at_rest_for_10_minutes)
{
    static const char *const laws[] = {"ideal_gas", "tait", "dfsph"};
    static const double spread_max[] = {0.0065, 0.007, 0.006}; /* m */
    char json[1024];
    snprintf(json, sizeof json, still_pool_scene, laws[_i]);
    ms_scene *sc = NULL;
    ck_assert_msg(ms_scene_parse(json, strlen(json), &sc) == MS_OK, "%s", ms_last_error());
    ms_sim *sim = NULL;
    ck_assert_int_eq(ms_sim_create_from_scene(sc, 1, &sim), MS_OK);
    const float dt = ms_scene_frame_dt(sc);
    const long frames = lround(600.0 / dt), settle = lround(SETTLE_S / dt);
    const long minute = lround(60.0 / dt);
    double level = 0.0, ke_first = 0.0, ke_last = 0.0, worst_spread = 0.0, lowest = 1e9;
    ms_volume *v = ms_sim_volume(sim);
    for (long f = 1; f <= frames; ++f) {
        ck_assert_msg(ms_sim_step(sim, dt) == MS_OK, "%s frame %ld: %s", laws[_i], f,
                      ms_last_error());
        const double ke = ms_volume_kinetic_energy(v);
        if (f > settle && f <= settle + minute)
            ke_first += ke / (double)minute;
        if (f > frames - minute)
            ke_last += ke / (double)minute;
        if (f < settle || f % 60)
            continue;
        int nx, ny;
        const float *h = ms_sim_height(sim, &nx, &ny);
        double lo = 1e9, hi = -1e9, mean = 0.0;
        for (int k = 0; k < nx * ny; ++k) {
            lo = fmin(lo, h[k]);
            hi = fmax(hi, h[k]);
            mean += h[k] / (double)(nx * ny);
        }
        if (f == settle) {
            level = mean;
            continue;
        }
        worst_spread = fmax(worst_spread, hi - lo);
        lowest = fmin(lowest, lo);
        ck_assert_msg(lo >= 0.9 * level,
                      "%s t = %.0f s: a cell at %.4f m, under 0.9 of the "
                      "settled level %.4f m",
                      laws[_i], f * dt, lo, level);
        ck_assert_msg(fabs(mean - level) <= 0.01 * level,
                      "%s t = %.0f s: mean level %.4f m, "
                      "more than 1 %% from the settled %.4f m",
                      laws[_i], f * dt, mean, level);
        ck_assert_msg(hi - lo <= spread_max[_i], "%s t = %.0f s: spread %.4f m over %.4f m",
                      laws[_i], f * dt, hi - lo, spread_max[_i]);
    }
    printf("still pool, %s, 10 min: level %.4f m, worst spread %.2f mm, lowest cell %.4f m, "
           "E_kin first minute %.3g J, last minute %.3g J\n",
           laws[_i], level, 1e3 * worst_spread, lowest, ke_first, ke_last);
    ck_assert_msg(ke_last <= ke_first,
                  "%s: kinetic energy grew from %.3g J (first minute) to "
                  "%.3g J (last minute)",
                  laws[_i], ke_first, ke_last);
    /* still water throws no spray (the settling included) */
    ms_stats stats = ms_stats_init();
    ms_sim_get_stats(sim, &stats);
    ck_assert_msg(stats.spray_emitted == 0, "%s: the pool at rest threw %ld spray droplets",
                  laws[_i], stats.spray_emitted);
    ms_sim_destroy(sim);
    ms_scene_destroy(sc);
}
END_TEST

/* Spray stays bounded in a 10-minute stir: a paddle (25 cm) spinning at
 * 5 rad/s and carried to and fro at 0.5 m/s in a 50 cm pool of 867
 * particles keeps throwing spray, which falls back (a paddle that only
 * spins stops throwing within minutes: the water turns with it, and
 * neither the trapped-air nor the wave-crest potential is left). Every
 * simulated second: at most the budget in flight, every droplet finite,
 * inside the domain's x-y extent and above its floor, the foam finite and
 * in [0, 1]; once past the start's burst (10 s) the budget is never
 * reached. The paddle keeps the water fast, so it keeps throwing: the
 * last minute emits at least half what the second did (measured: 28207
 * droplets in the second minute, 27657 in the last). Small, so that its 36000 frames take about 2.5 min
 * of one core. */
static const char spray_stir_scene[] =
    "{\"name\": \"spray_stir\", \"frame_dt\": 0.016667,\n"
    " \"domain\": {\"min\": [0, 0, 0], \"max\": [0.5, 0.5, 0.25]},\n"
    " \"volume\": {\"spacing\": 0.03, \"gas_constant\": 100, \"viscosity\": 0.5,\n"
    "   \"fill\": [{\"min\": [0, 0, 0], \"max\": [0.5, 0.5, 0.08]}], \"field\": [25, 25]},\n"
    " \"surface\": {\"cells\": [64, 64], \"wave_speed\": 0.25, \"damping\": 0.8},\n"
    " \"coupling\": {\"surface_from_volume\": 0.05, \"volume_from_surface\": 0.3},\n"
    " \"obstacles\": [{\"shape\": \"box\", \"params\": {\"size\": [0.25, 0.03, 0.3], "
    "\"radius\": 0.005},\n"
    "   \"position\": [0.25, 0.25, 0.1], \"spin\": [0, 0, 5],\n"
    "   \"path\": {\"points\": [[0.17, 0.25, 0.1], [0.33, 0.25, 0.1]], \"speed\": 0.5, "
    "\"loop\": true}}],\n"
    " \"effects\": {\"spray\": {\"budget\": 2048, \"rate\": [100, 100]}}}";

START_TEST(spray_stays_bounded_in_a_10_minute_stir)
{
    ms_scene *sc = NULL;
    ck_assert_msg(ms_scene_parse(spray_stir_scene, strlen(spray_stir_scene), &sc) == MS_OK, "%s",
                  ms_last_error());
    ms_sim *sim = NULL;
    ck_assert_int_eq(ms_sim_create_from_scene(sc, 1, &sim), MS_OK);
    const float dt = ms_scene_frame_dt(sc);
    /* whole seconds of frames: the minutes' counts are taken at the
     * per-second checks */
    const long second = lround(1.0 / dt), minute = 60 * second, frames = 10 * minute;
    long emitted_second_minute = 0, emitted_last_minute = 0, at = 0;
    int most_after_start = 0;
    for (long f = 1; f <= frames; ++f) {
        ck_assert_msg(ms_sim_step(sim, dt) == MS_OK, "frame %ld: %s", f, ms_last_error());
        if (f % second)
            continue;
        ms_stats st = ms_stats_init();
        ms_sim_get_stats(sim, &st);
        if (f == minute)
            at = st.spray_emitted;
        if (f == 2 * minute)
            emitted_second_minute = st.spray_emitted - at;
        if (f == frames - minute)
            at = st.spray_emitted;
        if (f == frames)
            emitted_last_minute = st.spray_emitted - at;
        int n, nx, ny;
        const float *p = ms_sim_spray(sim, &n);
        ck_assert_int_le(n, 2048);
        if (f > 10 * second)
            most_after_start = MS_MAX(most_after_start, n);
        for (int i = 0; i < n; ++i)
            ck_assert_msg(isfinite(p[3 * i + 2]) && p[3 * i] >= 0 && p[3 * i] <= 0.5f &&
                              p[3 * i + 1] >= 0 && p[3 * i + 1] <= 0.5f && p[3 * i + 2] >= 0,
                          "t = %.0f s: droplet %d at (%g, %g, %g) m", f * dt, i, p[3 * i],
                          p[3 * i + 1], p[3 * i + 2]);
        const float *foam = ms_sim_foam(sim, &nx, &ny);
        for (int c = 0; c < nx * ny; ++c)
            ck_assert_msg(foam[c] >= 0.0f && foam[c] <= 1.0f, "t = %.0f s: foam %g", f * dt,
                          foam[c]);
    }
    printf("spray stir, 10 min: at most %d droplets in flight after 10 s (budget 2048), "
           "%ld emitted in the second minute, %ld in the last\n",
           most_after_start, emitted_second_minute, emitted_last_minute);
    fflush(stdout);
    ck_assert_int_lt(most_after_start, 2048);
    ck_assert_msg(emitted_second_minute > 0 && 2 * emitted_last_minute >= emitted_second_minute,
                  "the stir threw %ld droplets in its second minute, %ld in its last",
                  emitted_second_minute, emitted_last_minute);
    ms_sim_destroy(sim);
    ms_scene_destroy(sc);
}
END_TEST

static Suite *stability_suite(void)
{
    Suite *s = suite_create("stability");
    TCase *w = tcase_create("waves");
    tcase_set_timeout(w, 120);
    tcase_add_test(w, waves_100000_steps_at_exactly_the_largest_stable_courant);
    tcase_add_test(w, waves_a_step_100x_over_the_bound_is_substepped);
    tcase_add_test(w, waves_a_drop_on_one_cell_every_step_for_10000_steps);
    tcase_add_test(w, waves_a_speed_map_with_a_100_to_1_jump);
    tcase_add_test(w, waves_a_damping_map_with_full_and_no_damping_side_by_side);
    tcase_add_test(w, waves_an_obstacle_mask_of_isolated_single_cells);
    suite_add_tcase(s, w);
    TCase *p = tcase_create("sph");
    tcase_set_timeout(p, 180);
    /* _i: the pressure solver, every one the library has */
    tcase_add_loop_test(p, sph_dam_break_at_the_largest_step_the_bounds_allow, 0, 3);
    tcase_add_loop_test(p, sph_all_particles_at_one_point, 0, 3);
    tcase_add_loop_test(p, sph_a_box_packed_at_twice_the_rest_density, 0, 3);
    tcase_add_loop_test(p, sph_an_obstacle_at_20_m_s, 0, 3);
    tcase_add_loop_test(p, sph_a_one_second_frame_hitch, 0, 3);
    tcase_add_loop_test(p, sph_the_container_jerked_at_10_g, 0, 3);
    tcase_add_loop_test(p, sph_a_sheet_one_particle_thick, 0, 3);
    tcase_add_loop_test(p, sph_viscosity_at_its_top_bound, 0, 3);
    suite_add_tcase(s, p);
    TCase *r = tcase_create("refusals");
    tcase_add_test(r, refuse_a_wave_grid_of_zero_cell_size);
    tcase_add_test(r, refuse_a_wave_speed_that_is_not_positive);
    tcase_add_test(r, refuse_a_wave_step_over_max_substeps);
    tcase_add_test(r, refuse_an_sph_step_over_max_substeps);
    tcase_add_test(r, refuse_an_n_time_below_the_cfl_bound);
    tcase_add_test(r, refuse_an_sph_frame_over_max_substeps_at_creation);
    suite_add_tcase(s, r);
    if (long_tests()) {
        /* two cases, which `make check-long` runs side by side on 2 cores */
        TCase *l = tcase_create("coupled_top_gains");
        tcase_set_timeout(l, 3600);
        tcase_add_test(l, coupled_fig1_top_gains_10_minutes);
        tcase_add_test(l, coupled_fig10_top_gains_10_minutes);
        suite_add_tcase(s, l);
        TCase *e = tcase_create("coupled_every_scene");
        tcase_set_timeout(e, 3600);
        tcase_add_test(e, coupled_every_shipped_scene_at_1_and_2_threads);
        suite_add_tcase(s, e);
        TCase *still = tcase_create("still_pool");
        tcase_set_timeout(still, 3600);
        tcase_add_loop_test(still, a_pool_at_rest_stays_at_rest_for_10_minutes, 0, 3);
        suite_add_tcase(s, still);
        TCase *spray = tcase_create("spray_stir");
        tcase_set_timeout(spray, 3600);
        tcase_add_test(spray, spray_stays_bounded_in_a_10_minute_stir);
        suite_add_tcase(s, spray);
    }
    return s;
}

int main(void)
{
    return ms_test_run(stability_suite());
}
