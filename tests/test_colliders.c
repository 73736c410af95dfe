/* Colliders of the volume (paper 3.3.1, eq. 15; ms_volume_add_collider):
 * a fast obstacle pushes the liquid and none tunnels, fast particles do not
 * cross a thin wall, a moving glass carries its liquid, a tilted glass
 * pours, a turning paddle stirs, a teleported collider is swept. Split out
 * of tests/test_volume.c (same runner pattern).
 */
#include <check.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "modesplit/modesplit.h"
#include "support.h"
#include "support_volume.h"
#include "volume/volume_internal.h"

/* ----------------------------------------------------------- colliders */

static ms_shape *shape(const char *kind, const char *json, float x, float y, float z, float vx,
                       float vy, float vz)
{
    ms_shape *s = NULL;
    ms_status st = ms_shape_create(kind, json, &s);
    ck_assert_msg(st == MS_OK, "shape %s: %s", kind, ms_last_error());
    ck_assert_int_eq(ms_shape_set_pose(s, (float[3]){x, y, z}, (float[3]){vx, vy, vz}), MS_OK);
    return s;
}

/* Particles inside the shape deeper than a hair (m). */
static int inside_count(const ms_volume *v, const ms_shape *s, float depth)
{
    int n = ms_volume_count(v), in = 0;
    float *p = malloc(sizeof(float) * 3 * (size_t)(n + 1));
    ms_volume_get_particles(v, p, NULL);
    for (int i = 0; i < n; ++i)
        in += ms_shape_distance(s, p + 3 * i, NULL) < -depth;
    free(p);
    return in;
}

/* A sphere of radius R = 2.5 cm moving at u = 20 m/s through the middle of
 * a 6 x 8 cm channel of liquid (eq. 15 field or DFSPH images, swept test),
 * from x = 0.1 to 0.4 m, then held still for 15 ms. Frames of 0.5 ms: the
 * ball moves one spacing (R/2.5) a frame, so a particle crossing it would
 * end a frame inside it. Asserted, for every pressure law:
 *  - it meets liquid: hundreds of particles start in the swept cylinder;
 *  - it passes through: when it stops, >= 90 % of those have moved more
 *    than R (out of its way), and the liquid's momentum along +x has
 *    reached at least the added mass of a sphere times u, rho V u / 2
 *    (potential flow in unbounded liquid; the channel's walls only raise
 *    it; measured 6-12x that);
 *  - none tunnels: after every frame no particle is inside the ball or
 *    outside the domain, none is lost, nothing is non-finite;
 *  - energy is bounded: no particle faster than 4u (the weakly compressible
 *    laws meet the ball at Mach 2, c0 = 10 m/s: measured 47 m/s ideal gas,
 *    71 Tait, 20 DFSPH), and once the ball stops the mechanical energy
 *    E = KE + m g z never rises above its value then (+2 %). */
static void obstacle_at_20_m_s(ms_pressure law)
{
    ms_volume_desc d = box_desc(0.6f, 0.06f, 0.16f, 0.01f);
    d.pressure = law;
    ms_volume *v = make(&d);
    ms_volume_fill_box(v, (float[3]){0, 0, 0}, (float[3]){0.6f, 0.06f, 0.08f});
    const int n = ms_volume_count(v);
    const float R = 0.025f, y0 = 0.03f, z0 = 0.04f, x_stop = 0.4f, g = -d.gravity[2];
    float x = 0.1f, u = 20.0f;
    ms_shape *ball = shape("sphere", "{\"radius\": 0.025}", x, y0, z0, u, 0, 0);
    ck_assert_int_eq(ms_volume_add_collider(v, ball), MS_OK);
    ms_volume_info in = ms_volume_info_init();
    ms_volume_get_info(v, &in);
    const double m = in.particle_mass;
    const double rho = m / ((double)d.spacing * d.spacing * d.spacing); /* as filled */
    const double bound = 0.5 * rho * (4.0 / 3.0 * 3.14159265358979 * R * R * R) * 20.0;

    float *p0 = malloc(sizeof(float) * 3 * (size_t)n);
    float *p = malloc(sizeof(float) * 3 * (size_t)n);
    float *w = malloc(sizeof(float) * 3 * (size_t)n);
    ms_volume_get_particles(v, p0, NULL);
    int in_path = 0;
    for (int i = 0; i < n; ++i) {
        float dy = p0[3 * i + 1] - y0, dz = p0[3 * i + 2] - z0;
        in_path += dy * dy + dz * dz < R * R && p0[3 * i] > x + R && p0[3 * i] < x_stop - R;
    }
    ck_assert_msg(in_path >= 300, "only %d particles in the ball's path", in_path);

    const float dt = 1.0f / 2000;
    float vmax = 0.0f;
    double px_max = 0.0, e_stop = -1.0;
    for (int f = 0; f < 60; ++f) {
        step(v, dt);
        x += u * dt;
        if (x >= x_stop - 1e-4f) {
            x = x_stop;
            u = 0.0f;
        }
        ms_shape_set_pose(ball, (float[3]){x, y0, z0}, (float[3]){u, 0, 0});
        ck_assert_msg(inside_count(v, ball, 1e-4f) == 0, "frame %d: particles inside the ball", f);
        assert_sane(v, &d);
        ms_volume_get_particles(v, p, w);
        double px = 0.0, pe = 0.0;
        for (int i = 0; i < n; ++i) {
            px += w[3 * i];
            pe += g * p[3 * i + 2];
            vmax = fmaxf(vmax, sqrtf(w[3 * i] * w[3 * i] + w[3 * i + 1] * w[3 * i + 1] +
                                     w[3 * i + 2] * w[3 * i + 2]));
        }
        px *= m;
        px_max = fmax(px_max, px);
        double e = ms_volume_kinetic_energy(v) + m * pe;
        if (u == 0.0f && e_stop < 0.0) { /* the frame it stopped: who moved */
            e_stop = e;
            int moved = 0, checked = 0;
            for (int i = 0; i < n; ++i) {
                float dy = p0[3 * i + 1] - y0, dz = p0[3 * i + 2] - z0;
                if (!(dy * dy + dz * dz < R * R && p0[3 * i] > 0.1f + R && p0[3 * i] < x_stop - R))
                    continue;
                float ex = p[3 * i] - p0[3 * i], ey = p[3 * i + 1] - p0[3 * i + 1],
                      ez = p[3 * i + 2] - p0[3 * i + 2];
                moved += ex * ex + ey * ey + ez * ez > R * R;
                ++checked;
            }
            ck_assert_msg(moved >= 0.9 * checked,
                          "only %d of the %d particles in its path "
                          "moved out of its way",
                          moved, checked);
        } else if (e_stop > 0.0) {
            ck_assert_msg(e <= 1.02 * e_stop,
                          "frame %d: mechanical energy %g J rose above "
                          "%g J at the stop",
                          f, e, e_stop);
        }
    }
    ck_assert_msg(e_stop > 0.0, "the ball never stopped");
    ck_assert_int_eq(ms_volume_count(v), n);
    ck_assert_msg(px_max >= bound,
                  "liquid momentum peaked at %g kg m/s, under the added "
                  "mass bound %g",
                  px_max, bound);
    ck_assert_msg(vmax < 80.0f, "a particle reached %g m/s", vmax);
    free(p0);
    free(p);
    free(w);
    ms_volume_destroy(v);
    ms_shape_destroy(ball);
}

START_TEST(an_obstacle_at_20_m_s_pushes_the_liquid_and_none_tunnels)
{
    if (skip_under_tsan())
        MS_SKIP(TSAN_WHY);
    obstacle_at_20_m_s(MS_PRESSURE_IDEAL_GAS);
}
END_TEST

START_TEST(tait_an_obstacle_at_20_m_s_pushes_the_liquid_and_none_tunnels)
{
    if (skip_under_tsan())
        MS_SKIP(TSAN_WHY);
    obstacle_at_20_m_s(MS_PRESSURE_TAIT);
}
END_TEST

/* The same under DFSPH (no eq. 15 field: the images and the swept test;
 * the collider's speed enters the CFL bound, step.c). */
START_TEST(dfsph_an_obstacle_at_20_m_s_pushes_the_liquid_and_none_tunnels)
{
    if (skip_under_tsan())
        MS_SKIP(TSAN_WHY);
    obstacle_at_20_m_s(MS_PRESSURE_DFSPH);
}
END_TEST

/* Particles shot at 10 m/s at a 4 mm glass wall stay inside the glass:
 * the swept test stops them at the wall, none crosses it between two
 * sub-steps or ends inside it. */
static void thin_wall(ms_pressure law)
{
    ms_volume_desc d = box_desc(0.4f, 0.4f, 0.3f, 0.01f);
    d.gravity[2] = 0.0f;
    d.pressure = law;
    ms_volume *v = make(&d);
    ms_shape *glass = shape("glass",
                            "{\"radius\": 0.1, \"height\": 0.2, \"wall\": 0.004, "
                            "\"floor\": 0.01}",
                            0.2f, 0.2f, 0.0f, 0, 0, 0);
    ck_assert_int_eq(ms_volume_add_collider(v, glass), MS_OK);
    enum { N = 64 };
    float p[3 * N], u[3 * N];
    for (int i = 0; i < N; ++i) { /* a ring of particles flying outwards */
        float a = 6.2831853f * i / N;
        p[3 * i] = 0.2f + 0.05f * cosf(a);
        p[3 * i + 1] = 0.2f + 0.05f * sinf(a);
        p[3 * i + 2] = 0.03f + 0.002f * (i % 8);
        u[3 * i] = 10.0f * cosf(a);
        u[3 * i + 1] = 10.0f * sinf(a);
        u[3 * i + 2] = 0.0f;
    }
    ck_assert_int_eq(ms_volume_add_particles(v, N, p, u), MS_OK);
    for (int f = 0; f < 20; ++f) {
        step(v, 1.0f / 600);
        ms_volume_get_particles(v, p, NULL);
        for (int i = 0; i < N; ++i) {
            float r = hypotf(p[3 * i] - 0.2f, p[3 * i + 1] - 0.2f);
            ck_assert_msg(r < 0.096f + 1e-4f, "frame %d: particle %d at r %g m, past the wall", f,
                          i, r);
        }
        ck_assert_int_eq(inside_count(v, glass, 1e-4f), 0);
    }
    ms_volume_destroy(v);
    ms_shape_destroy(glass);
}

START_TEST(fast_particles_do_not_cross_a_thin_wall)
{
    thin_wall(MS_PRESSURE_IDEAL_GAS);
}
END_TEST

START_TEST(dfsph_fast_particles_do_not_cross_a_thin_wall)
{
    thin_wall(MS_PRESSURE_DFSPH);
}
END_TEST

/* The paper's glass of water moved by the user: a glass with settled
 * water is moved sideways (velocity ramped up over 0.1 s to 0.3 m/s, then
 * held for 0.6 s): the water goes with it (its mean velocity, averaged over
 * the last 0.5 s, about one sloshing period, within 15 % of the glass's),
 * at least 97 % stays in the glass, none ends in its wall. */
START_TEST(a_moving_glass_carries_its_liquid)
{
    if (skip_under_tsan())
        MS_SKIP(TSAN_WHY);
    ms_volume_desc d = box_desc(0.8f, 0.4f, 0.3f, 0.01f);
    d.viscosity = 20.0f; /* settles quickly */
    ms_volume *v = make(&d);
    float x = 0.2f, u = 0.0f;
    ms_shape *glass = shape("glass",
                            "{\"radius\": 0.1, \"height\": 0.2, \"wall\": 0.006, "
                            "\"floor\": 0.01}",
                            x, 0.2f, 0.0f, 0, 0, 0);
    ck_assert_int_eq(ms_volume_add_collider(v, glass), MS_OK);
    ms_volume_fill_box(v, (float[3]){0.14f, 0.14f, 0.01f}, (float[3]){0.26f, 0.26f, 0.06f});
    const int n = ms_volume_count(v);
    const float dt = 1.0f / 60;
    for (int f = 0; f < 30; ++f)
        step(v, dt);
    ck_assert_int_eq(ms_volume_set_viscosity(v, 2.0f), MS_OK);
    double mean = 0.0;
    int frames = 0;
    float *p = malloc(sizeof(float) * 3 * (size_t)n), *w = malloc(sizeof(float) * 3 * (size_t)n);
    for (int f = 0; f < 42; ++f) {
        u = fminf(0.3f, u + 0.3f * dt / 0.1f);
        ms_shape_set_pose(glass, (float[3]){x, 0.2f, 0.0f}, (float[3]){u, 0, 0});
        step(v, dt);
        x += u * dt;
        /* none in its wall where the step left it: the shape at its end
         * pose (the next frame sets the same pose again). Counted at the
         * start pose, liquid 0.25 mm "inside" showed up as the summation
         * order of the sums or a 1-ulp change of gravity moved
         * the particles: a read-out artifact, 0 at the end pose. */
        ms_shape_set_pose(glass, (float[3]){x, 0.2f, 0.0f}, (float[3]){u, 0, 0});
        ck_assert_int_eq(inside_count(v, glass, 1e-4f), 0);
        if (f >= 12) {
            ms_volume_get_particles(v, NULL, w);
            double m = 0.0;
            for (int i = 0; i < n; ++i)
                m += w[3 * i];
            mean += m / n;
            frames++;
        }
    }
    mean /= frames;
    ms_volume_get_particles(v, p, NULL);
    int in_glass = 0;
    for (int i = 0; i < n; ++i)
        in_glass += hypotf(p[3 * i] - x, p[3 * i + 1] - 0.2f) < 0.094f && p[3 * i + 2] < 0.2f;
    ck_assert_msg(in_glass >= 0.97 * n, "%d of %d particles still in the glass", in_glass, n);
    ck_assert_msg(fabs(mean - u) < 0.15 * u, "mean vx %g m/s, glass %g m/s", mean, u);
    free(p);
    free(w);
    ms_volume_destroy(v);
    ms_shape_destroy(glass);
}
END_TEST

/* Water in the glass's own frame: within its inner radius and below its
 * rim (the glass of radius 0.1, wall 0.006, height 0.2 below). */
static int in_turned_glass(const ms_volume *v, const ms_shape *glass)
{
    int n = ms_volume_count(v), in = 0;
    float *p = malloc(sizeof(float) * 3 * (size_t)(n + 1)), pos[3], q[4];
    ms_volume_get_particles(v, p, NULL);
    ms_shape_get_pose(glass, pos, NULL);
    ms_shape_get_orientation(glass, q, NULL);
    /* R^T r by the conjugate quaternion: r' = r + 2 u x (u x r - w r)... in
     * matrix form, R from q, then its transpose */
    const float w = q[0], x = q[1], y = q[2], z = q[3];
    const float R[9] = {1 - 2 * (y * y + z * z), 2 * (x * y - w * z),     2 * (x * z + w * y),
                        2 * (x * y + w * z),     1 - 2 * (x * x + z * z), 2 * (y * z - w * x),
                        2 * (x * z - w * y),     2 * (y * z + w * x),     1 - 2 * (x * x + y * y)};
    for (int i = 0; i < n; ++i) {
        float r[3] = {p[3 * i] - pos[0], p[3 * i + 1] - pos[1], p[3 * i + 2] - pos[2]}, l[3];
        for (int k = 0; k < 3; ++k)
            l[k] = R[k] * r[0] + R[3 + k] * r[1] + R[6 + k] * r[2];
        in += hypotf(l[0], l[1]) < 0.094f && l[2] > 0.0f && l[2] < 0.2f;
    }
    free(p);
    return in;
}

/* A glass of water held above the floor and tilted by the user
 * (ms_shape_set_orientation with an angular velocity, 2 rad/s about y for
 * 0.9 s, to 103 degrees): while it is still steep the water stays, then it
 * pours out over the rim; no particle ever ends in the wall or outside the
 * domain, nothing is non-finite. */
START_TEST(a_tilted_glass_pours_its_water)
{
    if (skip_under_tsan())
        MS_SKIP(TSAN_WHY);
    ms_volume_desc d = box_desc(0.8f, 0.4f, 0.4f, 0.01f);
    d.viscosity = 20.0f; /* settles quickly */
    ms_volume *v = make(&d);
    ms_shape *glass = shape("glass",
                            "{\"radius\": 0.1, \"height\": 0.2, \"wall\": 0.006, "
                            "\"floor\": 0.01}",
                            0.3f, 0.2f, 0.1f, 0, 0, 0);
    ck_assert_int_eq(ms_volume_add_collider(v, glass), MS_OK);
    ms_volume_fill_box(v, (float[3]){0.24f, 0.14f, 0.11f}, (float[3]){0.36f, 0.26f, 0.16f});
    const int n = ms_volume_count(v);
    const float dt = 1.0f / 60, w = 2.0f; /* s, rad/s */
    for (int f = 0; f < 30; ++f)
        step(v, dt);
    ck_assert_int_eq(in_turned_glass(v, glass), n);
    ck_assert_int_eq(ms_volume_set_viscosity(v, 2.0f), MS_OK);
    float angle = 0.0f;
    int early = -1;
    for (int f = 0; f < 84; ++f) {
        float turn = f < 54 ? w : 0.0f;
        float q[4] = {cosf(0.5f * angle), 0.0f, sinf(0.5f * angle), 0.0f};
        ck_assert_int_eq(ms_shape_set_orientation(glass, q, (float[3]){0, turn, 0}), MS_OK);
        step(v, dt);
        angle += turn * dt;
        q[0] = cosf(0.5f * angle);
        q[2] = sinf(0.5f * angle);
        ck_assert_int_eq(ms_shape_set_orientation(glass, q, NULL), MS_OK);
        ck_assert_msg(inside_count(v, glass, 1e-4f) == 0, "frame %d: particles in the wall", f);
        assert_sane(v, &d);
        if (f == 10) /* 0.33 rad, 19 degrees: the level is still below the rim */
            early = in_turned_glass(v, glass);
    }
    ck_assert_msg(early >= 0.97 * n, "%d of %d in the glass at 19 degrees", early, n);
    int left = in_turned_glass(v, glass);
    ck_assert_msg(left < 0.5 * n, "%d of %d particles still in the glass at %g rad", left, n,
                  angle);
    ck_assert_int_eq(ms_volume_count(v), n);
    ms_volume_destroy(v);
    ms_shape_destroy(glass);
}
END_TEST

/* A paddle turning about the vertical in a tank (a box at 4 rad/s) stirs
 * the liquid: its angular momentum about the axis takes the paddle's sign
 * and no particle ends in the paddle. */
START_TEST(a_turning_paddle_stirs_the_liquid_its_way)
{
    if (skip_under_tsan())
        MS_SKIP(TSAN_WHY);
    ms_volume_desc d = box_desc(0.2f, 0.2f, 0.1f, 0.01f);
    ms_volume *v = make(&d);
    ms_volume_fill_box(v, (float[3]){0, 0, 0}, (float[3]){0.2f, 0.2f, 0.05f});
    ms_shape *paddle = shape("box", "{\"size\": [0.12, 0.02, 0.2]}", 0.1f, 0.1f, 0.05f, 0, 0, 0);
    ck_assert_int_eq(ms_volume_add_collider(v, paddle), MS_OK);
    const float dt = 1.0f / 120, w = 4.0f;
    float angle = 0.0f;
    for (int f = 0; f < 48; ++f) {
        float q[4] = {cosf(0.5f * angle), 0.0f, 0.0f, sinf(0.5f * angle)};
        ck_assert_int_eq(ms_shape_set_orientation(paddle, q, (float[3]){0, 0, w}), MS_OK);
        step(v, dt);
        angle += w * dt;
        q[0] = cosf(0.5f * angle);
        q[3] = sinf(0.5f * angle);
        ck_assert_int_eq(ms_shape_set_orientation(paddle, q, (float[3]){0, 0, w}), MS_OK);
        ck_assert_msg(inside_count(v, paddle, 1e-4f) == 0, "frame %d: particles in the paddle", f);
        assert_sane(v, &d);
    }
    const int n = ms_volume_count(v);
    float *p = malloc(sizeof(float) * 3 * (size_t)n), *u = malloc(sizeof(float) * 3 * (size_t)n);
    ms_volume_get_particles(v, p, u);
    double L = 0.0, speed = 0.0; /* about the axis, per unit mass */
    for (int i = 0; i < n; ++i) {
        double rx = p[3 * i] - 0.1, ry = p[3 * i + 1] - 0.1;
        L += rx * u[3 * i + 1] - ry * u[3 * i];
        speed += sqrt((double)u[3 * i] * u[3 * i] + (double)u[3 * i + 1] * u[3 * i + 1]);
    }
    L /= n;
    speed /= n;
    /* A liquid turning with the paddle as one body would hold w <r^2> =
     * 0.027 m^2/s per kg; after 0.4 s of stirring it holds 0.0048, at a mean
     * speed of 0.15 m/s (measured). Unturned, the paddle would leave both
     * near 0 (the liquid at rest is symmetric about the axis). */
    ck_assert_msg(speed > 0.05, "mean speed %g m/s: the paddle did not move the liquid", speed);
    ck_assert_msg(L > 2e-3, "angular momentum %g m^2/s per kg, mean speed %g m/s", L, speed);
    free(p);
    free(u);
    ms_volume_destroy(v);
    ms_shape_destroy(paddle);
}
END_TEST

/* A collider the caller moves without a velocity (a teleport by 3 cm into
 * the liquid) is swept there during the next step: no particle ends inside
 * it, nothing blows up. */
START_TEST(a_teleported_collider_is_swept_not_crushed)
{
    if (skip_under_tsan())
        MS_SKIP(TSAN_WHY);
    ms_volume_desc d = box_desc(0.3f, 0.1f, 0.15f, 0.01f);
    ms_volume *v = make(&d);
    ms_volume_fill_box(v, (float[3]){0, 0, 0}, (float[3]){0.3f, 0.1f, 0.06f});
    ms_shape *box = shape("box", "{\"size\": [0.05, 0.05, 0.05]}", 0.1f, 0.05f, 0.04f, 0, 0, 0);
    ck_assert_int_eq(ms_volume_add_collider(v, box), MS_OK);
    for (int f = 0; f < 10; ++f)
        step(v, 1.0f / 60);
    ck_assert_int_eq(inside_count(v, box, 1e-4f), 0);
    ms_shape_set_pose(box, (float[3]){0.13f, 0.05f, 0.04f}, (float[3]){0, 0, 0});
    step(v, 1.0f / 60);
    ck_assert_int_eq(inside_count(v, box, 1e-4f), 0);
    assert_sane(v, &d);
    /* The 3 cm jump in 1/60 s is a piston at U = 1.8 m/s; a wall at U
     * throws liquid at up to about 2U. Measured: 4.4 m/s fastest; the
     * fastest particle is a maximum over a splash, and gravity changed by
     * -5 .. +6 ulp gave 3.9 - 5.5 m/s, so asserted below 4U = 7.2 m/s, not 3U (crushing
     * it would fling it at tens of m/s). */
    ms_volume_info in = ms_volume_info_init();
    ms_volume_get_info(v, &in);
    ck_assert_msg(in.max_speed < 7.2f, "fastest %g m/s after a 1.8 m/s teleport", in.max_speed);
    ms_volume_destroy(v);
    ms_shape_destroy(box);
}
END_TEST

/* The next step's first sub-step takes the neighbour pass the
 * extraction ran between steps (ms_volume_count_neighbours) only while it
 * holds. Two volumes take the same steps with the same colliders; only A
 * is extracted between steps (a pass every frame), while between steps the
 * caller, in both: leaves the box alone, teleports it, sets it moving,
 * stops it, turns it, adds a sphere, removes and adds particles, sets it
 * moving and then leaves it behind its velocity (a jump). A stale
 * pass (a collider's old place, a particle set that changed) would change
 * A's sub-steps: the particles must match bit for bit after every step. */
static void move_both(ms_shape *s[2], const float pos[3], const float vel[3])
{
    for (int k = 0; k < 2; ++k)
        ck_assert_int_eq(ms_shape_set_pose(s[k], pos, vel), MS_OK);
}

START_TEST(a_pass_left_by_the_extraction_changes_no_byte)
{
    if (skip_under_tsan())
        MS_SKIP(TSAN_WHY);
    ms_volume_desc d = box_desc(0.2f, 0.1f, 0.12f, 0.01f);
    d.threads = 2; /* the lists are per chunk: the pass must match them too */
    ms_volume *v[2];
    ms_shape *box[2], *ball[2];
    for (int k = 0; k < 2; ++k) {
        v[k] = make(&d);
        ck_assert_int_eq(
            ms_volume_fill_box(v[k], (float[3]){0, 0, 0}, (float[3]){0.2f, 0.1f, 0.05f}), MS_OK);
        box[k] = shape("box", "{\"size\": [0.04, 0.04, 0.04]}", 0.06f, 0.05f, 0.04f, 0, 0, 0);
        ball[k] = shape("sphere", "{\"radius\": 0.02}", 0.15f, 0.05f, 0.05f, 0, 0, 0);
        ck_assert_int_eq(ms_volume_add_collider(v[k], box[k]), MS_OK);
    }
    const int n0 = ms_volume_count(v[0]);
    float *p[2] = {malloc(sizeof(float) * 6 * (size_t)(n0 + 64)),
                   malloc(sizeof(float) * 6 * (size_t)(n0 + 64))};
    float *hf = malloc(sizeof(float) * 16 * 8);
    ck_assert(p[0] && p[1] && hf);
    for (int f = 0; f < 16; ++f) {
        switch (f) {
        case 3: /* a teleport: swept during the next step */
            move_both(box, (float[3]){0.08f, 0.05f, 0.04f}, (float[3]){0, 0, 0});
            break;
        case 5: /* moving: placed where its velocity took it, by the caller */
            move_both(box, (float[3]){0.08f, 0.05f, 0.04f}, (float[3]){0.3f, 0, 0});
            break;
        case 6:
            move_both(box, (float[3]){0.085f, 0.05f, 0.04f}, (float[3]){0.3f, 0, 0});
            break;
        case 7: /* stopped where it was */
            move_both(box, (float[3]){0.085f, 0.05f, 0.04f}, (float[3]){0, 0, 0});
            break;
        case 9: /* turned in place */
            for (int k = 0; k < 2; ++k)
                ck_assert_int_eq(
                    ms_shape_set_orientation(box[k], (float[4]){0.99f, 0, 0, 0.14f}, NULL), MS_OK);
            break;
        case 11:
            for (int k = 0; k < 2; ++k)
                ck_assert_int_eq(ms_volume_add_collider(v[k], ball[k]), MS_OK);
            break;
        case 13:
            for (int k = 0; k < 2; ++k) {
                int removed = 0;
                ck_assert_int_eq(ms_volume_remove_box(v[k], (float[3]){0.17f, 0, 0},
                                                      (float[3]){0.2f, 0.1f, 0.12f}, &removed),
                                 MS_OK);
                ck_assert_int_gt(removed, 0);
                ck_assert_int_eq(ms_volume_add_particles(v[k], 1, (float[3]){0.1f, 0.05f, 0.1f},
                                                         (float[3]){0, 0, -1}),
                                 MS_OK);
            }
            break;
        case 14: /* moving, and next frame left where it is: a jump back */
            move_both(box, (float[3]){0.085f, 0.05f, 0.04f}, (float[3]){0.3f, 0, 0});
            break;
        default:
            break;
        }
        for (int k = 0; k < 2; ++k)
            step(v[k], 1.0f / 60);
        ck_assert_int_eq(ms_volume_extract_height(v[0], 16, 8, hf), MS_OK);
        const int n = ms_volume_count(v[0]);
        ck_assert_int_eq(ms_volume_count(v[1]), n);
        for (int k = 0; k < 2; ++k)
            ck_assert_int_eq(ms_volume_get_particles(v[k], p[k], p[k] + 3 * (size_t)n), MS_OK);
        ck_assert_msg(!memcmp(p[0], p[1], sizeof(float) * 6 * (size_t)n),
                      "frame %d: the extracted volume's particles differ", f);
    }
    free(p[0]);
    free(p[1]);
    free(hf);
    for (int k = 0; k < 2; ++k) {
        ms_volume_destroy(v[k]);
        ms_shape_destroy(box[k]);
        ms_shape_destroy(ball[k]);
    }
}
END_TEST

/* Between steps (the extraction, the coupling to the waves) the density
 * pass sees each collider where the step left it, not at its pose (the
 * step's start): the densities read there are those read after the
 * caller has moved the colliders on by their velocities, to float
 * round-off (measured 1e-6 of rho0). Viewed at their poses, a wall moving
 * at 0.4 m/s through the liquid (0.67 spacings a frame) and a paddle
 * turning at 3 rad/s read densities up to 0.78 rho0 off. */
START_TEST(the_pass_between_steps_sees_colliders_where_the_step_left_them)
{
    if (skip_under_tsan())
        MS_SKIP(TSAN_WHY);
    ms_volume_desc d = box_desc(0.4f, 0.2f, 0.12f, 0.01f);
    ms_volume *v = make(&d);
    ck_assert_int_eq(ms_volume_fill_box(v, (float[3]){0, 0, 0}, (float[3]){0.4f, 0.2f, 0.06f}),
                     MS_OK);
    const float dt = 1.0f / 60, u = 0.4f, w = 3.0f;
    float x = 0.1f, angle = 0.0f;
    ms_shape *wall = shape("box", "{\"size\": [0.03, 0.12, 0.2]}", x, 0.1f, 0.06f, u, 0, 0);
    ms_shape *paddle = shape("box", "{\"size\": [0.08, 0.015, 0.2]}", 0.3f, 0.1f, 0.06f, 0, 0, 0);
    ck_assert_int_eq(ms_volume_add_collider(v, wall), MS_OK);
    ck_assert_int_eq(ms_volume_add_collider(v, paddle), MS_OK);
    const int n = ms_volume_count(v);
    float *at_end = malloc(sizeof(float) * (size_t)n), *at_pose = malloc(sizeof(float) * (size_t)n);
    ck_assert(at_end && at_pose);
    double worst = 0.0, behind = 0.0;
    for (int f = 0; f < 12; ++f) {
        float q[4] = {cosf(0.5f * angle), 0.0f, 0.0f, sinf(0.5f * angle)};
        ck_assert_int_eq(ms_shape_set_pose(wall, (float[3]){x, 0.1f, 0.06f}, (float[3]){u, 0, 0}),
                         MS_OK);
        ck_assert_int_eq(ms_shape_set_orientation(paddle, q, (float[3]){0, 0, w}), MS_OK);
        step(v, dt);
        ck_assert_int_eq(ms_volume_count(v), n);
        ms_volume_grid_build(v);
        ck_assert_int_eq(ms_volume_count_neighbours(v), MS_OK);
        memcpy(at_end, v->rho, sizeof(float) * (size_t)n);
        ms_volume_boundary(v, 0.0); /* at the poses: the step's start */
        ck_assert_int_eq(ms_volume_density(v), MS_OK);
        memcpy(at_pose, v->rho, sizeof(float) * (size_t)n);
        /* the caller moves them on; the same particles, the same order */
        x += u * dt;
        angle += w * dt;
        q[0] = cosf(0.5f * angle);
        q[3] = sinf(0.5f * angle);
        ck_assert_int_eq(ms_shape_set_pose(wall, (float[3]){x, 0.1f, 0.06f}, (float[3]){u, 0, 0}),
                         MS_OK);
        ck_assert_int_eq(ms_shape_set_orientation(paddle, q, (float[3]){0, 0, w}), MS_OK);
        ms_volume_boundary(v, 0.0);
        ck_assert_int_eq(ms_volume_density(v), MS_OK);
        for (int i = 0; i < n; ++i) {
            worst = fmax(worst, fabs((double)at_end[i] - v->rho[i]) / d.rest_density);
            behind = fmax(behind, fabs((double)at_pose[i] - v->rho[i]) / d.rest_density);
        }
    }
    ck_assert_msg(worst < 1e-3,
                  "the pass between steps differs from the moved colliders' by %g "
                  "of rho0",
                  worst);
    ck_assert_msg(behind > 0.05, "seen at their poses the densities differ by only %g of rho0",
                  behind);
    free(at_end);
    free(at_pose);
    ms_volume_destroy(v);
    ms_shape_destroy(wall);
    ms_shape_destroy(paddle);
}
END_TEST

static Suite *colliders_suite(void)
{
    Suite *s = suite_create("colliders");
    TCase *col = tcase_create("colliders");
    tcase_set_timeout(col, 240);
    tcase_add_test(col, an_obstacle_at_20_m_s_pushes_the_liquid_and_none_tunnels);
    tcase_add_test(col, fast_particles_do_not_cross_a_thin_wall);
    tcase_add_test(col, a_moving_glass_carries_its_liquid);
    tcase_add_test(col, a_tilted_glass_pours_its_water);
    tcase_add_test(col, a_turning_paddle_stirs_the_liquid_its_way);
    tcase_add_test(col, a_teleported_collider_is_swept_not_crushed);
    tcase_add_test(col, dfsph_an_obstacle_at_20_m_s_pushes_the_liquid_and_none_tunnels);
    tcase_add_test(col, tait_an_obstacle_at_20_m_s_pushes_the_liquid_and_none_tunnels);
    tcase_add_test(col, dfsph_fast_particles_do_not_cross_a_thin_wall);
    tcase_add_test(col, a_pass_left_by_the_extraction_changes_no_byte);
    tcase_add_test(col, the_pass_between_steps_sees_colliders_where_the_step_left_them);
    suite_add_tcase(s, col);
    return s;
}

int main(void)
{
    return ms_test_run(colliders_suite());
}
