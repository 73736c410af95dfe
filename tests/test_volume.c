/* Volume: the SPH liquid of paper section 3.3 (ms_volume).
 *
 * Physics asserted: lattice density, hydrostatic pressure rho0 g d, the
 * Martin & Moyce (1952) dam break, momentum conservation, flat extraction of
 * a still liquid, adaptive smoothing (eq. 18), the hard cases (all particles
 * at one point, a 100x viscosity jump, 10 000 sub-steps at the largest
 * allowed step, a 1 s frame hitch, particles outside the domain), same bytes
 * for 1 and 2 threads, and every refusal; the same for DFSPH (hydrostatic
 * tank, dam break, settling energy, determinism). The colliders are in
 * tests/test_colliders.c.
 *
 * Sizes are kept small so the suite runs in seconds; MS_TEST_LONG=1 (CI may
 * set it) runs the long variants (finer dam break, 10 000 steps with more
 * particles).
 */
#include <check.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>

#include "modesplit/modesplit.h"
#include "support.h"
#include "support_volume.h"
#include "volume/extract.h"
#include "volume/passes.h"
#include "volume/volume_internal.h"

/* Kinetic plus gravitational energy (J), potential from the domain floor. */
static double mechanical_energy(const ms_volume *v, const ms_volume_desc *d)
{
    int n = ms_volume_count(v);
    float *p = malloc(sizeof(float) * 3 * (size_t)(n + 1));
    ms_volume_get_particles(v, p, NULL);
    ms_volume_info in = ms_volume_info_init();
    ms_volume_get_info(v, &in);
    double pot = 0.0;
    for (int i = 0; i < n; ++i)
        for (int k = 0; k < 3; ++k)
            pot -= (double)in.particle_mass * d->gravity[k] * (p[3 * i + k] - d->domain_min[k]);
    free(p);
    return ms_volume_kinetic_energy(v) + pot;
}

/* ---------------------------------------------------------------- desc */

START_TEST(default_desc_is_valid)
{
    ms_volume_desc d = ms_volume_desc_default();
    ms_volume *v = make(&d);
    ck_assert_int_eq(ms_volume_count(v), 0);
    ms_volume_info in = ms_volume_info_init();
    ms_volume_get_info(v, &in);
    ck_assert_float_eq_tol(in.sound_speed, 20.0f, 1e-4f);
    ck_assert(in.particle_mass > 0.0f);
    ck_assert(in.bytes > 0);
    ck_assert_int_eq(in.threads, 1);
    ms_volume_desc back = ms_volume_get_desc(v);
    ck_assert_int_eq(memcmp(&back, &d, sizeof d), 0);
    ms_volume_destroy(v);
    ms_volume_destroy(NULL);
}
END_TEST

#define REFUSE_DESC(field_stmt, status, word)                        \
    do {                                                             \
        ms_volume_desc d_ = ms_volume_desc_default();                \
        field_stmt;                                                  \
        ms_volume *v_ = (ms_volume *)1;                              \
        MS_ASSERT_REFUSED(ms_volume_create(&d_, &v_), status, word); \
        ck_assert_ptr_null(v_);                                      \
    } while (0)

START_TEST(bad_descs_are_refused_with_a_sentence)
{
    ms_volume *v = NULL;
    MS_ASSERT_REFUSED(ms_volume_create(NULL, &v), MS_ERR_INVALID_ARGUMENT, "desc");
    ms_volume_desc ok = ms_volume_desc_default();
    MS_ASSERT_REFUSED(ms_volume_create(&ok, NULL), MS_ERR_INVALID_ARGUMENT, "out");
    REFUSE_DESC(d_.domain_min[1] = NAN, MS_ERR_INVALID_ARGUMENT, "finite");
    REFUSE_DESC(d_.domain_max[0] = INFINITY, MS_ERR_INVALID_ARGUMENT, "finite");
    REFUSE_DESC(d_.domain_max[2] = 0.0f, MS_ERR_INVALID_ARGUMENT, "empty");
    REFUSE_DESC(d_.domain_max[0] = 2e6f, MS_ERR_INVALID_ARGUMENT, "1e6");
    REFUSE_DESC(d_.spacing = 0.0f, MS_ERR_INVALID_ARGUMENT, "spacing");
    REFUSE_DESC(d_.spacing = NAN, MS_ERR_INVALID_ARGUMENT, "spacing");
    REFUSE_DESC(d_.smoothing_length = 0.03f, MS_ERR_INVALID_ARGUMENT, "below spacing");
    REFUSE_DESC(d_.smoothing_length = 0.2f, MS_ERR_INVALID_ARGUMENT, "4 x spacing");
    REFUSE_DESC((d_.domain_max[1] = 0.15f), MS_ERR_INVALID_ARGUMENT, "2 h");
    REFUSE_DESC((d_.domain_max[0] = 1000.0f, d_.domain_max[1] = 1000.0f), MS_ERR_INVALID_ARGUMENT,
                "neighbour cells");
    REFUSE_DESC(d_.rest_density = 0.0f, MS_ERR_INVALID_ARGUMENT, "rest_density");
    REFUSE_DESC(d_.rest_density = NAN, MS_ERR_INVALID_ARGUMENT, "rest_density");
    REFUSE_DESC(d_.viscosity = -1.0f, MS_ERR_INVALID_ARGUMENT, "viscosity");
    REFUSE_DESC(d_.viscosity = NAN, MS_ERR_INVALID_ARGUMENT, "viscosity");
    REFUSE_DESC(d_.gravity[2] = -2000.0f, MS_ERR_INVALID_ARGUMENT, "gravity");
    REFUSE_DESC(d_.gravity[0] = NAN, MS_ERR_INVALID_ARGUMENT, "gravity");
    REFUSE_DESC(d_.gas_constant = 0.0f, MS_ERR_INVALID_ARGUMENT, "gas_constant");
    REFUSE_DESC(d_.gas_constant = 1e9f, MS_ERR_INVALID_ARGUMENT, "gas_constant");
    REFUSE_DESC((d_.pressure = MS_PRESSURE_TAIT, d_.sound_speed = -1.0f), MS_ERR_INVALID_ARGUMENT,
                "sound_speed");
    REFUSE_DESC((d_.pressure = MS_PRESSURE_TAIT, d_.sound_speed = 2e4f), MS_ERR_INVALID_ARGUMENT,
                "sound_speed");
    REFUSE_DESC(d_.sound_speed = NAN, MS_ERR_INVALID_ARGUMENT, "sound_speed");
    REFUSE_DESC(d_.gas_constant = NAN, MS_ERR_INVALID_ARGUMENT, "gas_constant");
    REFUSE_DESC((d_.pressure = MS_PRESSURE_DFSPH, d_.density_kernel = MS_DENSITY_POLY6),
                MS_ERR_INVALID_ARGUMENT, "poly6");
    REFUSE_DESC((d_.pressure = MS_PRESSURE_DFSPH, d_.sound_speed = 0.0f), MS_ERR_INVALID_ARGUMENT,
                "sound_speed");
    REFUSE_DESC(d_.max_density_error = 0.0f, MS_ERR_INVALID_ARGUMENT, "max_density_error");
    REFUSE_DESC(d_.max_density_error = 0.2f, MS_ERR_INVALID_ARGUMENT, "(0, 0.1]");
    REFUSE_DESC(d_.max_density_error = NAN, MS_ERR_INVALID_ARGUMENT, "max_density_error");
    REFUSE_DESC(d_.max_divergence_error = -1.0f, MS_ERR_INVALID_ARGUMENT, "max_divergence_error");
    REFUSE_DESC(d_.max_divergence_error = INFINITY, MS_ERR_INVALID_ARGUMENT,
                "max_divergence_error");
    REFUSE_DESC(d_.max_density_iterations = 0, MS_ERR_INVALID_ARGUMENT, "max_density_iterations");
    REFUSE_DESC(d_.max_density_iterations = 10001, MS_ERR_INVALID_ARGUMENT, "10000");
    REFUSE_DESC(d_.max_divergence_iterations = -1, MS_ERR_INVALID_ARGUMENT,
                "max_divergence_iterations");
    REFUSE_DESC(d_.max_divergence_iterations = 10001, MS_ERR_INVALID_ARGUMENT,
                "max_divergence_iterations");
    REFUSE_DESC(d_.pressure = (ms_pressure)7, MS_ERR_INVALID_ARGUMENT, "ms_pressure");
    REFUSE_DESC(d_.max_particles = 0, MS_ERR_INVALID_ARGUMENT, "max_particles");
    REFUSE_DESC(d_.courant = 0.0f, MS_ERR_INVALID_ARGUMENT, "courant");
    REFUSE_DESC(d_.courant = 0.6f, MS_ERR_INVALID_ARGUMENT, "0.5");
    REFUSE_DESC(d_.max_substeps = 0, MS_ERR_INVALID_ARGUMENT, "max_substeps");
    REFUSE_DESC(d_.threads = 0, MS_ERR_INVALID_ARGUMENT, "threads");
    REFUSE_DESC(d_.threads = 65, MS_ERR_INVALID_ARGUMENT, "threads");
    REFUSE_DESC(d_.smooth_steps = -1, MS_ERR_INVALID_ARGUMENT, "smooth_steps");
    REFUSE_DESC(d_.smooth_energy = 0.0f, MS_ERR_INVALID_ARGUMENT, "smooth_energy");
    REFUSE_DESC(d_.density_kernel = (ms_density_kernel)5, MS_ERR_INVALID_ARGUMENT,
                "density_kernel");
}
END_TEST

START_TEST(bad_calls_are_refused_with_a_sentence)
{
    ms_volume_desc d = box_desc(0.4f, 0.4f, 0.4f, 0.04f);
    d.max_particles = 100;
    ms_volume *v = make(&d);
    float lo[3] = {0, 0, 0}, hi[3] = {0.4f, 0.4f, 0.4f};
    MS_ASSERT_REFUSED(ms_volume_fill_box(v, lo, hi), MS_ERR_INVALID_ARGUMENT, "max_particles");
    ck_assert_int_eq(ms_volume_count(v), 0);
    float flat[3] = {0.4f, 0.4f, 0.0f};
    MS_ASSERT_REFUSED(ms_volume_fill_box(v, lo, flat), MS_ERR_INVALID_ARGUMENT, "empty");
    float nanbox[3] = {NAN, 0.1f, 0.1f};
    MS_ASSERT_REFUSED(ms_volume_fill_box(v, lo, nanbox), MS_ERR_INVALID_ARGUMENT, "finite");
    MS_ASSERT_REFUSED(ms_volume_fill_box(NULL, lo, hi), MS_ERR_INVALID_ARGUMENT, "fill_box");

    float p[6] = {0.1f, 0.1f, 0.1f, 0.2f, 0.5f, 0.2f}; /* the second is outside */
    MS_ASSERT_REFUSED(ms_volume_add_particles(v, 2, p, NULL), MS_ERR_INVALID_ARGUMENT,
                      "outside the domain");
    ck_assert_int_eq(ms_volume_count(v), 0); /* refused as a whole */
    float q[3] = {0.1f, NAN, 0.1f};
    MS_ASSERT_REFUSED(ms_volume_add_particles(v, 1, q, NULL), MS_ERR_INVALID_ARGUMENT, "finite");
    float u[3] = {INFINITY, 0, 0};
    MS_ASSERT_REFUSED(ms_volume_add_particles(v, 1, p, u), MS_ERR_INVALID_ARGUMENT, "velocity");
    MS_ASSERT_REFUSED(ms_volume_add_particles(v, -1, p, NULL), MS_ERR_INVALID_ARGUMENT, "negative");
    MS_ASSERT_REFUSED(ms_volume_add_particles(v, 1, NULL, NULL), MS_ERR_INVALID_ARGUMENT, "NULL");
    MS_ASSERT_REFUSED(ms_volume_add_particles(v, 101, p, NULL), MS_ERR_INVALID_ARGUMENT,
                      "max_particles");
    ck_assert_int_eq(ms_volume_add_particles(v, 1, p, NULL), MS_OK);
    ck_assert_int_eq(ms_volume_count(v), 1);

    MS_ASSERT_REFUSED(ms_volume_step(v, -1.0f), MS_ERR_INVALID_ARGUMENT, "dt");
    MS_ASSERT_REFUSED(ms_volume_step(v, 11.0f), MS_ERR_INVALID_ARGUMENT, "[0, 10]");
    MS_ASSERT_REFUSED(ms_volume_step(v, NAN), MS_ERR_INVALID_ARGUMENT, "dt");
    MS_ASSERT_REFUSED(ms_volume_step(NULL, 0.01f), MS_ERR_INVALID_ARGUMENT, "NULL");

    float out[16];
    MS_ASSERT_REFUSED(ms_volume_extract_height(v, 0, 4, out), MS_ERR_INVALID_ARGUMENT, "4096");
    MS_ASSERT_REFUSED(ms_volume_extract_height(v, 4, 5000, out), MS_ERR_INVALID_ARGUMENT, "4096");
    MS_ASSERT_REFUSED(ms_volume_extract_height(v, 4, 4, NULL), MS_ERR_INVALID_ARGUMENT, "out");

    float c[3] = {0.2f, 0.2f, 0.2f}, vel[3] = {1, 0, 0};
    MS_ASSERT_REFUSED(ms_volume_drag(v, c, 0.0f, vel, 1.0f), MS_ERR_INVALID_ARGUMENT, "radius");
    MS_ASSERT_REFUSED(ms_volume_drag(v, c, 0.1f, vel, -1.0f), MS_ERR_INVALID_ARGUMENT, "strength");
    MS_ASSERT_REFUSED(ms_volume_drag(v, NULL, 0.1f, vel, 1.0f), MS_ERR_INVALID_ARGUMENT, "centre");
    float bad[3] = {NAN, 0, 0};
    MS_ASSERT_REFUSED(ms_volume_push(v, c, 0.1f, bad), MS_ERR_INVALID_ARGUMENT, "acceleration");
    for (int k = 0; k < 16; ++k)
        ck_assert_int_eq(ms_volume_push(v, c, 0.1f, vel), MS_OK);
    MS_ASSERT_REFUSED(ms_volume_push(v, c, 0.1f, vel), MS_ERR_INVALID_ARGUMENT, "at most 16");
    step(v, 0.001f); /* the step clears them */
    ck_assert_int_eq(ms_volume_push(v, c, 0.1f, vel), MS_OK);

    MS_ASSERT_REFUSED(ms_volume_set_viscosity(v, -2.0f), MS_ERR_INVALID_ARGUMENT, "viscosity");
    MS_ASSERT_REFUSED(ms_volume_remove_box(v, NULL, hi, NULL), MS_ERR_INVALID_ARGUMENT, "lo");

    float w[4] = {0};
    ms_grid g = {.nx = 2, .ny = 2, .dx = 0.2f, .dy = 0.2f};
    MS_ASSERT_REFUSED(ms_volume_adapt_to_waves(v, w, &g, 1.5f), MS_ERR_INVALID_ARGUMENT, "gain");
    ms_grid bg = g;
    bg.dx = 0.0f;
    MS_ASSERT_REFUSED(ms_volume_adapt_to_waves(v, w, &bg, 0.5f), MS_ERR_INVALID_ARGUMENT, "grid");
    float wn[4] = {0, NAN, 0, 0};
    MS_ASSERT_REFUSED(ms_volume_adapt_to_waves(v, wn, &g, 0.5f), MS_ERR_INVALID_ARGUMENT,
                      "not finite");

    MS_ASSERT_REFUSED(ms_volume_add_collider(v, NULL), MS_ERR_INVALID_ARGUMENT, "shape");
    MS_ASSERT_REFUSED(ms_volume_remove_collider(v, (ms_shape *)&g), MS_ERR_INVALID_ARGUMENT,
                      "not a collider");
    ms_shape *sh[65];
    for (int k = 0; k < 65; ++k)
        ck_assert_int_eq(ms_shape_create("sphere", "{\"radius\": 0.01}", &sh[k]), MS_OK);
    ck_assert_int_eq(ms_volume_add_collider(v, sh[0]), MS_OK);
    MS_ASSERT_REFUSED(ms_volume_add_collider(v, sh[0]), MS_ERR_INVALID_ARGUMENT, "already");
    for (int k = 1; k < 64; ++k)
        ck_assert_int_eq(ms_volume_add_collider(v, sh[k]), MS_OK);
    MS_ASSERT_REFUSED(ms_volume_add_collider(v, sh[64]), MS_ERR_INVALID_ARGUMENT, "at most 64");
    for (int k = 0; k < 64; ++k)
        ck_assert_int_eq(ms_volume_remove_collider(v, sh[k]), MS_OK);
    ms_volume_destroy(v);
    for (int k = 0; k < 65; ++k)
        ms_shape_destroy(sh[k]);
}
END_TEST

START_TEST(a_step_needing_too_many_substeps_is_unstable_and_leaves_a_valid_state)
{
    ms_volume_desc d = box_desc(0.4f, 0.4f, 0.4f, 0.04f);
    d.max_substeps = 3;
    ms_volume *v = make(&d);
    ck_assert_int_eq(ms_volume_fill_box(v, (float[3]){0, 0, 0}, (float[3]){0.2f, 0.2f, 0.2f}),
                     MS_OK);
    /* 1 s needs at least 625 sub-steps even at rest (0.4 h / c0): refused
     * before any work */
    MS_ASSERT_REFUSED(ms_volume_step(v, 1.0f), MS_ERR_UNSTABLE, "max_substeps");
    ms_volume_info in = ms_volume_info_init();
    ms_volume_get_info(v, &in);
    ck_assert_int_eq(in.substeps, 0);
    ms_volume_destroy(v);
    /* 650 passes that test but the falling liquid needs 683: it stops at
     * the cap, at a valid state part-way */
    d.max_substeps = 650;
    v = make(&d);
    ck_assert_int_eq(ms_volume_fill_box(v, (float[3]){0, 0, 0}, (float[3]){0.2f, 0.2f, 0.2f}),
                     MS_OK);
    MS_ASSERT_REFUSED(ms_volume_step(v, 1.0f), MS_ERR_UNSTABLE, "max_substeps");
    ms_volume_get_info(v, &in);
    ck_assert_int_eq(in.substeps, 650);
    ck_assert(in.time > 0.0 && in.time < 1.0);
    assert_sane(v, &d);
    ms_volume_destroy(v);
}
END_TEST

/* ---------------------------------------------------------- the model */

/* A block on the desc's lattice has rho0 inside (the mass is calibrated on
 * the lattice), with either density kernel. */
START_TEST(a_lattice_block_has_rest_density_inside)
{
    for (int kern = 0; kern < 2; ++kern) {
        ms_volume_desc d = box_desc(0.6f, 0.6f, 0.6f, 0.05f);
        d.density_kernel = (ms_density_kernel)kern;
        d.gravity[2] = 0.0f;
        ms_volume *v = make(&d);
        ms_volume_fill_box(v, (float[3]){0.1f, 0.1f, 0.1f}, (float[3]){0.5f, 0.5f, 0.5f});
        ms_volume_grid_build(v);
        ms_volume_boundary(v, 0.0);
        ck_assert_int_eq(ms_volume_density(v), MS_OK);
        int inner = 0;
        for (int i = 0; i < v->n; ++i) {
            if (v->x[i] < 0.2f || v->x[i] > 0.4f || v->y[i] < 0.2f || v->y[i] > 0.4f ||
                v->z[i] < 0.2f || v->z[i] > 0.4f)
                continue;
            ck_assert_float_eq_tol(v->rho[i], d.rest_density, 1e-3f * d.rest_density);
            ck_assert_float_eq_tol(v->prs[i], 0.0f, 1.0f);
            inner++;
        }
        ck_assert_int_gt(inner, 8);
        ms_volume_destroy(v);
    }
}
END_TEST

/* The domain's walls reflect the liquid (wall images): a block filling a
 * box at the lattice spacing has rest density right up to the walls. */
START_TEST(walls_give_full_density_at_the_wall)
{
    ms_volume_desc d = box_desc(0.4f, 0.4f, 0.4f, 0.05f);
    d.gravity[2] = 0.0f;
    ms_volume *v = make(&d);
    ms_volume_fill_box(v, d.domain_min, d.domain_max);
    ms_volume_grid_build(v);
    ms_volume_boundary(v, 0.0);
    ck_assert_int_eq(ms_volume_density(v), MS_OK);
    for (int i = 0; i < v->n; ++i)
        ck_assert_float_eq_tol(v->rho[i], d.rest_density, 1e-3f * d.rest_density);
    ck_assert_int_eq(v->surface_count, 0); /* no particle of a full box is at a surface */
    ms_volume_destroy(v);
}
END_TEST

/* Each particle's depth below the free surface, counted as the liquid
 * above it: d_i = (k_i + 1/2) s^3 / area, k_i the number of particles
 * higher than i (ties by index), each taking its lattice volume s^3 at
 * rest density, and half of i's own. Hydrostatics is a force balance
 * across a horizontal plane: the pair forces crossing it carry the weight
 * of every particle above it, so the pressure there is rho0 g times this
 * depth wherever the surface particles sit and however far the column
 * below has settled. The free surface is where the count is zero, half a
 * layer (in volume) above the top layer's centres. Volume over area minus
 * z (the level as if every layer below sat at its lattice height) counts
 * the settling of the liquid below as depth: measured on the settled
 * 0.28 m column, the layer 2.5 spacings down sits 0.7-0.8 mm below its
 * lattice height under DFSPH (1.5 mm under the ideal gas, c = 20 m/s),
 * 1.5-3 % of its depth, the top layer 3.6 mm (sunk into the second: its
 * kernel lacks its upper half, so it is pushed only once it sits closer
 * to the layer below than a spacing). So
 * the top layer's centres + spacing/2 would put the surface 3.6 mm low
 * and the layer 2.5 spacings down 2.9-3.6 % high under DFSPH. */
typedef struct {
    float z;
    int i;
} z_rank;

static int higher_first(const void *pa, const void *pb)
{
    const z_rank *a = pa, *b = pb;
    if (a->z != b->z)
        return a->z > b->z ? -1 : 1;
    return (a->i > b->i) - (a->i < b->i);
}

static void depth_below_surface(const ms_volume *v, double area, double spacing, double *depth)
{
    z_rank *r = malloc(sizeof *r * (size_t)(v->n + 1));
    ck_assert_ptr_nonnull(r);
    for (int i = 0; i < v->n; ++i)
        r[i] = (z_rank){v->z[i], i};
    qsort(r, (size_t)v->n, sizeof *r, higher_first);
    const double cell = spacing * spacing * spacing / area;
    for (int k = 0; k < v->n; ++k)
        depth[r[k].i] = (k + 0.5) * cell;
    free(r);
}

/* Hydrostatic tank. After settling, the pressure of the particles in
 * horizontal layers (time-averaged over 0.5 s, which averages out the
 * column's breathing mode), deeper than h below the surface, matches
 * rho0 g d within 5 %, d counted as the liquid above (depth_below_surface);
 * measured at viscosity 5: the ideal gas within 4.2 % (the layer on the
 * floor 4.2 % low, the one 2.5 spacings down 2.5 % low, the others within
 * 2.1 %),
 * Tait within 3.3 % (2.3-2.9 % high inside, the layer 2.5 spacings down
 * 0.8 % low). The compression stays within 3 x what the law gives at rest,
 * rho0 g H / (rho0 c^2) = g H / c^2 = 0.7 % here (the settling column
 * overshoots): 2 %. */
static void hydrostatic(ms_pressure law)
{
    ms_volume_desc d = box_desc(0.2f, 0.2f, 0.4f, 0.02f);
    d.pressure = law;
    d.viscosity = 5.0f; /* settles faster; no effect on the equilibrium */
    ms_volume *v = make(&d);
    const float H = 0.28f;
    ms_volume_fill_box(v, (float[3]){0, 0, 0}, (float[3]){0.2f, 0.2f, H});
    const double s = d.spacing;
    enum { LAYERS = 16 }; /* index k: depth in [k s, (k + 1) s) */
    double lp[LAYERS] = {0}, lz[LAYERS] = {0}, ld[LAYERS] = {0};
    long lc[LAYERS] = {0};
    double *depth = malloc(sizeof *depth * (size_t)(v->n + 1));
    ck_assert_ptr_nonnull(depth);
    float max_err = 0.0f;
    for (int f = 0; f < 90; ++f) {
        step(v, 1.0f / 60);
        if (f < 60)
            continue;
        ms_volume_info in = ms_volume_info_init();
        ms_volume_get_info(v, &in);
        max_err = fmaxf(max_err, in.max_density_error);
        ms_volume_grid_build(v);
        ms_volume_boundary(v, 0.0);
        ck_assert_int_eq(ms_volume_density(v), MS_OK);
        depth_below_surface(v, 0.2 * 0.2, s, depth);
        for (int i = 0; i < v->n; ++i) {
            int k = (int)(depth[i] / s);
            if (k >= LAYERS)
                continue;
            lp[k] += v->prs[i];
            lz[k] += v->z[i];
            ld[k] += depth[i];
            lc[k]++;
        }
    }
    free(depth);
    int checked = 0;
    for (int k = 0; k < LAYERS; ++k) {
        if (!lc[k] || k * s < d.smoothing_length - 1e-9)
            continue;
        double z = lz[k] / lc[k], p = lp[k] / lc[k];
        double want = d.rest_density * 9.81 * ld[k] / lc[k];
        ck_assert_msg(fabs(p - want) <= 0.05 * want,
                      "%s: layer at z %.3f m: p %.1f Pa, rho0 g d %.1f Pa",
                      law == MS_PRESSURE_TAIT ? "Tait" : "ideal gas", z, p, want);
        checked++;
    }
    ck_assert_int_ge(checked, 8);
    float c = law == MS_PRESSURE_TAIT ? d.sound_speed : sqrtf(d.gas_constant);
    float compress = 9.81f * H / (c * c);
    ck_assert_msg(max_err < 3.0f * compress, "density error %g over 3 x g H / c^2 = %g", max_err,
                  3.0f * compress);
    ms_volume_destroy(v);
}

START_TEST(hydrostatic_pressure_matches_rho_g_d_ideal_gas)
{
    if (skip_under_tsan())
        MS_SKIP(TSAN_WHY);
    hydrostatic(MS_PRESSURE_IDEAL_GAS);
}
END_TEST

START_TEST(hydrostatic_pressure_matches_rho_g_d_tait)
{
    if (skip_under_tsan())
        MS_SKIP(TSAN_WHY);
    hydrostatic(MS_PRESSURE_TAIT);
}
END_TEST

/* DFSPH (incompressible): a settled 0.28 m column's pressure (dfsph.c's
 * read-out: both solves' impulses as a pressure, the mean over each
 * step's sub-steps, the measured gradient moment), averaged over 1.5 s,
 * matches rho0 g d within 2 % below the first layer, at
 * every viscosity of the scenes' range, d counted as the liquid above
 * (depth_below_surface): in every layer (a spacing thick) deeper than 2 h,
 * and in every slab h thick (two consecutive layers; h, the kernel's
 * radius, is the scale SPH resolves a field at) below the first layer.
 * Measured at viscosities 0.5, 1, 3, 4.99, 5, 5.01 and 8: layers deeper
 * than 2 h within 1.7 %, slabs within 1.4 % (the one 2-4 spacings down
 * 0.4-1.4 % low, the one 1-3 down within 0.8 %). Per layer, next to the
 * free surface the particles' pressures alternate: the layer 1.5 spacings
 * down reads 2.9-4.7 % high, the one 2.5 spacings down 1.6-3.5 % low (the
 * top layer, its density clamped at no tension, 18-24 % low), and so do
 * the two layers on the floor (1-1.7 % low, 0.4-1.4 % high). It is SPH's,
 * not the read-out's: the weakly compressible laws, whose pressure is
 * their density's, show it in the same tank (ideal gas, c = 20 m/s: +6.1 %
 * and -2.5 % at 1.5 and 2.5 spacings, +2.1 % and -4.2 % on the floor; Tait
 * +8.1 % and -0.8 % over its +2.7 % elsewhere), and the layer 2.5 spacings
 * down has an inside particle's neighbours (32.4 against 32.6) and no
 * surface flag. Nor is it the solve's tolerance (max_density_error 0.01 %
 * instead of 0.1 %, viscosity 5: +4.7 % and -1.1 % at 1.5 and 2.5
 * spacings), and it stays in the top layers as the spacing shrinks (0.01 m,
 * 11 200 particles: +5.1 % and -0.9 %, the next three within 0.6 %), so
 * its depth in metres halves with the spacing. In the interior a
 * particle's own pressure cancels from its force (sum_j grad W_ij = 0),
 * and at h = 2 spacings only the layers next to it push it (the ones two
 * away sit at the kernel's edge, where its gradient is 0): a layer's
 * weight sets the difference of the pressures of the layers above and
 * below it, so the odd layers' pressures are tied to each other and the
 * even layers' to each other, and where the neighbourhood is cut (the
 * surface's clamp, the floor) the two sets settle apart. The slope of p
 * against z, fitted over the layers deeper than h (blind to the level),
 * is rho0 g within 2 % (measured within 0.8 %). The pressure is read as
 * an average over the frame's sub-steps, not at its last one: the
 * iteration counts alternate sub-step by sub-step (a warm start's
 * period-2 swing, e.g. 3, 17, 2, 19 iterations), and a frame of 4
 * sub-steps read at its last always saw the same phase of it (the worst
 * slab then 1.3 % off at viscosity 5 but 9.8 % at 3).
 * The compression at the positions each step ends with, max(rho/rho0 - 1,
 * 0), averages at most the desc's 0.1 % plus a tenth of it (measured
 * 0.097-0.099 % at the seven viscosities) and peaks below 1 % (measured
 * 0.54-0.78 %), where the ideal gas law at c = 20 m/s compresses 0.7 %. */
static void hydrostatic_dfsph(float viscosity)
{
    ms_volume_desc d = box_desc(0.2f, 0.2f, 0.4f, 0.02f);
    d.pressure = MS_PRESSURE_DFSPH;
    d.viscosity = viscosity;
    ms_volume *v = make(&d);
    const float H = 0.28f;
    ms_volume_fill_box(v, (float[3]){0, 0, 0}, (float[3]){0.2f, 0.2f, H});
    const double rho_g = d.rest_density * 9.81, s = d.spacing, h = d.smoothing_length;
    enum { LAYERS = 16 }; /* index k: depth in [k s, (k + 1) s) */
    double lp[LAYERS] = {0}, lz[LAYERS] = {0}, ld[LAYERS] = {0}, avg_sum = 0.0;
    long lc[LAYERS] = {0};
    double *depth = malloc(sizeof *depth * (size_t)(v->n + 1));
    ck_assert_ptr_nonnull(depth);
    float max_err = 0.0f;
    int frames = 0;
    for (int f = 0; f < 135; ++f) {
        step(v, 1.0f / 60);
        if (f < 45)
            continue;
        depth_below_surface(v, 0.2 * 0.2, s, depth); /* prs and positions of the step's end */
        for (int i = 0; i < v->n; ++i) {
            int k = (int)(depth[i] / s);
            if (k >= LAYERS)
                continue;
            lp[k] += v->prs[i];
            lz[k] += v->z[i];
            ld[k] += depth[i];
            lc[k]++;
        }
        ms_volume_grid_build(v);
        ms_volume_boundary(v, 0.0);
        ck_assert_int_eq(ms_volume_density(v), MS_OK);
        double sum = 0.0;
        for (int i = 0; i < v->n; ++i) {
            float e = v->rho[i] / d.rest_density - 1.0f;
            sum += e > 0.0f ? e : 0.0f;
            max_err = fmaxf(max_err, e);
        }
        avg_sum += sum / v->n;
        frames++;
    }
    free(depth);
    int layers = 0, slabs = 0, fitted = 0;
    double fz = 0.0, fp = 0.0, fzz = 0.0, fzp = 0.0;
    for (int k = 0; k < LAYERS; ++k) {
        if (!lc[k] || k * s < h - 1e-9)
            continue;
        double z = lz[k] / lc[k], p = lp[k] / lc[k], want = rho_g * ld[k] / lc[k];
        fz += z;
        fp += p;
        fzz += z * z;
        fzp += z * p;
        fitted++;
        if (k * s < 2.0 * h - 1e-9)
            continue;
        ck_assert_msg(fabs(p - want) <= 0.02 * want,
                      "DFSPH, viscosity %g: layer at z %.3f m: p %.1f Pa, rho0 g d %.1f Pa",
                      (double)viscosity, z, p, want);
        layers++;
    }
    /* every slab h thick (h / s consecutive layers) below the first layer */
    const int per = (int)lround(h / s);
    for (int k = 1; k + per <= LAYERS && lc[k + per - 1]; ++k) {
        double p = 0.0, want = 0.0;
        long c = 0;
        for (int q = k; q < k + per; ++q) {
            p += lp[q];
            want += rho_g * ld[q];
            c += lc[q];
        }
        p /= c;
        want /= c;
        ck_assert_msg(fabs(p - want) <= 0.02 * want,
                      "DFSPH, viscosity %g: slab %.3f-%.3f m deep: p %.1f Pa, rho0 g d %.1f Pa",
                      (double)viscosity, k * s, (k + per) * s, p, want);
        slabs++;
    }
    ck_assert_int_ge(layers, 8);
    ck_assert_int_ge(slabs, 10);
    double slope = -(fitted * fzp - fz * fp) / (fitted * fzz - fz * fz);
    ck_assert_msg(fabs(slope - rho_g) <= 0.02 * rho_g,
                  "DFSPH, viscosity %g: -dp/dz %.1f Pa/m, rho0 g %.1f Pa/m", (double)viscosity,
                  slope, rho_g);
    double avg = avg_sum / frames;
    ck_assert_msg(avg <= 1.1 * d.max_density_error, "average compression %g over 1.1 x %g", avg,
                  (double)d.max_density_error);
    ck_assert_msg(max_err < 0.01f, "maximum compression %g over 1 %%", max_err);
    ms_volume_info in = ms_volume_info_init();
    ms_volume_get_info(v, &in);
    ck_assert_int_ge(in.density_iterations_total, 1);
    ck_assert(in.density_error <= d.max_density_error || in.density_iterations == 100);
    ms_volume_destroy(v);
}

/* The scenes' viscosities span 0.5-8; 4.99, 5 and 5.01 guard
 * against a read-out tuned to one setting. */
START_TEST(hydrostatic_pressure_matches_rho_g_d_dfsph)
{
    if (skip_under_tsan())
        MS_SKIP(TSAN_WHY);
    const float viscosities[] = {0.5f, 1.0f, 3.0f, 4.99f, 5.0f, 5.01f, 8.0f};
    for (size_t k = 0; k < sizeof viscosities / sizeof viscosities[0]; ++k)
        hydrostatic_dfsph(viscosities[k]);
}
END_TEST

/* DFSPH: a tank that starts sloshing (a dam break in a closed box) loses
 * mechanical energy from 0.2 s on: never more than 1 % above its energy
 * at 0.2 s (measured: 0.1 % above it at 0.22 s, while the column still
 * falls), and below 90 % of it at 1 s; and the divergence-free solve holds its
 * error: the average over the sub-steps of the error it reached is at
 * most its bound (it stops at the bound unless it hits its cap). */
START_TEST(a_settling_dfsph_tank_loses_energy_and_keeps_its_divergence)
{
    if (skip_under_tsan())
        MS_SKIP(TSAN_WHY);
    ms_volume_desc d = box_desc(0.3f, 0.1f, 0.3f, 0.02f);
    d.pressure = MS_PRESSURE_DFSPH;
    ms_volume *v = make(&d);
    ms_volume_fill_box(v, (float[3]){0, 0, 0}, (float[3]){0.12f, 0.1f, 0.2f});
    double e02 = 0.0, prev = 0.0, div_sum = 0.0;
    int frames = 0;
    for (int f = 0; f < 60; ++f) {
        step(v, 1.0f / 60);
        ms_volume_info in = ms_volume_info_init();
        ms_volume_get_info(v, &in);
        div_sum += in.divergence_error;
        frames++;
        double e = mechanical_energy(v, &d);
        if (f == 11)
            e02 = e;
        if (f > 11) /* the solves' 0.1 % errors may return a little: 1 % */
            ck_assert_msg(e <= 1.01 * e02, "frame %d: %g J over the %g J at 0.2 s", f, e, e02);
        prev = e;
    }
    ck_assert_msg(prev < 0.9 * e02, "energy %g J at 1 s, %g J at 0.2 s: did not settle", prev, e02);
    ck_assert_msg(div_sum / frames <= d.max_divergence_error, "divergence error %g over %g",
                  div_sum / frames, (double)d.max_divergence_error);
    assert_sane(v, &d);
    ms_volume_destroy(v);
}
END_TEST

/* Dam break: a column a wide and 2a high released at the end of a tank
 * (a quasi-2D slab between frictionless walls). The surge front Z = x/a
 * against T = t sqrt(2 g / a) follows Martin & Moyce (1952, their Table
 * 2): the RMS of Z - Z_exp over their 15 points; the residual column at
 * the back wall H = height / 2a against tau = t sqrt(g / a) (their Table
 * 6, the first 13 points, tau <= 3.06): the RMS of the relative error, as
 * tools/modesplit/study_sph.c. The front runs slightly ahead of the
 * experiment, as inviscid simulations do (the experiment's gate and wall
 * friction slow it). MS_TEST_LONG=1 also runs 3200 particles. */
typedef struct dam_result {
    double z_rms; /* RMS of Z - Z_exp (Z in units of a) */
    double h_rel; /* RMS of (H - H_exp) / H_exp */
    int count;
} dam_result;

static dam_result dam_break_law(float a, float s, ms_pressure law)
{
    static const double mm[15][2] = {{0.41, 1.11}, {0.84, 1.22}, {1.19, 1.44}, {1.43, 1.67},
                                     {1.63, 1.89}, {1.83, 2.11}, {1.98, 2.33}, {2.20, 2.56},
                                     {2.32, 2.78}, {2.51, 3.00}, {2.65, 3.22}, {2.83, 3.44},
                                     {2.98, 3.67}, {3.11, 3.89}, {3.33, 4.11}};
    static const double mmh[13][2] = {{0.56, 0.94}, {0.77, 0.89}, {0.93, 0.83}, {1.08, 0.78},
                                      {1.28, 0.72}, {1.46, 0.67}, {1.66, 0.61}, {1.84, 0.56},
                                      {2.00, 0.50}, {2.21, 0.44}, {2.45, 0.39}, {2.70, 0.33},
                                      {3.06, 0.28}};
    ms_volume_desc d = box_desc(5.0f * a, 4.0f * s, 2.5f * a, s);
    d.viscosity = 1.0f;
    d.pressure = law;
    ms_volume *v = make(&d);
    ms_volume_fill_box(v, (float[3]){0, 0, 0}, (float[3]){a, 4.0f * s, 2.0f * a});
    dam_result r = {.count = ms_volume_count(v)};
    const double tscale = sqrt(2.0 * 9.81 / a), hscale = sqrt(9.81 / a);
    int k = 0, kh = 0;
    double err2 = 0.0, herr2 = 0.0, tprev = 0.0, zprev = 1.0, hprev = 1.0;
    float *p = malloc(sizeof(float) * 3 * (size_t)r.count);
    while (k < 15 || kh < 13) {
        step(v, 0.002f);
        ms_volume_get_particles(v, p, NULL);
        /* the front: the farthest particle; the column: the highest of the
         * layer at the back wall (x < s, its centres at s / 2) */
        double xf = 0.0, zc = 0.0;
        for (int i = 0; i < r.count; ++i) {
            xf = fmax(xf, p[3 * i]);
            if (p[3 * i] < s)
                zc = fmax(zc, p[3 * i + 2]);
        }
        ms_volume_info in = ms_volume_info_init();
        ms_volume_get_info(v, &in);
        double t = in.time, zf = (xf + 0.5 * s) / a, hc = (zc + 0.5 * s) / (2.0 * a);
        while (k < 15 && t * tscale >= mm[k][0]) { /* linear between frames */
            double f = (mm[k][0] / tscale - tprev) / (t - tprev);
            double zi = zprev + (zf - zprev) * f;
            err2 += (zi - mm[k][1]) * (zi - mm[k][1]);
            k++;
        }
        while (kh < 13 && t * hscale >= mmh[kh][0]) {
            double f = (mmh[kh][0] / hscale - tprev) / (t - tprev);
            double e = (hprev + (hc - hprev) * f - mmh[kh][1]) / mmh[kh][1];
            herr2 += e * e;
            kh++;
        }
        tprev = t;
        zprev = zf;
        hprev = hc;
        ck_assert(in.time < 1.0);
    }
    free(p);
    ms_volume_destroy(v);
    r.z_rms = sqrt(err2 / 15.0);
    r.h_rel = sqrt(herr2 / 13.0);
    return r;
}

/* Measured: front RMS 0.197, column 10.4 % with 800 particles (a = 0.1 m,
 * spacing 0.01 m); 0.276 and 6.2 % with 3200 (a = 0.2 m). */
START_TEST(dam_break_follows_martin_and_moyce)
{
    if (skip_under_tsan())
        MS_SKIP(TSAN_WHY);
    dam_result r = dam_break_law(0.1f, 0.01f, MS_PRESSURE_IDEAL_GAS);
    ck_assert_int_eq(r.count, 800);
    ck_assert_msg(r.z_rms < 0.3, "RMS %.3f of Z against Martin & Moyce with %d particles", r.z_rms,
                  r.count);
    ck_assert_msg(r.h_rel < 0.15, "column H %.3f off Martin & Moyce with %d particles", r.h_rel,
                  r.count);
    if (long_tests()) {
        r = dam_break_law(0.2f, 0.01f, MS_PRESSURE_IDEAL_GAS);
        ck_assert_msg(r.z_rms < 0.35, "RMS %.3f with %d particles", r.z_rms, r.count);
        ck_assert_msg(r.h_rel < 0.1, "column H %.3f with %d particles", r.h_rel, r.count);
    }
}
END_TEST

/* The same dam break with DFSPH against the ideal gas law at the same 800
 * particles: at least as close as the weakly compressible solver. The column H(tau) is: measured 10.3 % against 10.4 % (over
 * frames of 1-4 ms, which resample both and change DFSPH's sub-steps,
 * 7.6-11.1 % against 9.3-14.5 %); asserted: within 2 points of the ideal
 * gas's. The front Z(T) is NOT: RMS 0.290 against 0.197 (0.290-0.302
 * against 0.197-0.209 over those frames), its best time shift T0 0.236
 * against 0.174. The cause, measured: the bulk agrees (kinetic energy
 * within 1 %, centre of mass within 1 mm at every 10 ms to 0.2 s), the
 * lead is the front's first particles. Under DFSPH the eq. 15 wall field is off
 * (volume.c: its stiffness would bound the step), so only the images hold
 * the liquid off the floor, and a particle short of neighbours (the free
 * surface) is not compressed, hence not pushed up, until its own image is
 * near: the leading particle slides at z = 1.7-3 mm (0.17-0.3 spacing,
 * the ideal gas's 5-11 mm) with rho ~ rho0 from 5 real neighbours and 8-9
 * images, and that compression's pressure, against neighbours all behind
 * it, pushes it ahead: 1.64 m/s against 1.48 at t = 0.1 s. Turning the
 * field back on takes the RMS to 0.190; the compressible release (its
 * delay ~ 2a / c) is not it: the ideal gas's T0 is 0.174-0.176 at c = 20,
 * 40 and 80 m/s. Asserted where it measures: RMS < 0.35 and within 0.12
 * of the ideal gas's. */
START_TEST(dam_break_follows_martin_and_moyce_dfsph)
{
    if (skip_under_tsan())
        MS_SKIP(TSAN_WHY);
    dam_result r = dam_break_law(0.1f, 0.01f, MS_PRESSURE_DFSPH);
    dam_result w = dam_break_law(0.1f, 0.01f, MS_PRESSURE_IDEAL_GAS);
    ck_assert_int_eq(r.count, 800);
    ck_assert_int_eq(w.count, r.count);
    ck_assert_msg(r.h_rel <= w.h_rel + 0.02, "DFSPH: column H %.3f off, the ideal gas %.3f",
                  r.h_rel, w.h_rel);
    ck_assert_msg(r.z_rms < 0.35 && r.z_rms <= w.z_rms + 0.12,
                  "DFSPH: RMS %.3f of Z against Martin & Moyce, the ideal gas %.3f", r.z_rms,
                  w.z_rms);
}
END_TEST

/* Eqs. 13 and 14 divided by rho_i are antisymmetric pair by pair: with no
 * gravity and no wall in reach, the total momentum stays what it was. */
START_TEST(internal_forces_conserve_momentum)
{
    ms_volume_desc d = box_desc(1.0f, 1.0f, 1.0f, 0.04f);
    d.gravity[2] = 0.0f;
    ms_volume *v = make(&d);
    ms_volume_fill_box(v, (float[3]){0.35f, 0.35f, 0.35f}, (float[3]){0.65f, 0.65f, 0.65f});
    int n = ms_volume_count(v);
    float *u = calloc(3 * (size_t)n, sizeof(float));
    float *p = malloc(sizeof(float) * 3 * (size_t)n);
    ms_volume_get_particles(v, p, NULL);
    ms_rng r;
    ms_rng_seed(&r, 7);
    for (int i = 0; i < 3 * n; ++i) {
        u[i] = 0.2f * (ms_rng_uniform(&r) - 0.5f);
        p[i] += 0.004f * (ms_rng_uniform(&r) - 0.5f); /* off the lattice: real pressure */
    }
    ms_volume_remove_box(v, d.domain_min, d.domain_max, NULL);
    ck_assert_int_eq(ms_volume_add_particles(v, n, p, u), MS_OK);
    double m0[3] = {0, 0, 0}, m1[3] = {0, 0, 0};
    for (int i = 0; i < n; ++i)
        for (int k = 0; k < 3; ++k)
            m0[k] += u[3 * i + k];
    step(v, 0.05f);
    ms_volume_get_particles(v, NULL, u);
    double speed = 0.0;
    for (int i = 0; i < n; ++i)
        for (int k = 0; k < 3; ++k) {
            m1[k] += u[3 * i + k];
            speed += fabs(u[3 * i + k]);
        }
    for (int k = 0; k < 3; ++k)
        ck_assert_msg(fabs(m1[k] - m0[k]) < 1e-4 * speed, "momentum %d: %g -> %g", k, m0[k], m1[k]);
    free(u);
    free(p);
    ms_volume_destroy(v);
}
END_TEST

/* ----------------------------------------------------------- extraction */

static void settle_tank(ms_volume *v, int frames)
{
    for (int f = 0; f < frames; ++f)
        step(v, 1.0f / 60);
}

/* A still liquid extracts flat at its level (volume over area): every cell
 * within a quarter spacing of it after the eq. 18 smoothing. */
START_TEST(still_liquid_extracts_a_flat_surface_at_its_level)
{
    if (skip_under_tsan())
        MS_SKIP(TSAN_WHY);
    ms_volume_desc d = box_desc(0.4f, 0.4f, 0.4f, 0.02f);
    d.viscosity = 20.0f;
    ms_volume *v = make(&d);
    ms_volume_fill_box(v, (float[3]){0, 0, 0}, (float[3]){0.4f, 0.4f, 0.12f});
    settle_tank(v, 40);
    const float level = 0.12f;
    enum { N = 20 };
    float hf[N * N];
    ck_assert_int_eq(ms_volume_extract_height(v, N, N, hf), MS_OK);
    for (int c = 0; c < N * N; ++c)
        ck_assert_msg(fabsf(hf[c] - level) < 0.25f * d.spacing, "cell %d: %g m, level %g m", c,
                      hf[c], level);
    /* same state, same bytes */
    float again[N * N];
    ck_assert_int_eq(ms_volume_extract_height(v, N, N, again), MS_OK);
    ck_assert_int_eq(memcmp(hf, again, sizeof hf), 0);
    ms_volume_destroy(v);
}
END_TEST

START_TEST(columns_without_liquid_extract_zero)
{
    ms_volume_desc d = box_desc(0.8f, 0.4f, 0.4f, 0.02f);
    d.gravity[2] = 0.0f;
    ms_volume *v = make(&d);
    ms_volume_fill_box(v, (float[3]){0, 0, 0}, (float[3]){0.2f, 0.4f, 0.1f});
    enum { NX = 16, NY = 8 };
    float hf[NX * NY];
    ck_assert_int_eq(ms_volume_extract_height(v, NX, NY, hf), MS_OK);
    for (int j = 0; j < NY; ++j)
        for (int i = 0; i < NX; ++i) {
            float x = (i + 0.5f) * 0.05f, hh = hf[j * NX + i];
            if (x < 0.15f)
                ck_assert_msg(fabsf(hh - 0.1f) < 0.01f, "liquid cell (%d,%d): %g", i, j, hh);
            if (x > 0.3f)
                ck_assert_msg(hh == 0.0f, "dry cell (%d,%d): %g", i, j, hh);
        }
    ms_volume_destroy(v);
}
END_TEST

/* Eq. 18: the same particles extract smoother when still than when fast. */
static double roughness(const float *f, int n)
{
    double s = 0.0;
    for (int j = 0; j < n; ++j)
        for (int i = 0; i + 1 < n; ++i)
            s += fabs(f[j * n + i + 1] - f[j * n + i]);
    return s;
}

/* Phase B's gather runs in C or AVX-512 (picked at run time): over frames
 * of moving liquid in three shipped scenes (columns with wall images at
 * the sides and corners among them) both give the same field to the bit,
 * and ms_extract_cell the same cells. On a CPU without AVX-512 the C
 * gather is checked alone and the AVX-512 one is not applicable. */
START_TEST(every_instruction_set_path_extracts_the_same_field)
{
    const int other =
        ms_volume_pick_isa() == MS_VOLUME_ISA_AVX512 ? MS_VOLUME_ISA_AVX512 : MS_VOLUME_ISA_C;
    if (other != MS_VOLUME_ISA_AVX512)
        MS_NOT_APPLICABLE("the AVX-512 gather: this CPU (or build) has no AVX-512");
    static const char *const scenes[] = {"data/scenes/fig1.json", "data/scenes/fig10.json",
                                         "data/scenes/glass.json"};
    for (size_t k = 0; k < sizeof scenes / sizeof *scenes; ++k) {
        ms_scene *sc;
        ck_assert_int_eq(ms_scene_load(scenes[k], &sc), MS_OK);
        ms_sim *sim;
        ck_assert_int_eq(ms_sim_create_from_scene(sc, 1, &sim), MS_OK);
        ms_volume *v = ms_sim_volume(sim);
        ms_extract_snap s = {0};
        ms_extract_work w = {0};
        float *a = NULL, *b = NULL;
        int nx = 0, ny = 0, wet = 0;
        for (int f = 0; f < 24; ++f) {
            ck_assert_int_eq(ms_sim_step(sim, ms_scene_frame_dt(sc)), MS_OK);
            if (!a) {
                ms_sim_volume_height(sim, &nx, &ny);
                a = malloc(sizeof(float) * (size_t)nx * ny);
                b = malloc(sizeof(float) * (size_t)nx * ny);
                ck_assert_ptr_nonnull(a);
                ck_assert_ptr_nonnull(b);
            }
            ck_assert_int_eq(ms_volume_extract_snap(v, &s), MS_OK);
            for (int ref = 1; ref >= 0; --ref) { /* the reference search, then the band's */
                s.reference = ref;
                s.isa = MS_VOLUME_ISA_C;
                ck_assert_int_eq(ms_extract_field(&s, &w, NULL, nx, ny, a), MS_OK);
                s.isa = other;
                ck_assert_int_eq(ms_extract_field(&s, &w, NULL, nx, ny, b), MS_OK);
                ck_assert_msg(memcmp(a, b, sizeof(float) * (size_t)nx * ny) == 0,
                              "%s frame %d reference %d: the AVX-512 gather's field differs "
                              "from C's",
                              scenes[k], f, ref);
                const int corners[4][2] = {{0, 0}, {nx - 1, 0}, {0, ny - 1}, {nx / 2, ny / 2}};
                for (int c = 0; c < 4; ++c) {
                    float h;
                    const int i = corners[c][0], j = corners[c][1];
                    ck_assert_int_eq(ms_extract_cell(&s, &w, nx, ny, i, j, &h), MS_OK);
                    ck_assert_msg(memcmp(&h, &b[(size_t)j * nx + i], sizeof h) == 0,
                                  "%s frame %d reference %d: cell (%d, %d) alone differs",
                                  scenes[k], f, ref, i, j);
                }
            }
        }
        for (int c = 0; c < nx * ny; ++c)
            wet += b[c] > 0.0f;
        ck_assert_msg(wet > 0, "%s: no liquid extracted", scenes[k]);
        free(a);
        free(b);
        ms_extract_snap_free(&s);
        ms_extract_work_free(&w);
        ms_sim_destroy(sim);
        ms_scene_destroy(sc);
    }
}
END_TEST

/* The spheres of a column at (px, py): every particle and its
 * images in the side walls within R, as (z, 1 - horizontal distance^2 /
 * R^2), in double; n of at most cap. */
static int column_spheres(const ms_extract_snap *s, double px, double py, double *zc, double *ac,
                          int cap)
{
    const double R = s->R;
    int n = 0;
    for (int k = 0; k < s->n_all; ++k) { /* eq. 16 over every particle */
        const double x = s->x[k], y = s->y[k];
        const double xs[2] = {x, x - s->lo[0] < R ? 2.0 * s->lo[0] - x : 2.0 * s->hi[0] - x};
        const double ys[2] = {y, y - s->lo[1] < R ? 2.0 * s->lo[1] - y : 2.0 * s->hi[1] - y};
        const int nxm = x - s->lo[0] < R || s->hi[0] - x < R ? 2 : 1;
        const int nym = y - s->lo[1] < R || s->hi[1] - y < R ? 2 : 1;
        for (int my = 0; my < nym; ++my)
            for (int mx = 0; mx < nxm; ++mx) {
                const double dx = xs[mx] - px, dy = ys[my] - py;
                const double a = 1.0 - (dx * dx + dy * dy) / (R * R);
                if (a > 0.0 && n < cap) {
                    zc[n] = s->z[k];
                    ac[n++] = a;
                }
                if (a > 0.0 && n < cap && s->z[k] - s->lo[2] < R) { /* the floor's image */
                    zc[n] = 2.0 * s->lo[2] - s->z[k];
                    ac[n++] = a;
                }
            }
    }
    ck_assert_int_lt(n, cap);
    return n;
}

/* phi - T (eqs. 16, 17) at height z of a column's spheres, in double */
static double phi_minus_t(const ms_extract_snap *s, const double *zc, const double *ac, int n,
                          double z)
{
    const double inv_r2 = 1.0 / ((double)s->R * s->R);
    double sum = 0.0;
    for (int k = 0; k < n; ++k) {
        const double q = ac[k] - (z - zc[k]) * (z - zc[k]) * inv_r2;
        sum += q > 0.0 ? sqrt(q) : 0.0;
    }
    return sum - s->iso;
}

/* How far height h of the column at (px, py) is from the nearest root of
 * phi = T: sign changes on a grid of 1/2048 of a spacing either side (half
 * a spacing out; near a sphere's rim phi can wiggle across T within a
 * 1/128 of a spacing), then bisection in double. */
static double root_distance(const ms_extract_snap *s, double px, double py, double h)
{
    enum { CAP = 4096 };
    static double zc[CAP], ac[CAP];
    const int n = column_spheres(s, px, py, zc, ac, CAP);
    const double z0 = s->lo[2] + h, dz = s->spacing / 2048.0; /* finer than a rim's wiggle */
    double best = INFINITY;
    for (int dir = -1; dir <= 1; dir += 2) {
        double za = z0, fa = phi_minus_t(s, zc, ac, n, za);
        if (fa == 0.0)
            return 0.0;
        for (int k = 1; k <= 1024; ++k) {
            double zb = z0 + dir * k * dz, fb = phi_minus_t(s, zc, ac, n, zb);
            if ((fa < 0.0) != (fb < 0.0)) {
                for (int it = 0; it < 40; ++it) {
                    const double zm = 0.5 * (za + zb), fm = phi_minus_t(s, zc, ac, n, zm);
                    if ((fm < 0.0) == (fa < 0.0)) {
                        za = zm;
                        fa = fm;
                    } else {
                        zb = zm;
                    }
                }
                best = fmin(best, fabs(0.5 * (za + zb) - z0));
                break;
            }
            za = zb;
            fa = fb;
        }
    }
    return best;
}

/* The band path (bins with the wall images, a secant root
 * search) against the reference (663cc3c's: the same walk, a bracket
 * closed to 1/256 of a spacing) over frames of moving liquid in three
 * shipped scenes, walls and corners included, the raw columns (no eq. 18
 * smoothing): the same cells wet, and each column's height as close to a
 * root of phi = T (eq. 17, in double over all marked spheres) as the
 * reference's or within 1/256 of a spacing of one. bench_extract prints
 * the band's max |dh| against the reference over 100 frames. */
START_TEST(the_band_search_finds_the_reference_surface)
{
    static const char *const scenes[] = {"data/scenes/fig1.json", "data/scenes/fig10.json",
                                         "data/scenes/glass.json"};
    const int frames = skip_under_tsan() ? 3 : 12;
    for (size_t k = 0; k < sizeof scenes / sizeof *scenes; ++k) {
        ms_scene *sc;
        ck_assert_int_eq(ms_scene_load(scenes[k], &sc), MS_OK);
        ms_sim *sim;
        ck_assert_int_eq(ms_sim_create_from_scene(sc, 1, &sim), MS_OK);
        ms_volume *v = ms_sim_volume(sim);
        ms_extract_snap s = {0};
        ms_extract_work w = {0};
        float *a = NULL, *b = NULL;
        int nx = 0, ny = 0;
        double worst_ref = 0.0, worst_band = 0.0;
        long wet = 0;
        for (int f = 0; f < frames * 4; ++f) {
            ck_assert_int_eq(ms_sim_step(sim, ms_scene_frame_dt(sc)), MS_OK);
            if (f % 4 != 3)
                continue;
            if (!a) {
                ms_sim_volume_height(sim, &nx, &ny);
                a = malloc(sizeof(float) * (size_t)nx * ny);
                b = malloc(sizeof(float) * (size_t)nx * ny);
                ck_assert_ptr_nonnull(a);
                ck_assert_ptr_nonnull(b);
            }
            ck_assert_int_eq(ms_volume_extract_snap(v, &s), MS_OK);
            s.smooth_steps = 0; /* the columns themselves */
            s.reference = 1;
            ck_assert_int_eq(ms_extract_field(&s, &w, NULL, nx, ny, a), MS_OK);
            s.reference = 0;
            ck_assert_int_eq(ms_extract_field(&s, &w, NULL, nx, ny, b), MS_OK);
            const double dxe = (s.hi[0] - s.lo[0]) / nx, dye = (s.hi[1] - s.lo[1]) / ny;
            for (int c = 0; c < nx * ny; ++c) {
                ck_assert_msg((a[c] > 0.0f) == (b[c] > 0.0f), "%s frame %d cell %d: %g m, %g m",
                              scenes[k], f, c, a[c], b[c]);
                if (a[c] <= 0.0f || c % 3) /* every third wet column */
                    continue;
                wet++;
                const double px = s.lo[0] + (c % nx + 0.5) * dxe;
                const double py = s.lo[1] + (c / nx + 0.5) * dye;
                const double ra = root_distance(&s, px, py, a[c]);
                const double rb = root_distance(&s, px, py, b[c]);
                worst_ref = fmax(worst_ref, ra);
                worst_band = fmax(worst_band, rb);
                ck_assert_msg(rb <= ra + 1e-6 || rb < s.spacing / 256.0,
                              "%s frame %d cell %d: %g m from a root (reference %g m)", scenes[k],
                              f, c, rb, ra);
            }
        }
        ck_assert_msg(wet > 0, "%s: no liquid extracted", scenes[k]);
        fprintf(stderr,
                "%s: max distance to a root of phi = T: reference %.3g m, band %.3g m "
                "(spacing %g m)\n",
                scenes[k], worst_ref, worst_band, (double)s.spacing);
        free(a);
        free(b);
        ms_extract_snap_free(&s);
        ms_extract_work_free(&w);
        ms_sim_destroy(sim);
        ms_scene_destroy(sc);
    }
}
END_TEST

/* A glass column under DFSPH (acceleration-bound factor 0.5)
 * whose phi dips under T between two layers below its surface: the secant
 * stalled at the bracket's lower end for ten steps and its estimate stood
 * 0.15 mm (7.7 tol/2) from the nearest root (main 914c088). Its spheres (z, 1 - d^2 / R^2) as
 * phase B gathered them, placed around one column of a wide domain: the
 * band's height is within tol/2 = spacing / 512 of a root of phi = T. */
START_TEST(a_stalled_secant_still_ends_within_half_a_tolerance)
{
    static const float sph[][2] = {
        {0.0307387281f, 0.21976459f},   {0.0489525609f, 0.0407658815f},
        {0.0587471165f, 0.0418227911f}, {0.0213956796f, 0.139305532f},
        {0.0627828315f, 0.259481788f},  {0.0116637209f, 0.753078818f},
        {0.0237290971f, 0.339695632f},  {0.0342858844f, 0.412444472f},
        {0.0461708084f, 0.444905639f},  {0.0613659248f, 0.393671751f},
        {0.0148955584f, 0.615630984f},  {0.0190534201f, 0.881979823f},
        {0.0471156277f, 0.64890486f},   {0.0592163615f, 0.708055735f},
        {0.0145474123f, 0.490791619f},  {0.027922811f, 0.335661352f},
        {0.0506237708f, 0.679645181f},  {0.0632346869f, 0.155081451f},
        {0.0120235933f, 0.95950073f},   {0.0253163669f, 0.929774106f},
        {0.0484441221f, 0.943423092f},  {0.0417936891f, 0.944848061f},
        {0.0611290187f, 0.983473122f},  {0.0651021972f, 0.941908181f},
        {0.0158481933f, 0.435009122f},  {0.018985074f, 0.86237371f},
        {0.0312563106f, 0.901762784f},  {0.0240688194f, 0.50581336f},
        {0.0517242067f, 0.707154155f},  {0.056913808f, 0.535070419f},
        {0.0320819952f, 0.346229136f},  {0.0445261747f, 0.412760139f},
        {0.0601904616f, 0.633765101f},  {0.0137000093f, 0.273264885f},
        {0.0557337441f, 0.0400726795f},
    };
    enum { N = sizeof sph / sizeof *sph };
    float x[N], y[N], z[N];
    const float R = 0.02f, c = 0.1f;
    for (int k = 0; k < N; ++k) { /* at 1 - a of R^2 from the centre, spread in angle */
        const double d = R * sqrt(1.0 - sph[k][1]), t = 2.399963 * k;
        x[k] = (float)(c + d * cos(t));
        y[k] = (float)(c + d * sin(t));
        z[k] = sph[k][0];
    }
    ms_extract_snap s = {0};
    s.m = s.n_all = s.cap = N;
    s.x = x;
    s.y = y;
    s.z = z;
    s.iso = 10.0393515f;
    s.R = R;
    s.spacing = 0.01f;
    s.hi[0] = s.hi[1] = 2.0f * c;
    s.hi[2] = 0.25f;
    /* the C gather, and the AVX-512 one where the CPU has it */
    if (ms_volume_pick_isa() != MS_VOLUME_ISA_AVX512)
        MS_NOT_APPLICABLE("the AVX-512 gather: this CPU (or build) has no AVX-512");
    for (int isa = MS_VOLUME_ISA_C; isa <= ms_volume_pick_isa(); isa += MS_VOLUME_ISA_AVX512) {
        ms_extract_work w = {0};
        float h[2];
        s.isa = isa;
        for (int ref = 0; ref <= 1; ++ref) {
            s.reference = ref;
            ck_assert_int_eq(ms_extract_field(&s, &w, NULL, 1, 1, &h[ref]), MS_OK);
        }
        const double rb = root_distance(&s, c, c, h[0]), ra = root_distance(&s, c, c, h[1]);
        fprintf(
            stderr,
            "stalled column (isa %d): band %.9g m, %.3g m from a root; reference %.9g m, %.3g m\n",
            isa, (double)h[0], rb, (double)h[1], ra);
        ck_assert_msg(rb <= s.spacing / 512.0, "band %g m, %g m from a root (tol/2 %g m)",
                      (double)h[0], rb, s.spacing / 512.0);
        ms_extract_work_free(&w);
    }
}
END_TEST

START_TEST(adaptive_smoothing_keeps_turbulent_liquid_detailed)
{
    ms_volume_desc d = box_desc(0.4f, 0.4f, 0.4f, 0.02f);
    d.gravity[2] = 0.0f;
    ms_volume *v = make(&d);
    /* a rough surface: columns of random height */
    ms_rng r;
    ms_rng_seed(&r, 3);
    for (int j = 0; j < 20; ++j)
        for (int i = 0; i < 20; ++i) {
            float top = 0.08f + 0.02f * (float)(ms_rng_u32(&r) % 4);
            float lo[3] = {i * 0.02f, j * 0.02f, 0.0f},
                  hi[3] = {(i + 1) * 0.02f, (j + 1) * 0.02f, top};
            ck_assert_int_eq(ms_volume_fill_box(v, lo, hi), MS_OK);
        }
    enum { N = 40 };
    float still[N * N], fast[N * N];
    ck_assert_int_eq(ms_volume_extract_height(v, N, N, still), MS_OK);
    /* the liquid carried as a whole at 1 m/s is still inside: smoothed */
    float carried[N * N];
    for (int i = 0; i < v->n; ++i)
        v->vx[i] = 1.0f;
    ck_assert_int_eq(ms_volume_extract_height(v, N, N, carried), MS_OK);
    ck_assert_msg(memcmp(carried, still, sizeof still) == 0,
                  "a uniform velocity changed the smoothing");
    for (int i = 0; i < v->n; ++i) /* e = 0.5 J/kg about the mean, over smooth_energy */
        v->vx[i] = i % 2 ? 1.0f : -1.0f;
    ck_assert_int_eq(ms_volume_extract_height(v, N, N, fast), MS_OK);
    double rs = roughness(still, N), rf = roughness(fast, N);
    ck_assert_msg(rs < 0.7 * rf, "still %g not smoother than turbulent %g", rs, rf);
    ms_volume_destroy(v);
}
END_TEST

/* ------------------------------------------------------------- stepping */

static uint64_t state_hash(const ms_volume *v)
{
    int n = ms_volume_count(v);
    float *p = malloc(sizeof(float) * 6 * (size_t)(n + 1));
    ms_volume_get_particles(v, p, p + 3 * (size_t)n);
    uint64_t hsh = 1469598103934665603ull;
    const unsigned char *b = (const unsigned char *)p;
    for (size_t i = 0; i < sizeof(float) * 6 * (size_t)n; ++i)
        hsh = (hsh ^ b[i]) * 1099511628211ull;
    free(p);
    return hsh;
}

/* Whether path isa runs here; a path this build has and the CPU lacks
 * is recorded as not applicable (a path of another target, NEON on
 * x86-64, is not built at all). */
static int isa_here(int isa)
{
    if (ms_volume_isa_runs(isa))
        return 1;
    if (ms_volume_passes_of(isa))
        MS_NOT_APPLICABLE(ms_volume_isa_name(isa));
    return 0;
}

static uint64_t run_dam_law(int threads, int isa, ms_pressure law)
{
    ms_volume_desc d = box_desc(0.5f, 0.1f, 0.25f, 0.01f);
    d.threads = threads;
    d.pressure = law;
    ms_volume *v = make(&d);
    if (isa >= 0)
        v->isa = isa;
    ms_volume_fill_box(v, (float[3]){0, 0, 0}, (float[3]){0.15f, 0.1f, 0.2f});
    for (int f = 0; f < 6; ++f)
        step(v, 1.0f / 60);
    float hf[64];
    ck_assert_int_eq(ms_volume_extract_height(v, 8, 8, hf), MS_OK);
    uint64_t hsh = state_hash(v);
    for (int c = 0; c < 64; ++c) {
        uint32_t b;
        memcpy(&b, &hf[c], 4);
        hsh = (hsh ^ b) * 1099511628211ull;
    }
    for (int i = 0; i < v->n; ++i) { /* the pressure output too (DFSPH's read-out) */
        uint32_t b;
        memcpy(&b, &v->prs[i], 4);
        hsh = (hsh ^ b) * 1099511628211ull;
    }
    ms_volume_destroy(v);
    return hsh;
}

static uint64_t run_dam_isa(int threads, int isa)
{
    return run_dam_law(threads, isa, MS_PRESSURE_IDEAL_GAS);
}

static uint64_t run_dam(int threads)
{
    return run_dam_isa(threads, -1);
}

START_TEST(one_and_two_threads_give_the_same_bytes)
{
    uint64_t a = run_dam(1), b = run_dam(2), c = run_dam(1);
    ck_assert_msg(a == c, "two runs with one thread differ");
    ck_assert_msg(a == b, "1 and 2 threads differ");
}
END_TEST

/* DFSPH's iteration counts come from integer sums, so the thread split
 * cannot change them: 1 and 2 threads, and every instruction-set path of
 * the neighbour search and the other forces, give the same bytes. */
START_TEST(dfsph_gives_the_same_bytes_for_threads_and_instruction_sets)
{
    uint64_t a = run_dam_law(1, -1, MS_PRESSURE_DFSPH), b = run_dam_law(2, -1, MS_PRESSURE_DFSPH);
    ck_assert_msg(a == b, "DFSPH: 1 and 2 threads differ");
    ck_assert_msg(a != run_dam(1), "DFSPH ran the ideal gas law");
    for (int isa = MS_VOLUME_ISA_C; isa < MS_VOLUME_ISA_COUNT; ++isa)
        if (isa_here(isa))
            ck_assert_msg(run_dam_law(1, isa, MS_PRESSURE_DFSPH) == a, "DFSPH: path %s differs",
                          ms_volume_isa_name(isa));
}
END_TEST

/* Every instruction-set path this build has (plain C, SSE2, AVX2,
 * AVX-512; NEON on aarch64), picked at run time, gives the same bytes;
 * a path the CPU lacks is not applicable. */
START_TEST(every_instruction_set_path_gives_the_same_bytes)
{
    if (skip_under_tsan())
        MS_SKIP(TSAN_WHY);
    const uint64_t ref = run_dam_isa(1, MS_VOLUME_ISA_C);
    for (int isa = MS_VOLUME_ISA_C + 1; isa < MS_VOLUME_ISA_COUNT; ++isa)
        if (isa_here(isa))
            ck_assert_msg(run_dam_isa(1, isa) == ref, "path %s differs from plain C",
                          ms_volume_isa_name(isa));
}
END_TEST

/* The same bytes on every machine (as the every-effect scene's golden
 * hash in test_determinism, for the volume alone): the dam break above
 * under the ideal gas and under DFSPH, on the path this machine picks (or
 * MODESPLIT_ISA's), hashes to the values committed in GOLDEN_VOLUME_FILE.
 * The x86-64 paths and aarch64's NEON (make check-aarch64, under
 * qemu-user) answer to the same file; the cases above tie every other path
 * of a machine to the one picked. A change meant to change results
 * rewrites it with `make golden`. */
#define GOLDEN_VOLUME_FILE "tests/data/golden_volume_hash.txt"

START_TEST(the_dam_break_gives_the_committed_bytes)
{
    ms_build_info b;
    ck_assert_int_eq(ms_get_build_info(&b), MS_OK);
    const char *path = b.path_chosen;
    const unsigned long long h[2] = {run_dam_law(1, -1, MS_PRESSURE_IDEAL_GAS),
                                     run_dam_law(1, -1, MS_PRESSURE_DFSPH)};
    const char *write = getenv("MS_GOLDEN_WRITE");
    if (write && write[0] == '1') {
        FILE *f = fopen(GOLDEN_VOLUME_FILE, "w");
        ck_assert_msg(f != NULL, "cannot write %s (run from the source root)", GOLDEN_VOLUME_FILE);
        fprintf(f, "%016llx %016llx\n", h[0], h[1]);
        fclose(f);
        fprintf(stderr, "golden: wrote %016llx %016llx (path %s) to %s\n", h[0], h[1], path,
                GOLDEN_VOLUME_FILE);
        return;
    }
    FILE *f = fopen(GOLDEN_VOLUME_FILE, "r");
    ck_assert_msg(f != NULL, "%s is missing: run `make golden`", GOLDEN_VOLUME_FILE);
    unsigned long long want[2] = {0, 0};
    int got = fscanf(f, "%llx %llx", &want[0], &want[1]);
    fclose(f);
    ck_assert_int_eq(got, 2);
    ck_assert_msg(h[0] == want[0] && h[1] == want[1],
                  "the dam break on path %s hashes to %016llx (ideal gas) %016llx (DFSPH), %s "
                  "says %016llx %016llx: the results changed; if that is meant, run `make "
                  "golden` and commit it",
                  path, h[0], h[1], GOLDEN_VOLUME_FILE, want[0], want[1]);
}
END_TEST

/* MODESPLIT_ISA forces a path: a path this CPU runs is taken; a name
 * that is no path, or a path this CPU or build lacks, is refused with a
 * sentence naming the paths it has; ms_get_build_info says the same. */
START_TEST(modesplit_isa_forces_a_path_or_is_refused)
{
    ms_volume_desc d = box_desc(0.2f, 0.2f, 0.2f, 0.02f);
    for (int isa = MS_VOLUME_ISA_C; isa < MS_VOLUME_ISA_COUNT; ++isa) {
        ck_assert_int_eq(setenv("MODESPLIT_ISA", ms_volume_isa_name(isa), 1), 0);
        ms_volume *v = NULL;
        ms_build_info b;
        ms_status st = ms_volume_create(&d, &v);
        if (ms_volume_isa_runs(isa)) {
            ck_assert_int_eq(st, MS_OK);
            ck_assert_int_eq(v->isa, isa);
            ms_volume_destroy(v);
            ck_assert_int_eq(ms_get_build_info(&b), MS_OK);
            ck_assert_str_eq(b.path_chosen, ms_volume_isa_name(isa));
            ck_assert_ptr_nonnull(strstr(b.paths_cpu, ms_volume_isa_name(isa)));
        } else {
            ck_assert_int_eq(st, MS_ERR_UNSUPPORTED);
            ck_assert_ptr_null(v);
            ck_assert_msg(strstr(ms_last_error(), "this CPU runs") &&
                              strstr(ms_last_error(), "it has: c"),
                          "%s", ms_last_error());
            ck_assert_int_eq(ms_get_build_info(&b), MS_ERR_UNSUPPORTED);
            ck_assert_ptr_null(b.path_chosen);
        }
    }
    ck_assert_int_eq(setenv("MODESPLIT_ISA", "avx1024", 1), 0);
    ms_volume *v = NULL;
    ck_assert_int_eq(ms_volume_create(&d, &v), MS_ERR_INVALID_ARGUMENT);
    ck_assert_ptr_nonnull(strstr(ms_last_error(), "MODESPLIT_ISA=avx1024 names no path"));
    ck_assert_int_eq(unsetenv("MODESPLIT_ISA"), 0);
    ck_assert_int_eq(ms_volume_create(&d, &v), MS_OK);
    ck_assert_int_eq(v->isa, ms_volume_pick_isa());
    ms_volume_destroy(v);
    ms_build_info b;
    ck_assert_int_eq(ms_get_build_info(&b), MS_OK);
    ck_assert_str_eq(b.path_chosen, ms_volume_isa_name(ms_volume_pick_isa()));
    ck_assert_ptr_nonnull(strstr(b.paths_built, "c"));
    ck_assert(strlen(b.compiler) > 3);
}
END_TEST

/* `modesplit info --build` prints the compiler, the paths built and this
 * CPU's, and the one chosen; a MODESPLIT_ISA this CPU lacks is refused
 * (exit 2) with the sentence naming the paths it has. */
START_TEST(info_build_prints_the_paths_and_the_choice)
{
    char dir[512], out[600], err[600];
    ck_assert_int_eq(ms_test_tmp_dir(dir, sizeof dir, "info_build"), 0);
    snprintf(out, sizeof out, "%s/out.txt", dir);
    snprintf(err, sizeof err, "%s/err.txt", dir);
    const char *const args[] = {"info", "--build", NULL};
    ck_assert_int_eq(setenv("MODESPLIT_ISA", "c", 1), 0);
    int st = ms_test_run_tool(args, out, err);
    ck_assert(WIFEXITED(st) && WEXITSTATUS(st) == 0);
    char *o = ms_test_slurp(out);
    ck_assert_msg(strstr(o, "compiler") && strstr(o, "chosen    c (MODESPLIT_ISA)") &&
                      strstr(o, "(this CPU)"),
                  "%s", o);
    free(o);
    int lacking = -1;
    for (int isa = MS_VOLUME_ISA_C; isa < MS_VOLUME_ISA_COUNT; ++isa)
        if (!ms_volume_isa_runs(isa))
            lacking = isa;
    if (lacking >= 0) { /* NEON on x86-64, SSE2 on aarch64 */
        ck_assert_int_eq(setenv("MODESPLIT_ISA", ms_volume_isa_name(lacking), 1), 0);
        st = ms_test_run_tool(args, out, err);
        ck_assert(WIFEXITED(st) && WEXITSTATUS(st) == 2);
        char *e = ms_test_slurp(err);
        ck_assert_msg(strstr(e, "not a path this CPU runs") && strstr(e, "it has: c"), "%s", e);
        free(e);
    }
    ck_assert_int_eq(unsetenv("MODESPLIT_ISA"), 0);
    ms_test_remove_tree(dir);
}
END_TEST

/* ---- the passes against a double-precision reference ----
 *
 * Density (eq. 9, spiky kernel of eq. 11), the law's pressure, and the
 * pressure and viscosity accelerations (eqs. 13, 14) of every path, checked
 * against sums in double over every pair (all particles, no grid, no
 * lists) and every wall image (each nonempty set of the walls within h of
 * the particle, the neighbour reflected across them), in hard layouts.
 * The forces' reference takes the pass's own float p and 1/rho (checked
 * first), so each check bounds one pass's rounding.
 *
 * The bounds, u = 2^-24 (float rounding), for a pair at distance r, t =
 * h - r: the list's r^2 = fl(fl(dx^2) + fl(dy^2) + fl(dz^2)) has
 * relative error <= 5u, so r (one more rounding in sqrt) <= 3.5u h
 * absolute, and fl(h - r) carries <= 4u h; t^3's two products add 2u
 * relative: a term's error <= 3 t^2 4u h + 3u t^3 <= u (12 h t^2 + 3 t^3).
 * A sum of the 16 lanes, each a chain of nb blocks, then a 4-level tree,
 * adds at most (nb + 4) u sum |terms| (recursive summation). With m K
 * (two roundings) and the product by it: 3u rho more. Pressure p =
 * k (rho - rho0): <= 2u |p| (+ u k |rho|: the difference's rounding).
 * The force terms: t as above, fv = (1/rho_j) t, fp = (p_i + p_j) fv t /
 * r, times x_i - x_j' (fl of a difference of coordinates <= L, the
 * domain's extent: <= 2u L; a reflected one 2 w - x one more); an error
 * in t moves fp by |dfp/dt| 4u h = 2 |fp| / t 4u h, bounded via
 * |(p_i + p_j) / rho_j| 2 t / r 4u h without the division by t; fp's
 * own four roundings and the product's: 6u |fp dx|. Viscosity: fv's
 * 4u h / rho_j |dv| and 2u |fv dv| + u |fv| (|v_i| + |v_j|) for the
 * velocity difference. The acceleration cp/rho_i s_p + cv/rho_i s_v + b +
 * g: the sums' errors times |cp/rho_i|, |cv/rho_i|, and 6u of each
 * addend's size. A bug in a pass (a lost pair, a wrong image, a swapped
 * lane) moves a sum by a whole term, far above these bounds. */
enum { REF_CORNER, REF_SHEET, REF_SPLASH, REF_LAYOUTS };

static uint64_t ref_rng(uint64_t *s)
{
    *s = *s * 6364136223846793005ull + 1442695040888963407ull;
    return *s >> 11;
}
static float ref_uniform(uint64_t *s, float lo, float hi)
{
    return lo + (hi - lo) * (float)((double)ref_rng(s) / 9007199254740992.0);
}

/* Particles of layout k into a volume of box L^3 with spacing s; returns
 * the count. */
static int ref_layout(int k, float L, float s, float *pos, float *vel, int cap)
{
    uint64_t seed = 12345u + 977u * (uint64_t)k;
    int n = 0;
    if (k == REF_CORNER) { /* a jittered block in the corner: 7 images at once */
        for (int a = 0; a < 13; ++a)
            for (int b = 0; b < 13; ++b)
                for (int c = 0; c < 13 && n < cap; ++c, ++n) {
                    const int q[3] = {a, b, c};
                    for (int d = 0; d < 3; ++d)
                        pos[3 * n + d] =
                            (0.5f + (float)q[d]) * s + ref_uniform(&seed, -0.2f, 0.2f) * s;
                }
    } else if (k == REF_SHEET) { /* two layers in mid-air, most particles at the surface */
        for (int a = 0; a < 40; ++a)
            for (int b = 0; b < 40; ++b)
                for (int c = 0; c < 2 && n < cap; ++c, ++n) {
                    pos[3 * n] =
                        0.5f * L + ((float)a - 20.0f) * s + ref_uniform(&seed, -0.1f, 0.1f) * s;
                    pos[3 * n + 1] =
                        0.5f * L + ((float)b - 20.0f) * s + ref_uniform(&seed, -0.1f, 0.1f) * s;
                    pos[3 * n + 2] = 0.5f * L + (float)c * s + ref_uniform(&seed, -0.1f, 0.1f) * s;
                }
    } else { /* a splash: a random cloud against a wall, uneven density */
        while (n < 2500 && n < cap) {
            float p[3] = {ref_uniform(&seed, 0.0f, 6.0f * s),
                          ref_uniform(&seed, 0.3f * L, 0.7f * L),
                          ref_uniform(&seed, 0.3f * L, 0.7f * L)};
            int ok = 1;
            for (int j = 0; j < n && ok; ++j) {
                const float dx = p[0] - pos[3 * j], dy = p[1] - pos[3 * j + 1],
                            dz = p[2] - pos[3 * j + 2];
                ok = dx * dx + dy * dy + dz * dz > 0.04f * s * s; /* no coincident pairs */
            }
            if (ok) {
                memcpy(pos + 3 * n, p, sizeof p);
                n++;
            }
        }
    }
    for (int i = 0; i < 3 * n; ++i)
        vel[i] = ref_uniform(&seed, -1.0f, 1.0f); /* m/s */
    return n;
}

typedef struct ref_out {
    double rho, rho_tol, ax[3], a_tol[3];
} ref_out;

/* The reference of particle i of v (cell order) after the passes, from
 * v's own float positions, velocities and (forces) p and 1/rho. */
static ref_out ref_particle(const ms_volume *v, int i)
{
    const double u = 1.0 / 16777216.0, h = v->K.h, L = v->desc.domain_max[0];
    const double K = 15.0 / (3.14159265358979323846 * h * h * h * h * h * h);
    float wallf[3];
    const unsigned near = ms_volume_walls_near(v, v->x[i], v->y[i], v->z[i], wallf);
    const double xi[3] = {v->x[i], v->y[i], v->z[i]}, ui[3] = {v->vx[i], v->vy[i], v->vz[i]};
    const double pi = v->prs[i], eps = sqrt((double)v->eps2);
    double w = 0.0, werr = 0.0, sp[3] = {0}, sv[3] = {0}, ep[3] = {0}, evv[3] = {0};
    double absp[3] = {0}, absv[3] = {0};
    int terms = 0;
    for (unsigned set = 0; set < 8; ++set) { /* set 0: the real neighbours */
        if (set & ~near)
            continue;
        for (int j = 0; j < v->n; ++j) {
            double xj[3] = {v->x[j], v->y[j], v->z[j]}, uj[3] = {v->vx[j], v->vy[j], v->vz[j]};
            for (int d = 0; d < 3; ++d)
                if (set & (1u << d)) {
                    xj[d] = 2.0 * (double)wallf[d] - xj[d];
                    uj[d] = -uj[d];
                }
            const double dx[3] = {xi[0] - xj[0], xi[1] - xj[1], xi[2] - xj[2]};
            const double r = sqrt(dx[0] * dx[0] + dx[1] * dx[1] + dx[2] * dx[2]);
            if (!(r < h))
                continue;
            const double t = h - r;
            w += t * t * t;
            werr += 12.0 * h * t * t + 3.0 * t * t * t;
            terms++;
            if (r <= eps)
                continue; /* itself: no direction, no force */
            const double irj = v->inv_rho[j], pp = pi + v->prs[j];
            const double fv = irj * t, fp = pp * fv * t / r;
            for (int d = 0; d < 3; ++d) {
                const double tp = fp * dx[d], tv = fv * (uj[d] - ui[d]);
                sp[d] += tp;
                sv[d] += tv;
                absp[d] += fabs(tp);
                absv[d] += fabs(tv);
                ep[d] += fabs(pp * irj) * 2.0 * t / r * 4.0 * u * h * fabs(dx[d]) +
                         6.0 * u * fabs(tp) + fabs(fp) * 3.0 * u * L;
                evv[d] += irj * 4.0 * u * h * fabs(uj[d] - ui[d]) + 2.0 * u * fabs(tv) +
                          u * fabs(fv) * (fabs(uj[d]) + fabs(ui[d]));
            }
        }
    }
    const double nb = terms / 16.0 + 2.0 + 4.0; /* blocks of each lane's chain, and the tree */
    ref_out o;
    o.rho = v->mass * K * w;
    o.rho_tol = v->mass * K * (u * werr + nb * u * w) + 3.0 * u * o.rho;
    const double cp = 0.5f * v->press_scale * v->mass * v->K.spiky_grad;
    const double cv = 0.5f * v->mass * v->K.visc_lap * v->desc.viscosity;
    const double ri = v->inv_rho[i], b[3] = {v->b_ax[i], v->b_ay[i], v->b_az[i]};
    for (int d = 0; d < 3; ++d) {
        const double a_p = cp * ri * sp[d], a_v = cv * ri * sv[d];
        o.ax[d] = a_p + a_v + b[d] + v->desc.gravity[d];
        o.a_tol[d] = fabs(cp * ri) * (ep[d] + nb * u * absp[d]) +
                     fabs(cv * ri) * (evv[d] + nb * u * absv[d]) +
                     6.0 * u * (fabs(a_p) + fabs(a_v) + fabs(b[d]) + fabs(v->desc.gravity[d]));
    }
    return o;
}

START_TEST(every_path_matches_a_double_precision_reference)
{
    if (skip_under_tsan())
        MS_SKIP(TSAN_WHY);
    const float L = 1.0f, s = 0.02f; /* m */
    enum { CAP = 4000 };
    float *pos = malloc(sizeof(float) * 3 * CAP), *vel = malloc(sizeof(float) * 3 * CAP);
    ref_out *ref = malloc(sizeof(ref_out) * CAP);
    ck_assert_ptr_nonnull(ref);
    ck_assert_ptr_nonnull(pos);
    ck_assert_ptr_nonnull(vel);
    static const char *const names[REF_LAYOUTS] = {"wall corner", "thin sheet", "splash"};
    for (int k = 0; k < REF_LAYOUTS; ++k) {
        const int n = ref_layout(k, L, s, pos, vel, CAP);
        ck_assert_int_gt(n, 2000);
        for (int isa = MS_VOLUME_ISA_C; isa < MS_VOLUME_ISA_COUNT; ++isa) {
            if (!isa_here(isa))
                continue;
            ms_volume_desc d = box_desc(L, L, L, s);
            d.viscosity = 5.0f; /* Pa s: a viscosity sum as large as the pressure's */
            ms_volume *v = make(&d);
            v->isa = isa;
            ck_assert_int_eq(ms_volume_add_particles(v, n, pos, vel), MS_OK);
            ms_volume_grid_build(v);
            ms_volume_boundary(v, 0.0);
            ck_assert_int_eq(ms_volume_density(v), MS_OK);
            ms_volume_forces(v);
            double worst_rho = 0.0, worst_a = 0.0, max_drho = 0.0;
            int images = 0;
            if (isa == MS_VOLUME_ISA_C) /* the inputs are the same bytes on every path */
                for (int i = 0; i < v->n; ++i)
                    ref[i] = ref_particle(v, i);
            for (int i = 0; i < v->n; ++i) {
                const ref_out o = ref[i];
                float wall[3];
                images += ms_volume_walls_near(v, v->x[i], v->y[i], v->z[i], wall) != 0;
                const double e = fabs(v->rho[i] - o.rho);
                ck_assert_msg(e <= o.rho_tol,
                              "%s, path %s, particle %d: rho %.9g, reference %.9g (off %.3g, "
                              "bound %.3g kg/m^3)",
                              names[k], ms_volume_isa_name(isa), i, (double)v->rho[i], o.rho, e,
                              o.rho_tol);
                worst_rho = fmax(worst_rho, e / o.rho_tol);
                max_drho = fmax(max_drho, e);
                /* the law's pressure and 1/rho of the pass's rho */
                const double p =
                    fmax(v->desc.gas_constant * ((double)v->rho[i] - v->desc.rest_density), 0.0);
                ck_assert_msg(fabs(v->prs[i] - p) <=
                                  2.0 * 5.96e-8 * p + 5.96e-8 * v->desc.gas_constant * v->rho[i],
                              "%s, path %s: p %.9g, law %.9g", names[k], ms_volume_isa_name(isa),
                              (double)v->prs[i], p);
                ck_assert(fabs(v->inv_rho[i] - 1.0 / v->rho[i]) <= 5.96e-8 / v->rho[i]);
                const float a[3] = {v->ax[i], v->ay[i], v->az[i]};
                for (int c = 0; c < 3; ++c) {
                    const double ea = fabs(a[c] - o.ax[c]);
                    ck_assert_msg(ea <= o.a_tol[c],
                                  "%s, path %s, particle %d, axis %d: a %.9g, reference %.9g "
                                  "(off %.3g, bound %.3g m/s^2)",
                                  names[k], ms_volume_isa_name(isa), i, c, (double)a[c], o.ax[c],
                                  ea, o.a_tol[c]);
                    worst_a = fmax(worst_a, ea / o.a_tol[c]);
                }
            }
            if (k != REF_SHEET)
                ck_assert_int_gt(images, n / 10); /* the walls' images were exercised */
            if (isa == MS_VOLUME_ISA_C)
                fprintf(stderr,
                        "reference, %s: %d particles, %d at walls; worst error / bound: "
                        "density %.2g, acceleration %.2g\n",
                        names[k], n, images, worst_rho, worst_a);
            ms_volume_destroy(v);
        }
    }
    free(pos);
    free(vel);
    free(ref);
}
END_TEST

/* The same with the poly6 density kernel, the ideal gas and Tait laws
 * and a moving sphere in the liquid (its shape images take the force
 * pass's C loop on every path; the wall field, damping, weight sums and
 * pressure laws have AVX-512 loops of their own):
 * every path gives the same bytes. */
static uint64_t run_ball_isa(int isa, ms_pressure law)
{
    ms_volume_desc d = box_desc(0.5f, 0.1f, 0.25f, 0.01f);
    d.density_kernel = MS_DENSITY_POLY6;
    d.pressure = law;
    d.viscosity = 2.0f;
    ms_volume *v = make(&d);
    v->isa = isa;
    ms_shape *ball = NULL;
    ck_assert_int_eq(ms_shape_create("sphere", "{\"radius\": 0.03}", &ball), MS_OK);
    ck_assert_int_eq(
        ms_shape_set_pose(ball, (float[3]){0.05f, 0.05f, 0.05f}, (float[3]){0.5f, 0.0f, 0.0f}),
        MS_OK);
    ck_assert_int_eq(ms_volume_add_collider(v, ball), MS_OK);
    ms_volume_fill_box(v, (float[3]){0, 0, 0}, (float[3]){0.15f, 0.1f, 0.2f});
    /* two frames: 178 sub-steps (ideal gas) or 357 (Tait) here, every pass and the
     * sphere's images on each, and a differing bit grows through them;
     * more frames only repeat the same loops (8 runs: the case's cost) */
    for (int f = 0; f < 2; ++f)
        step(v, 1.0f / 60);
    uint64_t hsh = state_hash(v);
    ms_volume_destroy(v);
    ms_shape_destroy(ball);
    return hsh;
}

START_TEST(every_instruction_set_path_gives_the_same_bytes_with_poly6_and_a_shape)
{
    if (skip_under_tsan())
        MS_SKIP(TSAN_WHY);
    const ms_pressure laws[2] = {MS_PRESSURE_IDEAL_GAS, MS_PRESSURE_TAIT};
    for (int k = 0; k < 2; ++k) {
        const uint64_t ref = run_ball_isa(MS_VOLUME_ISA_C, laws[k]);
        for (int isa = MS_VOLUME_ISA_C + 1; isa < MS_VOLUME_ISA_COUNT; ++isa)
            if (isa_here(isa))
                ck_assert_msg(run_ball_isa(isa, laws[k]) == ref,
                              "law %d: path %s differs from plain C", (int)laws[k],
                              ms_volume_isa_name(isa));
    }
}
END_TEST

/* All particles started at one point: pushed apart (coincident pairs get
 * a direction from their ids), none lost, nothing non-finite, and the
 * kinetic energy bounded by the compression energy the start stored
 * (an ideal gas stores at most k ln(rho/rho0) per kg). */
START_TEST(all_particles_at_one_point_spread_and_stay_bounded)
{
    ms_volume_desc d = box_desc(0.6f, 0.6f, 0.6f, 0.03f);
    d.viscosity = 2.0f;
    ms_volume *v = make(&d);
    enum { N = 400 };
    float *p = malloc(sizeof(float) * 3 * N);
    for (int i = 0; i < N; ++i) {
        p[3 * i] = 0.3f;
        p[3 * i + 1] = 0.3f;
        p[3 * i + 2] = 0.3f;
    }
    ck_assert_int_eq(ms_volume_add_particles(v, N, p, NULL), MS_OK);
    ms_volume_grid_build(v);
    ms_volume_boundary(v, 0.0);
    ck_assert_int_eq(ms_volume_density(v), MS_OK);
    ck_assert_int_gt(v->coincident, 0);
    ms_volume_info in = ms_volume_info_init();
    ms_volume_get_info(v, &in);
    const double mass = (double)in.particle_mass * N;
    const double bound = mass * (d.gas_constant * log(v->rho[0] / d.rest_density) + 9.81 * 0.6);
    double emax = 0.0;
    for (int f = 0; f < 60; ++f) {
        step(v, 1.0f / 60);
        emax = fmax(emax, ms_volume_kinetic_energy(v));
        assert_sane(v, &d);
    }
    ck_assert_int_eq(ms_volume_count(v), N);
    ck_assert_msg(emax < bound, "kinetic energy %g J over the stored %g J", emax, bound);
    /* spread: no two particles left at one point */
    ms_volume_get_particles(v, p, NULL);
    float spread = 0.0f;
    for (int i = 1; i < N; ++i)
        spread = fmaxf(spread, fabsf(p[3 * i] - p[0]) + fabsf(p[3 * i + 1] - p[1]));
    ck_assert(spread > 0.1f);
    free(p);
    ms_volume_destroy(v);
}
END_TEST

/* A 100x viscosity jump mid-run: the viscous bound takes over the time
 * step, nothing blows up, and viscosity only takes energy out. */
START_TEST(a_hundredfold_viscosity_jump_stays_stable)
{
    if (skip_under_tsan())
        MS_SKIP(TSAN_WHY);
    ms_volume_desc d = box_desc(0.2f, 0.04f, 0.12f, 0.01f);
    d.viscosity = 2.0f;
    ms_volume *v = make(&d);
    ms_volume_fill_box(v, (float[3]){0, 0, 0}, (float[3]){0.08f, 0.04f, 0.1f});
    for (int f = 0; f < 6; ++f)
        step(v, 1.0f / 60); /* the dam is breaking */
    ck_assert_int_eq(ms_volume_set_viscosity(v, 200.0f), MS_OK);
    double e0 = mechanical_energy(v, &d);
    double prev = e0;
    for (int f = 0; f < 20; ++f) {
        step(v, 1.0f / 60);
        double e = mechanical_energy(v, &d);
        ck_assert_msg(e <= prev * 1.002 + 1e-6, "energy rose from %g to %g J", prev, e);
        prev = e;
        assert_sane(v, &d);
    }
    ms_volume_info in = ms_volume_info_init();
    ms_volume_get_info(v, &in);
    ck_assert_str_eq(in.dt_limit, "viscous");
    ck_assert(prev < e0);
    ms_volume_destroy(v);
}
END_TEST

/* 10 000 sub-steps at the largest CFL number allowed (0.5) of a sloshing
 * block: nothing non-finite, none lost, and the mechanical energy never
 * above its start (no energy is made). MS_TEST_LONG=1: more particles. */
START_TEST(ten_thousand_steps_at_the_largest_step_stay_bounded)
{
    if (skip_under_tsan())
        MS_SKIP(TSAN_WHY);
    const int big = long_tests();
    ms_volume_desc d = box_desc(0.3f, big ? 0.15f : 0.06f, 0.3f, 0.015f);
    d.courant = 0.5f;
    d.viscosity = 0.5f;
    ms_volume *v = make(&d);
    ms_volume_fill_box(v, (float[3]){0, 0, 0}, (float[3]){0.12f, d.domain_max[1], 0.15f});
    const int n = ms_volume_count(v);
    const double e0 = mechanical_energy(v, &d);
    ms_volume_info in = ms_volume_info_init();
    long frames = 0;
    do {
        step(v, 0.05f);
        ms_volume_get_info(v, &in);
        double e = mechanical_energy(v, &d);
        ck_assert_msg(e <= e0 * 1.001, "energy %g J over the start %g J at t = %g s", e, e0,
                      in.time);
        if (++frames % 20 == 0)
            assert_sane(v, &d);
    } while (in.substeps < 10000);
    assert_sane(v, &d);
    ck_assert_int_eq(ms_volume_count(v), n);
    ms_volume_destroy(v);
}
END_TEST

/* A frame hitch (dt = 1 s) is sub-stepped in full (not clamped): the
 * whole second is simulated, every sub-step within the bounds, and the
 * state stays sane. */
START_TEST(a_one_second_frame_hitch_is_substepped)
{
    if (skip_under_tsan())
        MS_SKIP(TSAN_WHY);
    ms_volume_desc d = box_desc(0.2f, 0.04f, 0.12f, 0.01f);
    ms_volume *v = make(&d), *w = make(&d);
    ms_volume_fill_box(v, (float[3]){0, 0, 0}, (float[3]){0.06f, 0.04f, 0.1f});
    ms_volume_fill_box(w, (float[3]){0, 0, 0}, (float[3]){0.06f, 0.04f, 0.1f});
    const double e0 = mechanical_energy(v, &d);
    step(v, 1.0f);
    for (int f = 0; f < 60; ++f) /* the same second in frames */
        step(w, 1.0f / 60);
    ms_volume_info in = ms_volume_info_init();
    ms_volume_get_info(v, &in);
    ck_assert_float_eq_tol(in.time, 1.0, 1e-6);
    ck_assert(in.substeps > 100);
    ck_assert(in.last_dt <= in.max_dt * 1.0001f);
    assert_sane(v, &d);
    /* No energy is created, the collapse ran (measured: 0.095 J -> 0.030 J,
     * kinetic 0.0011 J), and the hitch ends where 60 frames end (measured
     * 0.0300 J and 0.0302 J): sub-stepped in full, not clamped. */
    const double e1 = mechanical_energy(v, &d), e60 = mechanical_energy(w, &d);
    ck_assert_msg(e1 < 0.5 * e0, "energy %g J after 1 s from %g J: the column did not fall", e1,
                  e0);
    ck_assert_msg(ms_volume_kinetic_energy(v) < 0.05 * e0, "kinetic %g J of %g J",
                  ms_volume_kinetic_energy(v), e0);
    ck_assert_msg(fabs(e1 - e60) < 0.05 * e0, "1 s step: %g J, 60 frames: %g J", e1, e60);
    ms_volume_destroy(v);
    ms_volume_destroy(w);
}
END_TEST

/* ---------------------------------------------------------- interaction */

START_TEST(drag_pulls_towards_its_velocity_and_never_past_it)
{
    ms_volume_desc d = box_desc(0.6f, 0.6f, 0.4f, 0.03f);
    d.gravity[2] = 0.0f;
    ms_volume *v = make(&d);
    ms_volume_fill_box(v, (float[3]){0.15f, 0.15f, 0.0f}, (float[3]){0.45f, 0.45f, 0.15f});
    float c[3] = {0.3f, 0.3f, 0.075f}, target[3] = {0.5f, 0.0f, 0.0f};
    int n = ms_volume_count(v), reach = 0;
    float *u = malloc(sizeof(float) * 3 * (size_t)n);
    ms_volume_get_particles(v, u, NULL);
    for (int i = 0; i < n; ++i) {
        float dx = u[3 * i] - c[0], dy = u[3 * i + 1] - c[1], dz = u[3 * i + 2] - c[2];
        reach += dx * dx + dy * dy + dz * dz < 0.1f * 0.1f;
    }
    for (int f = 0; f < 5; ++f) {
        ck_assert_int_eq(ms_volume_drag(v, c, 0.1f, target, 50.0f), MS_OK);
        step(v, 1.0f / 60);
    }
    ms_volume_get_particles(v, NULL, u);
    double mx = 0.0;
    for (int i = 0; i < n; ++i)
        mx += u[3 * i];
    /* Measured: mean vx 0.043 m/s (500 particles). Lower bound half of
     * that; upper bound from momentum: the drag never makes a particle
     * faster than 0.5 m/s and reached only those within its radius at the
     * start (1.5 x for the few that flowed in). */
    ck_assert_msg(mx / n > 0.02, "mean vx %g after dragging at 0.5 m/s", mx / n);
    ck_assert_msg(mx / n < 1.5 * 0.5 * reach / n, "mean vx %g over what %d dragged particles hold",
                  mx / n, reach);
    ms_volume_info in = ms_volume_info_init();
    ms_volume_get_info(v, &in);
    ck_assert(in.max_speed < 0.6f);
    free(u);
    ms_volume_destroy(v);
}
END_TEST

START_TEST(push_accelerates_only_inside_its_radius)
{
    ms_volume_desc d = box_desc(1.0f, 1.0f, 1.0f, 0.05f);
    d.gravity[2] = 0.0f;
    ms_volume *v = make(&d);
    float p[6] = {0.3f, 0.5f, 0.5f, 0.7f, 0.5f, 0.5f};
    ck_assert_int_eq(ms_volume_add_particles(v, 2, p, NULL), MS_OK);
    ck_assert_int_eq(ms_volume_push(v, (float[3]){0.3f, 0.5f, 0.5f}, 0.3f, (float[3]){0, 0, 4}),
                     MS_OK);
    step(v, 0.1f);
    float u[6];
    ms_volume_get_particles(v, NULL, u);
    /* 4 m/s^2 for 0.1 s at a weight (1 - r/R)^2 that falls from 1 to 0.87
     * as it rises 2 cm from the centre */
    ck_assert(u[2] > 0.9f * 0.4f && u[2] < 0.4f);
    ck_assert_float_eq_tol(u[5], 0.0f, 1e-6f);
    ms_volume_destroy(v);
}
END_TEST

START_TEST(remove_box_removes_and_keeps_the_order_of_the_rest)
{
    ms_volume_desc d = box_desc(0.4f, 0.4f, 0.4f, 0.04f);
    ms_volume *v = make(&d);
    ms_volume_fill_box(v, (float[3]){0, 0, 0}, (float[3]){0.4f, 0.4f, 0.08f});
    int n0 = ms_volume_count(v); /* 10 x 10 x 2 */
    float *p0 = malloc(sizeof(float) * 3 * (size_t)n0);
    step(v, 0.01f); /* reorders internally */
    ms_volume_get_particles(v, p0, NULL);
    int removed = -1;
    ck_assert_int_eq(
        ms_volume_remove_box(v, (float[3]){0, 0, 0}, (float[3]){0.2f, 0.4f, 0.4f}, &removed),
        MS_OK);
    ck_assert_int_eq(removed, n0 / 2);
    ck_assert_int_eq(ms_volume_count(v), n0 - removed);
    float *p1 = malloc(sizeof(float) * 3 * (size_t)n0);
    ms_volume_get_particles(v, p1, NULL);
    int k = 0;
    for (int i = 0; i < n0; ++i) {
        if (p0[3 * i] <= 0.2f)
            continue;
        ck_assert_float_eq(p1[3 * k], p0[3 * i]);
        ck_assert_float_eq(p1[3 * k + 2], p0[3 * i + 2]);
        k++;
    }
    ck_assert_int_eq(k, n0 - removed);
    free(p0);
    free(p1);
    ms_volume_destroy(v);
}
END_TEST

/* Coupling from the waves: gain 0 changes nothing; with gain, a rising
 * wave lifts the surface particles towards the wave's speed, never past. */
START_TEST(waves_nudge_surface_particles_without_adding_unbounded_energy)
{
    ms_volume_desc d = box_desc(0.4f, 0.4f, 0.3f, 0.02f);
    d.gravity[2] = 0.0f;
    ms_volume *v = make(&d);
    ms_volume_fill_box(v, (float[3]){0, 0, 0}, (float[3]){0.4f, 0.4f, 0.1f});
    ms_grid g = {.nx = 8, .ny = 8, .dx = 0.05f, .dy = 0.05f, .origin = {0, 0}};
    float w[64] = {0};
    uint64_t before = state_hash(v);
    for (int c = 0; c < 64; ++c)
        w[c] = 0.01f * (float)(c % 3);
    ck_assert_int_eq(ms_volume_adapt_to_waves(v, w, &g, 0.0f), MS_OK);
    ck_assert(state_hash(v) == before); /* gain 0: off */
    /* with gain: record, let 0.01 s pass, raise the waves by 1 cm: u = 1 m/s */
    for (int c = 0; c < 64; ++c)
        w[c] = 0.0f;
    ck_assert_int_eq(ms_volume_adapt_to_waves(v, w, &g, 0.5f), MS_OK);
    step(v, 0.01f);
    for (int c = 0; c < 64; ++c)
        w[c] = 0.01f;
    ck_assert_int_eq(ms_volume_adapt_to_waves(v, w, &g, 0.5f), MS_OK);
    int n = ms_volume_count(v), lifted = 0;
    float *p = malloc(sizeof(float) * 3 * (size_t)n), *u = malloc(sizeof(float) * 3 * (size_t)n);
    ms_volume_get_particles(v, p, u);
    for (int i = 0; i < n; ++i) {
        ck_assert(u[3 * i + 2] <= 1.0f + 1e-3f); /* never past the wave's speed */
        if (p[3 * i + 2] > 0.08f && u[3 * i + 2] > 0.4f)
            lifted++;
    }
    ck_assert_int_gt(lifted, 100); /* the top layer: 20 x 20 */
    free(p);
    free(u);
    ms_volume_destroy(v);
}
END_TEST

/* ---------------------------------------------------------------- views */

/* The views of ms_volume_particles hold exactly what ms_volume_get_particles
 * copies out (insertion order), byte for byte, at equal distances. */
static void assert_views_current(ms_volume *v, const float *pos[3], const float *vel[3])
{
    int n = ms_volume_count(v);
    ck_assert(pos[0] && vel[0]);
    ck_assert(pos[1] - pos[0] > 0 && pos[2] - pos[1] == pos[1] - pos[0]);
    ck_assert(vel[1] - vel[0] == pos[1] - pos[0] && vel[2] - vel[1] == pos[1] - pos[0]);
    float *p = malloc(sizeof(float) * 3 * (size_t)(n + 1));
    float *u = malloc(sizeof(float) * 3 * (size_t)(n + 1));
    ck_assert_int_eq(ms_volume_get_particles(v, p, u), MS_OK);
    for (int i = 0; i < n; ++i)
        for (int a = 0; a < 3; ++a) {
            ck_assert_msg(memcmp(&pos[a][i], &p[3 * i + a], sizeof(float)) == 0,
                          "particle %d axis %d: view %g, copy %g", i, a, pos[a][i], p[3 * i + a]);
            ck_assert_msg(memcmp(&vel[a][i], &u[3 * i + a], sizeof(float)) == 0,
                          "particle %d axis %d: velocity view %g, copy %g", i, a, vel[a][i],
                          u[3 * i + a]);
        }
    free(p);
    free(u);
}

START_TEST(particle_views_stay_current_across_steps_and_count_changes)
{
    ms_volume_desc d = box_desc(0.4f, 0.4f, 0.8f, 0.04f);
    ms_volume *v = make(&d);
    int n = -1;
    const float *pos[3], *vel[3];
    MS_ASSERT_REFUSED(ms_volume_particles(NULL, &n, pos, vel), MS_ERR_INVALID_ARGUMENT, "volume");
    MS_ASSERT_REFUSED(ms_volume_particles(v, NULL, pos, vel), MS_ERR_INVALID_ARGUMENT, "n");
    /* never held a particle: no storage, NULL views */
    ck_assert_int_eq(ms_volume_particles(v, &n, pos, vel), MS_OK);
    ck_assert(n == 0 && pos[0] == NULL && vel[2] == NULL);
    ms_volume_info before = ms_volume_info_init(), after = ms_volume_info_init();
    ms_volume_fill_box(v, (float[3]){0, 0, 0}, (float[3]){0.4f, 0.4f, 0.12f}); /* 10x10x3 */
    ck_assert_int_eq(ms_volume_particles(v, &n, pos, vel), MS_OK);
    ck_assert_int_eq(n, 300);
    assert_views_current(v, pos, vel);
    const float *p0 = pos[0], *v0 = vel[0];
    /* steps reorder the particles internally; the views keep their place
     * and follow the state (insertion order) */
    for (int f = 0; f < 5; ++f) {
        step(v, 1.0f / 60);
        assert_views_current(v, pos, vel);
    }
    ck_assert(vel[2][0] != 0.0f); /* they moved: the views are not the start */
    ck_assert_int_eq(ms_volume_particles(v, &n, pos, vel), MS_OK);
    ck_assert(pos[0] == p0 && vel[0] == v0 && n == 300);
    /* removal: same place, the survivors first */
    int removed = 0;
    ck_assert_int_eq(
        ms_volume_remove_box(v, (float[3]){0, 0, 0}, (float[3]){0.2f, 0.4f, 0.4f}, &removed),
        MS_OK);
    ck_assert_int_gt(removed, 0);
    ck_assert_int_eq(ms_volume_particles(v, &n, pos, vel), MS_OK);
    ck_assert(pos[0] == p0 && n == 300 - removed);
    assert_views_current(v, pos, vel);
    /* an added particle within the storage: same place */
    float q[3] = {0.1f, 0.1f, 0.3f}, qv[3] = {0.5f, 0, 0};
    ck_assert_int_eq(ms_volume_add_particles(v, 1, q, qv), MS_OK);
    ck_assert_int_eq(ms_volume_particles(v, &n, pos, vel), MS_OK);
    ck_assert(pos[0] == p0 && n == 301 - removed);
    ck_assert(pos[0][n - 1] == 0.1f && vel[0][n - 1] == 0.5f);
    assert_views_current(v, pos, vel);
    /* the coupling from the waves changes vz: the views follow */
    ms_grid g = {.nx = 8, .ny = 8, .dx = 0.05f, .dy = 0.05f};
    float w[64] = {0};
    ck_assert_int_eq(ms_volume_adapt_to_waves(v, w, &g, 0.5f), MS_OK);
    step(v, 0.01f);
    for (int c = 0; c < 64; ++c)
        w[c] = 0.01f;
    ck_assert_int_eq(ms_volume_adapt_to_waves(v, w, &g, 0.5f), MS_OK);
    assert_views_current(v, pos, vel);
    /* growth past the storage (1024 particles) moves them: call again */
    ms_volume_get_info(v, &before);
    ck_assert_int_eq(ms_volume_fill_box(v, (float[3]){0, 0, 0.2f}, (float[3]){0.4f, 0.4f, 0.8f}),
                     MS_OK);
    ck_assert_int_gt(ms_volume_count(v), 1024);
    ck_assert_int_eq(ms_volume_particles(v, &n, pos, vel), MS_OK);
    ck_assert_int_eq(n, ms_volume_count(v));
    assert_views_current(v, pos, vel);
    step(v, 1.0f / 60);
    assert_views_current(v, pos, vel);
    ms_volume_get_info(v, &after);
    ck_assert(after.bytes > before.bytes);
    ms_volume_destroy(v);
}
END_TEST

/* The views are a copy out of the state: asking for them changes nothing
 * the simulation computes (same bytes as a volume that never asked). */
START_TEST(particle_views_do_not_change_the_simulation)
{
    ms_volume_desc d = box_desc(0.4f, 0.4f, 0.4f, 0.04f);
    ms_volume *a = make(&d), *b = make(&d);
    int n;
    const float *pos[3], *vel[3];
    ck_assert_int_eq(ms_volume_particles(a, &n, pos, vel), MS_OK); /* before any particle */
    for (int k = 0; k < 2; ++k)
        ms_volume_fill_box(k ? b : a, (float[3]){0, 0, 0}, (float[3]){0.2f, 0.4f, 0.2f});
    for (int f = 0; f < 10; ++f) {
        step(a, 1.0f / 60);
        step(b, 1.0f / 60);
    }
    n = ms_volume_count(a);
    ck_assert_int_eq(n, ms_volume_count(b));
    float *pa = malloc(sizeof(float) * 6 * (size_t)n), *pb = malloc(sizeof(float) * 6 * (size_t)n);
    ms_volume_get_particles(a, pa, pa + 3 * n);
    ms_volume_get_particles(b, pb, pb + 3 * n);
    ck_assert(memcmp(pa, pb, sizeof(float) * 6 * (size_t)n) == 0);
    float ha[16 * 16], hb[16 * 16];
    ck_assert_int_eq(ms_volume_extract_height(a, 16, 16, ha), MS_OK);
    ck_assert_int_eq(ms_volume_extract_height(b, 16, 16, hb), MS_OK);
    ck_assert(memcmp(ha, hb, sizeof ha) == 0);
    free(pa);
    free(pb);
    ms_volume_destroy(a);
    ms_volume_destroy(b);
}
END_TEST

/* ms_volume_settle: refused outside [0, MS_VOLUME_SETTLE_MAX_S] s; 0 leaves
 * the fill as it is; otherwise the particles end at rest, off the
 * lattice, the clock and step counts unmoved, the same bytes every time;
 * and the settled pool (a still pool's 0.15 m deep, gas constant 100) set
 * free moves less in its first 3 s than the lattice fill does, which
 * collapses into its packing in that time: its peak kinetic energy under
 * SETTLED_KE_FRACTION of the lattice's (measured: 0.022 J against 0.17 J,
 * 0.13; the bound leaves twice that for other instruction-set paths'
 * packings). */
#define SETTLED_KE_FRACTION 0.3
static ms_volume_desc still_tank_desc(void)
{
    ms_volume_desc d = box_desc(0.5f, 0.5f, 0.3f, 0.05f);
    d.gas_constant = 100.0f;
    d.viscosity = 0.5f;
    return d;
}

static double peak_kinetic_energy(ms_volume *v, float seconds)
{
    double peak = 0.0;
    for (int f = 0; f < (int)lroundf(seconds * 60.0f); ++f) {
        step(v, 1.0f / 60);
        peak = fmax(peak, ms_volume_kinetic_energy(v));
    }
    return peak;
}

START_TEST(settle_leaves_the_fill_at_rest_off_the_lattice)
{
    const ms_volume_desc d = still_tank_desc();
    const float lo[3] = {0, 0, 0}, hi[3] = {0.5f, 0.5f, 0.15f};
    ms_volume *a = make(&d), *b = make(&d), *lattice = make(&d);
    MS_ASSERT_REFUSED(ms_volume_settle(NULL, 1.0f), MS_ERR_INVALID_ARGUMENT, "NULL");
    MS_ASSERT_REFUSED(ms_volume_settle(a, -1.0f), MS_ERR_INVALID_ARGUMENT, "settle");
    MS_ASSERT_REFUSED(ms_volume_settle(a, NAN), MS_ERR_INVALID_ARGUMENT, "settle");
    MS_ASSERT_REFUSED(ms_volume_settle(a, MS_VOLUME_SETTLE_MAX_S * 1.01f), MS_ERR_INVALID_ARGUMENT,
                      "settle");
    ck_assert_int_eq(ms_volume_settle(a, 1.0f), MS_OK); /* no particles: nothing to do */
    for (int k = 0; k < 3; ++k)
        ms_volume_fill_box(k == 0 ? a : k == 1 ? b : lattice, lo, hi);
    const int n = ms_volume_count(a);
    float *pl = malloc(sizeof(float) * 6 * (size_t)n), *pa = malloc(sizeof(float) * 6 * (size_t)n);
    ms_volume_get_particles(lattice, pl, pl + 3 * n);
    ck_assert_int_eq(ms_volume_settle(lattice, 0.0f), MS_OK);
    ms_volume_get_particles(lattice, pa, pa + 3 * n);
    ck_assert(memcmp(pa, pl, sizeof(float) * 6 * (size_t)n) == 0);
    for (int k = 0; k < 2; ++k)
        ck_assert_msg(ms_volume_settle(k ? b : a, 3.0f) == MS_OK, "%s", ms_last_error());
    ms_volume_get_particles(a, pa, pa + 3 * n);
    float *pb = malloc(sizeof(float) * 6 * (size_t)n);
    ms_volume_get_particles(b, pb, pb + 3 * n);
    ck_assert(memcmp(pa, pb, sizeof(float) * 6 * (size_t)n) == 0);
    double moved = 0.0;
    for (int i = 0; i < 3 * n; ++i) {
        ck_assert(pa[3 * n + i] == 0.0f);
        moved = fmax(moved, fabs(pa[i] - pl[i]));
    }
    ck_assert_msg(moved > 0.05 * d.spacing, "settled particles at most %g m off the lattice",
                  moved);
    ms_volume_info info = ms_volume_info_init();
    ms_volume_get_info(a, &info);
    ck_assert(info.time == 0.0 && info.steps == 0 && info.substeps == 0);
    const double settled = peak_kinetic_energy(a, 3.0f),
                 filled = peak_kinetic_energy(lattice, 3.0f);
    printf("settle: peak kinetic energy in the first 3 s %.3g J settled, %.3g J as filled\n",
           settled, filled);
    ck_assert_msg(
        settled < SETTLED_KE_FRACTION * filled,
        "settled pool's peak kinetic energy %.3g J is not under %g of the lattice's %.3g J",
        settled, SETTLED_KE_FRACTION, filled);
    free(pa);
    free(pb);
    free(pl);
    ms_volume_destroy(a);
    ms_volume_destroy(b);
    ms_volume_destroy(lattice);
}
END_TEST

static Suite *volume_suite(void)
{
    Suite *s = suite_create("volume");
    TCase *api = tcase_create("api");
    tcase_set_timeout(api, 60);
    tcase_add_test(api, default_desc_is_valid);
    tcase_add_test(api, bad_descs_are_refused_with_a_sentence);
    tcase_add_test(api, bad_calls_are_refused_with_a_sentence);
    tcase_add_test(api, a_step_needing_too_many_substeps_is_unstable_and_leaves_a_valid_state);
    suite_add_tcase(s, api);

    TCase *model = tcase_create("model");
    tcase_set_timeout(model, 240);
    tcase_add_test(model, a_lattice_block_has_rest_density_inside);
    tcase_add_test(model, walls_give_full_density_at_the_wall);
    tcase_add_test(model, hydrostatic_pressure_matches_rho_g_d_ideal_gas);
    tcase_add_test(model, hydrostatic_pressure_matches_rho_g_d_tait);
    tcase_add_test(model, dam_break_follows_martin_and_moyce);
    tcase_add_test(model, hydrostatic_pressure_matches_rho_g_d_dfsph);
    tcase_add_test(model, a_settling_dfsph_tank_loses_energy_and_keeps_its_divergence);
    tcase_add_test(model, dam_break_follows_martin_and_moyce_dfsph);
    tcase_add_test(model, internal_forces_conserve_momentum);
    tcase_add_test(model, settle_leaves_the_fill_at_rest_off_the_lattice);
    suite_add_tcase(s, model);

    TCase *ex = tcase_create("extraction");
    tcase_set_timeout(ex, 120);
    tcase_add_test(ex, still_liquid_extracts_a_flat_surface_at_its_level);
    tcase_add_test(ex, columns_without_liquid_extract_zero);
    tcase_add_test(ex, adaptive_smoothing_keeps_turbulent_liquid_detailed);
    tcase_add_test(ex, every_instruction_set_path_extracts_the_same_field);
    tcase_add_test(ex, the_band_search_finds_the_reference_surface);
    tcase_add_test(ex, a_stalled_secant_still_ends_within_half_a_tolerance);
    suite_add_tcase(s, ex);

    TCase *hard = tcase_create("hard");
    tcase_set_timeout(hard, 300);
    tcase_add_test(hard, one_and_two_threads_give_the_same_bytes);
    tcase_add_test(hard, every_instruction_set_path_gives_the_same_bytes);
    tcase_add_test(hard, modesplit_isa_forces_a_path_or_is_refused);
    tcase_add_test(hard, every_path_matches_a_double_precision_reference);
    tcase_add_test(hard, every_instruction_set_path_gives_the_same_bytes_with_poly6_and_a_shape);
    tcase_add_test(hard, dfsph_gives_the_same_bytes_for_threads_and_instruction_sets);
    tcase_add_test(hard, all_particles_at_one_point_spread_and_stay_bounded);
    tcase_add_test(hard, a_hundredfold_viscosity_jump_stays_stable);
    tcase_add_test(hard, ten_thousand_steps_at_the_largest_step_stay_bounded);
    tcase_add_test(hard, a_one_second_frame_hitch_is_substepped);
    suite_add_tcase(s, hard);

    TCase *in = tcase_create("interaction");
    tcase_set_timeout(in, 60);
    tcase_add_test(in, drag_pulls_towards_its_velocity_and_never_past_it);
    tcase_add_test(in, push_accelerates_only_inside_its_radius);
    tcase_add_test(in, remove_box_removes_and_keeps_the_order_of_the_rest);
    tcase_add_test(in, waves_nudge_surface_particles_without_adding_unbounded_energy);
    suite_add_tcase(s, in);

    TCase *views = tcase_create("views");
    tcase_set_timeout(views, 60);
    tcase_add_test(views, particle_views_stay_current_across_steps_and_count_changes);
    tcase_add_test(views, particle_views_do_not_change_the_simulation);
    suite_add_tcase(s, views);

    /* the tool's view of the paths: a case of its own, which a build
     * without the tool (make check-aarch64) leaves out */
    /* the committed bytes: a case of its own, which `make golden` runs */
    TCase *golden = tcase_create("golden");
    tcase_set_timeout(golden, 60);
    tcase_add_test(golden, the_dam_break_gives_the_committed_bytes);
    suite_add_tcase(s, golden);

    TCase *tool = tcase_create("tool");
    tcase_set_timeout(tool, 60);
    tcase_add_test(tool, info_build_prints_the_paths_and_the_choice);
    suite_add_tcase(s, tool);
    return s;
}

int main(void)
{
    return ms_test_run(volume_suite());
}
