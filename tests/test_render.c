/* The renderer (paper section 3.6): the caustics light map conserves light
 * and focuses it where a lens-shaped bump converges it (Snell's law); with
 * OSMesa, flat water reflects the Fresnel share of the sky (Schlick: about
 * 2 % at normal incidence, 14 % at 70 degrees), a bump changes the image
 * where it is and nowhere else, milk hides the pool floor that water
 * shows, caustics brighten the floor under the lens, the same field gives
 * the same bytes for any llvmpipe thread count, PNGs round-trip, and every
 * bad input is refused with a sentence naming it. Images are small
 * (128 x 128) to keep the suite fast. */
#include <check.h>
#include <errno.h>
#include <math.h>
#include <png.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <pthread.h>
#include <sys/wait.h>
#include <unistd.h>

#include "core/core_internal.h"
#include "modesplit/modesplit.h"
#include "modesplit/plugin.h"
#include "render/render_internal.h"
#include "scene/scene_internal.h"
#include "support.h"
#include "support_render.h"

/* A case that draws needs a GL context backend: in a build without OSMesa
 * and EGL it is recorded as skipped (MS_SKIP), not compiled out. */
#define REQUIRE_GL()                                                   \
    do {                                                               \
        if (!MS_HAVE_GL)                                               \
            MS_SKIP("built without OSMesa and EGL: nothing can draw"); \
    } while (0)

#define N 64  /* field cells per side in the image tests */
#define W 128 /* image side */

/* ---- helpers ------------------------------------------------------------ */

/* Looking straight down on the 1 m pool from 1.75 m above the water: the
 * water fills the image, +y up, +x right. */
static ms_renderer_desc top_down(const char *shader)
{
    ms_renderer_desc d = ms_renderer_desc_default();
    d.width = d.height = W;
    d.shader = shader;
    d.caustics_resolution = 128;
    const float eye[3] = {0.5f, 0.5f, 2.0f}, target[3] = {0.5f, 0.5f, 0.25f}, up[3] = {0, 1, 0};
    memcpy(d.eye, eye, sizeof eye);
    memcpy(d.target, target, sizeof target);
    memcpy(d.up, up, sizeof up);
    d.fov = 30;
    return d;
}

static ms_renderer *create_ok(const ms_renderer_desc *d)
{
    ms_renderer *r = NULL;
    ms_status st = ms_renderer_create_desc(d, &r);
    ck_assert_msg(st == MS_OK, "%s: %s", ms_status_name(st), ms_last_error());
    return r;
}

static void draw_ok(ms_renderer *r, const float *h, int n)
{
    ms_grid g = grid(n);
    ms_status st = ms_renderer_draw_field(r, h, &g, 0.0);
    ck_assert_msg(st == MS_OK, "%s: %s", ms_status_name(st), ms_last_error());
}

/* A copy of the image of one draw of h by a renderer made from d. */
static unsigned char *render(const ms_renderer_desc *d, const float *h, int n)
{
    ms_renderer *r = create_ok(d);
    draw_ok(r, h, n);
    int w, hh;
    const unsigned char *px = ms_renderer_pixels(r, &w, &hh);
    ck_assert_int_eq(w, d->width);
    ck_assert_int_eq(hh, d->height);
    size_t bytes = (size_t)w * (size_t)hh * 4;
    unsigned char *copy = malloc(bytes);
    ck_assert_ptr_nonnull(copy);
    memcpy(copy, px, bytes);
    ms_renderer_destroy(r);
    return copy;
}

static double srgb_to_linear(unsigned char c)
{
    double v = c / 255.0;
    return v <= 0.04045 ? v / 12.92 : pow((v + 0.055) / 1.055, 2.4);
}

/* Mean over the channels and the pixels of a box (top-first rows) of a
 * function of two images' pixels. */
static double box_mean_abs_diff(const unsigned char *a, const unsigned char *b, int x0, int y0,
                                int x1, int y1)
{
    double s = 0;
    for (int y = y0; y < y1; ++y)
        for (int x = x0; x < x1; ++x)
            for (int c = 0; c < 3; ++c) {
                size_t i = ((size_t)y * W + (size_t)x) * 4 + (size_t)c;
                s += fabs((double)a[i] - b[i]);
            }
    return s / (3.0 * (x1 - x0) * (y1 - y0));
}

static int box_max_abs_diff(const unsigned char *a, const unsigned char *b, int x0, int y0, int x1,
                            int y1)
{
    int m = 0;
    for (int y = y0; y < y1; ++y)
        for (int x = x0; x < x1; ++x)
            for (int c = 0; c < 3; ++c) {
                size_t i = ((size_t)y * W + (size_t)x) * 4 + (size_t)c;
                m = MS_MAX(m, abs((int)a[i] - (int)b[i]));
            }
    return m;
}

/* Writes a size x size PNG of one colour. */
static void write_face(const char *path, int size, int height, const unsigned char rgb[3])
{
    png_image img;
    memset(&img, 0, sizeof img);
    img.version = PNG_IMAGE_VERSION;
    img.width = (png_uint_32)size;
    img.height = (png_uint_32)height;
    img.format = PNG_FORMAT_RGB;
    unsigned char *px = malloc((size_t)size * (size_t)height * 3);
    ck_assert_ptr_nonnull(px);
    for (int i = 0; i < size * height; ++i)
        memcpy(px + 3 * i, rgb, 3);
    ck_assert(png_image_write_to_file(&img, path, 0, px, 0, NULL));
    free(px);
}

/* A directory of six one-colour faces; colours[f] for face f. */
static void write_cubemap_dir(const char *dir, const unsigned char colours[6][3])
{
    static const char *const names[6] = {"px", "nx", "py", "ny", "pz", "nz"};
    ck_assert(mkdir(dir, 0700) == 0 || errno == EEXIST);
    for (int f = 0; f < 6; ++f) {
        char path[512];
        snprintf(path, sizeof path, "%s/%s.png", dir, names[f]);
        write_face(path, 8, 8, colours[f]);
    }
}

static char tmpdir[256];

static void make_tmpdir(void)
{
    snprintf(tmpdir, sizeof tmpdir, "/tmp/ms_test_render_XXXXXX");
    ck_assert_ptr_nonnull(mkdtemp(tmpdir));
}

static void remove_tmpdir(void)
{
    char cmd[512];
    snprintf(cmd, sizeof cmd, "rm -rf '%s'", tmpdir);
    ck_assert_int_eq(system(cmd), 0);
}

/* ---- descs, scenes, refusals (no GL needed) ----------------------------- */

START_TEST(a_scene_gives_the_desc_of_its_render_section)
{
    const char *text = "{\"domain\": {\"min\": [-1, 0, 0.5], \"max\": [1, 1, 1.5]},"
                       " \"surface\": {\"cells\": [64, 32], \"level\": 0.4},"
                       " \"render\": {\"width\": 64, \"height\": 48, \"shader\": \"milk\","
                       "   \"caustics\": {\"resolution\": 32, \"intensity\": 2,"
                       "                  \"light\": [0, 0, -2]},"
                       "   \"camera\": {\"eye\": [0, -3, 2], \"target\": [0, 0.5, 0.5],"
                       "                \"fov\": 50}}}";
    ms_scene *sc = NULL;
    ck_assert_int_eq(ms_scene_parse(text, strlen(text), &sc), MS_OK);
    ms_renderer_desc d = ms_renderer_desc_default();
    ck_assert_int_eq(ms_renderer_desc_from_scene(sc, &d), MS_OK);
    ck_assert_int_eq(d.width, 64);
    ck_assert_int_eq(d.height, 48);
    ck_assert_str_eq(d.shader, "milk");
    ck_assert_str_eq(d.cubemap, "builtin");
    ck_assert_int_eq(d.caustics, 1);
    ck_assert_int_eq(d.caustics_resolution, 32);
    ck_assert_float_eq_tol(d.caustics_intensity, 2, 1e-6f);
    ck_assert_float_eq_tol(d.light_dir[2], -1, 1e-6f); /* normalised by the scene */
    ck_assert_float_eq_tol(d.eye[1], -3, 1e-6f);
    ck_assert_float_eq_tol(d.fov, 50, 1e-6f);
    /* the pool is the domain; heights are above its floor */
    ck_assert_float_eq_tol(d.pool_min[0], -1, 1e-6f);
    ck_assert_float_eq_tol(d.pool_max[1], 1, 1e-6f);
    ck_assert_float_eq_tol(d.pool_min[2], 0.5f, 1e-6f);
    ck_assert_float_eq_tol(d.water_level, 0.9f, 1e-6f);
    ck_assert_float_gt(d.pool_max[2], d.water_level);
    ck_assert_float_le(d.pool_max[2], 1.5f);
    ck_assert_str_eq(d.backend, "auto");
    ms_scene_destroy(sc);

    /* render.backend picks the GL context; an unknown one names the key */
    const char *egl = "{\"surface\": {}, \"render\": {\"backend\": \"egl\"}}";
    ck_assert_int_eq(ms_scene_parse(egl, strlen(egl), &sc), MS_OK);
    ck_assert_int_eq(ms_renderer_desc_from_scene(sc, &d), MS_OK);
    ck_assert_str_eq(d.backend, "egl");
    ms_scene_destroy(sc);
    const char *gpu = "{\"surface\": {}, \"render\": {\"backend\": \"vulkan\"}}";
    sc = NULL;
    ck_assert_int_ne(ms_scene_parse(gpu, strlen(gpu), &sc), MS_OK);
    ck_assert_ptr_null(sc);
    ck_assert_msg(strstr(ms_last_error(), "backend") && strstr(ms_last_error(), "osmesa"), "%s",
                  ms_last_error());

    /* no render section: the desc still has the pool, but create refuses */
    const char *bare = "{\"surface\": {}}";
    ck_assert_int_eq(ms_scene_parse(bare, strlen(bare), &sc), MS_OK);
    ck_assert_int_eq(ms_renderer_desc_from_scene(sc, &d), MS_OK);
    ck_assert_int_eq(d.caustics, 0);
    ck_assert_float_eq_tol(d.water_level, 0.25f, 1e-6f);
    ms_renderer *r = (ms_renderer *)sc; /* must be set to NULL */
    MS_ASSERT_REFUSED(ms_renderer_create_from_scene(sc, &r), MS_ERR_INVALID_ARGUMENT,
                      "no \"render\" section");
    ck_assert_ptr_null(r);
    ms_scene_destroy(sc);
    MS_ASSERT_REFUSED(ms_renderer_desc_from_scene(NULL, &d), MS_ERR_INVALID_ARGUMENT, "scene");
}
END_TEST

START_TEST(bad_descs_are_refused_with_the_value)
{
    ms_renderer *r = NULL;
    ms_renderer_desc d = top_down("water");
#define REFUSE(field_set, status, word)                                       \
    do {                                                                      \
        d = top_down("water");                                                \
        field_set;                                                            \
        MS_ASSERT_REFUSED(ms_renderer_create_desc(&d, &r), (status), (word)); \
        ck_assert_ptr_null(r);                                                \
    } while (0)
    REFUSE(d.width = 0, MS_ERR_INVALID_ARGUMENT, "width 0 is outside [16, 8192]");
    REFUSE(d.height = 100000, MS_ERR_INVALID_ARGUMENT, "height 100000");
    REFUSE((d.width = 8192, d.height = 8192), MS_ERR_INVALID_ARGUMENT, "over 33554432 pixels");
    REFUSE(d.shader = NULL, MS_ERR_INVALID_ARGUMENT, "shader is NULL");
    REFUSE(d.shader = "", MS_ERR_INVALID_ARGUMENT, "shader \"\" is empty");
    REFUSE(d.cubemap = "", MS_ERR_INVALID_ARGUMENT, "cubemap \"\" is empty");
    REFUSE(d.caustics = 2, MS_ERR_INVALID_ARGUMENT, "caustics 2");
    REFUSE(d.caustics_resolution = 8, MS_ERR_INVALID_ARGUMENT, "caustics_resolution 8");
    REFUSE(d.caustics_intensity = -1, MS_ERR_INVALID_ARGUMENT, "caustics_intensity -1");
    REFUSE(d.light_dir[0] = d.light_dir[1] = d.light_dir[2] = 0, MS_ERR_INVALID_ARGUMENT,
           "light_dir [0, 0, 0] is the zero vector");
    REFUSE(d.light_dir[1] = NAN, MS_ERR_INVALID_ARGUMENT, "light_dir[1] nan");
    REFUSE(d.light_color[2] = -0.5f, MS_ERR_INVALID_ARGUMENT, "light_color[2] -0.5");
    REFUSE(d.ior = 0.5f, MS_ERR_INVALID_ARGUMENT, "ior 0.5");
    REFUSE(d.fov = 180, MS_ERR_INVALID_ARGUMENT, "fov 180 degrees");
    REFUSE(memcpy(d.target, d.eye, sizeof d.eye), MS_ERR_INVALID_ARGUMENT, "equals eye");
    REFUSE((d.up[0] = 0, d.up[1] = 0, d.up[2] = 1), MS_ERR_INVALID_ARGUMENT,
           "along the view direction");
    REFUSE(d.pool_max[0] = -1, MS_ERR_INVALID_ARGUMENT, "pool_max[0] -1 m must be above");
    REFUSE(d.water_level = 0.5f, MS_ERR_INVALID_ARGUMENT, "water_level 0.5 m is outside [0, 0.3]");
    REFUSE(d.tile_size = -1, MS_ERR_INVALID_ARGUMENT, "tile_size -1 m");
    REFUSE(d.floor_color[0] = 2, MS_ERR_INVALID_ARGUMENT, "floor_color[0] 2");
    REFUSE(d.mesh_step = 65, MS_ERR_INVALID_ARGUMENT, "mesh_step 65 is outside [0, 64]");
#undef REFUSE
    d = top_down("water");
    MS_ASSERT_REFUSED(ms_renderer_create_desc(NULL, &r), MS_ERR_INVALID_ARGUMENT, "desc is NULL");
    MS_ASSERT_REFUSED(ms_renderer_create_desc(&d, NULL), MS_ERR_INVALID_ARGUMENT, "out is NULL");
    /* calls on no renderer */
    ck_assert_ptr_null(ms_renderer_pixels(NULL, NULL, NULL));
    ck_assert_ptr_null(ms_renderer_caustics(NULL, NULL));
    ms_renderer_destroy(NULL);
    float h = 0;
    ms_grid g = grid(2);
    MS_ASSERT_REFUSED(ms_renderer_draw_field(NULL, &h, &g, 0), MS_ERR_INVALID_ARGUMENT,
                      "renderer is NULL");
    MS_ASSERT_REFUSED(ms_renderer_write_png(NULL, "x.png"), MS_ERR_INVALID_ARGUMENT,
                      "renderer is NULL");
}
END_TEST

#if !MS_HAVE_GL
START_TEST(without_osmesa_create_says_so)
{
    ms_renderer *r = NULL;
    ms_renderer_desc d = top_down("water");
    MS_ASSERT_REFUSED(ms_renderer_create_desc(&d, &r), MS_ERR_UNSUPPORTED, "no OpenGL");
    ck_assert_ptr_null(r);
}
END_TEST
#endif

/* ---- with GL (OSMesa or EGL; skipped in a build with neither) -------------------------------------------------------- */

/* Fresnel reflectance measured at the image's centre: the same flat water
 * under a black and under a white sky (uniform cubemaps); the difference
 * of the linear colours is the reflected share of the sky. */
static double measured_reflectance(const ms_renderer_desc *base)
{
    static const unsigned char black[6][3] = {{0}},
                               white[6][3] = {{255, 255, 255}, {255, 255, 255}, {255, 255, 255},
                                              {255, 255, 255}, {255, 255, 255}, {255, 255, 255}};
    char dark[300], bright[300];
    snprintf(dark, sizeof dark, "%s/black", tmpdir);
    snprintf(bright, sizeof bright, "%s/white", tmpdir);
    write_cubemap_dir(dark, black);
    write_cubemap_dir(bright, white);
    float *h = field(N, 0.25f);
    ms_renderer_desc d = *base;
    d.cubemap = dark;
    unsigned char *a = render(&d, h, N);
    d.cubemap = bright;
    unsigned char *b = render(&d, h, N);
    double s = 0;
    int k = 0;
    for (int y = W / 2 - 2; y < W / 2 + 2; ++y)
        for (int x = W / 2 - 2; x < W / 2 + 2; ++x)
            for (int c = 0; c < 3; ++c, ++k) {
                size_t i = ((size_t)y * W + (size_t)x) * 4 + (size_t)c;
                ck_assert_int_lt(b[i], 250); /* not clipped */
                s += srgb_to_linear(b[i]) - srgb_to_linear(a[i]);
            }
    free(a);
    free(b);
    free(h);
    return s / k;
}

START_TEST(flat_water_reflects_the_fresnel_share_of_the_sky)
{
    REQUIRE_GL();
    make_tmpdir();
    ms_renderer_desc d = top_down("water");
    /* a dark floor, no caustics, the sun low at the side: no highlight */
    d.floor_color[0] = d.floor_color[1] = d.floor_color[2] = 0.05f;
    d.caustics = 0;
    const float low_sun[3] = {1, 0, -0.2f};
    memcpy(d.light_dir, low_sun, sizeof low_sun);
    /* Schlick with n = 1.333: R0 = ((n - 1)/(n + 1))^2 = 0.0204 */
    const double n = 1.333, r0 = ((n - 1) / (n + 1)) * ((n - 1) / (n + 1));
    double normal = measured_reflectance(&d);
    ck_assert_msg(fabs(normal - r0) < 0.005, "reflectance at normal incidence %g, Schlick %g",
                  normal, r0);
    /* 70 degrees from the normal: R = R0 + (1 - R0)(1 - cos 70)^5 = 0.141 */
    const double inc = 70 * 3.14159265358979 / 180;
    const float dist = 2.5f;
    d.eye[0] = 0.5f;
    d.eye[1] = 0.5f - dist * (float)sin(inc);
    d.eye[2] = 0.25f + dist * (float)cos(inc);
    d.up[0] = 0, d.up[1] = 0, d.up[2] = 1;
    double oblique = measured_reflectance(&d);
    double schlick = r0 + (1 - r0) * pow(1 - cos(inc), 5);
    ck_assert_msg(fabs(oblique - schlick) < 0.015, "reflectance at 70 degrees %g, Schlick %g",
                  oblique, schlick);
    remove_tmpdir();
}
END_TEST

START_TEST(a_bump_changes_the_image_where_it_is_only)
{
    REQUIRE_GL();
    ms_renderer_desc d = top_down("water");
    float *flat = field(N, 0.25f), *bumped = field(N, 0.25f);
    add_bump(bumped, N, 0.3f, 0.7f, 0.01f, 0.03f);
    unsigned char *a = render(&d, flat, N), *b = render(&d, bumped, N);
    /* world (x, y) on the water to pixels: 1.75 m away, 30 degrees of view */
    const double half = 1.75 * tan(15 * 3.14159265358979 / 180); /* m */
    int bx = (int)((0.3 - 0.5) / half * (W / 2) + W / 2);
    int by = (int)(-(0.7 - 0.5) / half * (W / 2) + W / 2);
    double near = box_mean_abs_diff(a, b, bx - 6, by - 6, bx + 6, by + 6);
    int most = box_max_abs_diff(a, b, bx - 6, by - 6, bx + 6, by + 6);
    ck_assert_msg(near > 2 && most > 20,
                  "the bump changed its pixels by %g levels on average, "
                  "%d at most",
                  near, most);
    /* the opposite quadrant, well away from the bump and its light */
    int far = box_max_abs_diff(a, b, W / 2 + 16, W / 2 + 16, W - 8, W - 8);
    ck_assert_msg(far <= 1, "pixels far from the bump changed by %d levels", far);
    free(a);
    free(b);
    free(flat);
    free(bumped);
}
END_TEST

START_TEST(milk_hides_the_floor_that_water_shows)
{
    REQUIRE_GL();
    float *h = field(N, 0.25f);
    add_bump(h, N, 0.5f, 0.5f, 0.004f, 0.05f);
    const int lo = W / 4, hi = 3 * W / 4; /* the middle of the water */
    const char *const shaders[2] = {"water", "milk"};
    double diff[2];
    for (int s = 0; s < 2; ++s) {
        ms_renderer_desc d = top_down(shaders[s]);
        d.floor_color[0] = 0.9f, d.floor_color[1] = 0.2f, d.floor_color[2] = 0.1f;
        unsigned char *red = render(&d, h, N);
        d.floor_color[0] = 0.1f, d.floor_color[1] = 0.2f, d.floor_color[2] = 0.9f;
        unsigned char *blue = render(&d, h, N);
        diff[s] = box_mean_abs_diff(red, blue, lo, lo, hi, hi);
        free(red);
        free(blue);
    }
    ck_assert_msg(diff[0] > 10, "water shows the floor's colour by %g levels", diff[0]);
    ck_assert_msg(diff[1] == 0, "milk shows the floor's colour by %g levels", diff[1]);

    /* the passes: milk asks for reflection only, so neither the refraction
     * half of the cubemap nor the caustics are made */
    ms_renderer_desc d = top_down("milk");
    ms_renderer *r = create_ok(&d);
    draw_ok(r, h, N);
    ms_render_stats st = ms_render_stats_init();
    ms_renderer_get_stats(r, &st);
    ck_assert_uint_eq(st.passes, MS_SHADER_NEEDS_REFLECTION);
    ck_assert_double_eq(st.caustics_ms, 0);
    ck_assert_int_eq(st.frames, 1);
    int n = -1;
    ck_assert_ptr_null(ms_renderer_caustics(r, &n));
    ck_assert_int_eq(n, 0);
    ms_renderer_destroy(r);
    d = top_down("water");
    r = create_ok(&d);
    draw_ok(r, h, N);
    ms_renderer_get_stats(r, &st);
    ck_assert_uint_eq(st.passes, MS_SHADER_NEEDS_REFLECTION | MS_SHADER_NEEDS_REFRACTION |
                                     MS_SHADER_NEEDS_CAUSTICS);
    ck_assert_ptr_nonnull(ms_renderer_caustics(r, &n));
    ck_assert_int_eq(n, 128);
    ms_renderer_destroy(r);
    d.caustics = 0; /* the scene asks for none: not traced */
    r = create_ok(&d);
    draw_ok(r, h, N);
    ms_renderer_get_stats(r, &st);
    ck_assert_uint_eq(st.passes, MS_SHADER_NEEDS_REFLECTION | MS_SHADER_NEEDS_REFRACTION);
    ck_assert_ptr_null(ms_renderer_caustics(r, &n));
    ms_renderer_destroy(r);
    free(h);
}
END_TEST

START_TEST(caustics_brighten_the_floor_under_a_lens)
{
    REQUIRE_GL();
    ms_renderer_desc d = top_down("water");
    const float down[3] = {0, 0, -1};
    memcpy(d.light_dir, down, sizeof down);
    /* focal length n R / (n - 1) = the depth: R = 0.25 (n - 1) / n */
    const float sigma = 0.04f, R = 0.25f * 0.333f / 1.333f, a = sigma * sigma / R;
    float *h = field(N, 0.25f - a);
    add_bump(h, N, 0.5f, 0.5f, a, sigma);
    unsigned char *on = render(&d, h, N);
    d.caustics = 0;
    unsigned char *off = render(&d, h, N);
    double lum_on = 0, lum_off = 0;
    for (int y = W / 2 - 3; y < W / 2 + 3; ++y)
        for (int x = W / 2 - 3; x < W / 2 + 3; ++x)
            for (int c = 0; c < 3; ++c) {
                size_t i = ((size_t)y * W + (size_t)x) * 4 + (size_t)c;
                lum_on += srgb_to_linear(on[i]);
                lum_off += srgb_to_linear(off[i]);
            }
    ck_assert_msg(lum_on > 1.3 * lum_off, "under the lens: %g with caustics, %g without", lum_on,
                  lum_off);
    /* away from the lens the light map is 1, as without caustics */
    int far = box_max_abs_diff(on, off, 8, 8, 32, 32);
    ck_assert_msg(far <= 1, "far from the lens the caustics changed pixels by %d", far);
    free(on);
    free(off);
    free(h);
}
END_TEST

/* FNV-1a of the image. */
static uint64_t image_hash(const unsigned char *px, size_t n)
{
    uint64_t hsh = 1469598103934665603ull;
    for (size_t i = 0; i < n; ++i)
        hsh = (hsh ^ px[i]) * 1099511628211ull;
    return hsh;
}

static uint64_t hash_in_child(const char *threads)
{
    int fd[2];
    ck_assert_int_eq(pipe(fd), 0);
    pid_t pid = fork();
    ck_assert_int_ge(pid, 0);
    if (pid == 0) {
        close(fd[0]);
        setenv("LP_NUM_THREADS", threads, 1);
        ms_renderer_desc d = top_down("water");
        d.eye[1] = -0.5f; /* oblique: every part of the scene in view */
        d.up[0] = 0, d.up[1] = 0, d.up[2] = 1;
        float *h = field(N, 0.25f);
        add_bump(h, N, 0.4f, 0.6f, 0.01f, 0.05f);
        ms_renderer *r = NULL;
        ms_grid g = grid(N);
        uint64_t v = 0;
        if (ms_renderer_create_desc(&d, &r) == MS_OK &&
            ms_renderer_draw_field(r, h, &g, 1.5) == MS_OK)
            v = image_hash(ms_renderer_pixels(r, NULL, NULL), (size_t)W * W * 4);
        ms_renderer_destroy(r);
        free(h);
        ssize_t wr = write(fd[1], &v, sizeof v);
        _exit(wr == (ssize_t)sizeof v ? 0 : 1);
    }
    close(fd[1]);
    uint64_t v = 0;
    ck_assert_int_eq(read(fd[0], &v, sizeof v), (ssize_t)sizeof v);
    close(fd[0]);
    int status = 0;
    waitpid(pid, &status, 0);
    ck_assert(WIFEXITED(status) && WEXITSTATUS(status) == 0);
    return v;
}

START_TEST(the_same_field_gives_the_same_bytes_for_any_thread_count)
{
    REQUIRE_GL();
    uint64_t one = hash_in_child("1"), two = hash_in_child("2"), three = hash_in_child("3");
    ck_assert_uint_ne(one, 0);
    ck_assert_uint_eq(one, two);
    ck_assert_uint_eq(one, three);
    /* and one renderer drawing the same field again */
    ms_renderer_desc d = top_down("water");
    float *h = field(N, 0.25f);
    add_bump(h, N, 0.4f, 0.6f, 0.01f, 0.05f);
    ms_renderer *r = create_ok(&d);
    draw_ok(r, h, N);
    uint64_t first = image_hash(ms_renderer_pixels(r, NULL, NULL), (size_t)W * W * 4);
    float *other = field(N, 0.2f);
    draw_ok(r, other, N);
    ck_assert_uint_ne(image_hash(ms_renderer_pixels(r, NULL, NULL), (size_t)W * W * 4), first);
    draw_ok(r, h, N);
    ck_assert_uint_eq(image_hash(ms_renderer_pixels(r, NULL, NULL), (size_t)W * W * 4), first);
    ms_renderer_destroy(r);
    free(h);
    free(other);
}
END_TEST

START_TEST(png_round_trips)
{
    REQUIRE_GL();
    make_tmpdir();
    ms_renderer_desc d = top_down("water");
    d.width = 96; /* not square: rows and columns are not swapped */
    float *h = field(N, 0.25f);
    add_bump(h, N, 0.3f, 0.3f, 0.01f, 0.03f);
    ms_renderer *r = create_ok(&d);
    char path[300];
    snprintf(path, sizeof path, "%s/frame.png", tmpdir);
    MS_ASSERT_REFUSED(ms_renderer_write_png(r, path), MS_ERR_STATE, "nothing drawn yet");
    draw_ok(r, h, N);
    ck_assert_int_eq(ms_renderer_write_png(r, path), MS_OK);
    png_image img;
    memset(&img, 0, sizeof img);
    img.version = PNG_IMAGE_VERSION;
    ck_assert(png_image_begin_read_from_file(&img, path));
    ck_assert_uint_eq(img.width, 96);
    ck_assert_uint_eq(img.height, W);
    img.format = PNG_FORMAT_RGBA;
    unsigned char *back = malloc(PNG_IMAGE_SIZE(img));
    ck_assert(png_image_finish_read(&img, NULL, back, 0, NULL));
    ck_assert_int_eq(memcmp(back, ms_renderer_pixels(r, NULL, NULL), (size_t)96 * W * 4), 0);
    free(back);
    /* alpha is opaque everywhere; the sky is at the top of an oblique view */
    const unsigned char *px = ms_renderer_pixels(r, NULL, NULL);
    for (int i = 0; i < 96 * W; ++i)
        ck_assert_int_eq(px[4 * i + 3], 255);
    char tmp[320];
    snprintf(tmp, sizeof tmp, "%s.tmp", path);
    ck_assert_int_ne(access(tmp, F_OK), 0); /* renamed into place */
    snprintf(path, sizeof path, "%s/no/such/dir/frame.png", tmpdir);
    MS_ASSERT_REFUSED(ms_renderer_write_png(r, path), MS_ERR_IO, "cannot write");
    MS_ASSERT_REFUSED(ms_renderer_write_png(r, NULL), MS_ERR_INVALID_ARGUMENT, "path is NULL");
    ms_renderer_destroy(r);
    free(h);
    remove_tmpdir();
}
END_TEST

START_TEST(cubemaps_load_from_a_directory_or_a_strip)
{
    REQUIRE_GL();
    make_tmpdir();
    static const unsigned char colours[6][3] = {{200, 40, 40},  {40, 200, 40},  {40, 40, 200},
                                                {200, 200, 40}, {40, 200, 200}, {200, 40, 200}};
    char dir[300], strip[300];
    snprintf(dir, sizeof dir, "%s/sky", tmpdir);
    write_cubemap_dir(dir, colours);
    /* the same faces as one strip, +x at the top */
    snprintf(strip, sizeof strip, "%s/strip.png", tmpdir);
    {
        png_image img;
        memset(&img, 0, sizeof img);
        img.version = PNG_IMAGE_VERSION;
        img.width = 8;
        img.height = 48;
        img.format = PNG_FORMAT_RGB;
        unsigned char px[8 * 48 * 3];
        for (int i = 0; i < 8 * 48; ++i)
            memcpy(px + 3 * i, colours[i / 64], 3);
        ck_assert(png_image_write_to_file(&img, strip, 0, px, 0, NULL));
    }
    /* looking along +y, level: the sky above the pool is the +y face */
    ms_renderer_desc d = top_down("milk");
    const float eye[3] = {0.5f, -2.0f, 0.6f}, target[3] = {0.5f, 0.5f, 0.6f};
    memcpy(d.eye, eye, sizeof eye);
    memcpy(d.target, target, sizeof target);
    d.up[0] = 0, d.up[1] = 0, d.up[2] = 1;
    float *h = field(N, 0.25f);
    d.cubemap = dir;
    unsigned char *a = render(&d, h, N);
    d.cubemap = strip;
    unsigned char *b = render(&d, h, N);
    ck_assert_int_eq(memcmp(a, b, (size_t)W * W * 4), 0);
    const unsigned char *top = a + ((size_t)4 * W + W / 2) * 4;
    for (int c = 0; c < 3; ++c)
        ck_assert_msg(abs((int)top[c] - colours[2][c]) <= 2, "sky pixel %d %d %d", top[0], top[1],
                      top[2]);
    free(a);
    free(b);

    /* refusals: a missing file, a directory without faces, not a PNG, a
     * strip of the wrong shape, faces of different sizes */
    ms_renderer *r = NULL;
    char path[320];
    snprintf(path, sizeof path, "%s/nothing.png", tmpdir);
    d.cubemap = path;
    MS_ASSERT_REFUSED(ms_renderer_create_desc(&d, &r), MS_ERR_IO, "does not exist");
    snprintf(path, sizeof path, "%s/empty", tmpdir);
    ck_assert_int_eq(mkdir(path, 0700), 0);
    d.cubemap = path;
    MS_ASSERT_REFUSED(ms_renderer_create_desc(&d, &r), MS_ERR_IO, "has no px.png (or posx.png)");
    snprintf(path, sizeof path, "%s/notes.png", tmpdir);
    FILE *f = fopen(path, "w");
    ck_assert_ptr_nonnull(f);
    fputs("not a png\n", f);
    fclose(f);
    d.cubemap = path;
    MS_ASSERT_REFUSED(ms_renderer_create_desc(&d, &r), MS_ERR_PARSE, "is not a readable PNG");
    snprintf(path, sizeof path, "%s/square.png", tmpdir);
    write_face(path, 8, 8, colours[0]);
    d.cubemap = path;
    MS_ASSERT_REFUSED(ms_renderer_create_desc(&d, &r), MS_ERR_INVALID_ARGUMENT,
                      "height = 6 x width");
    snprintf(path, sizeof path, "%s/sky/nz.png", tmpdir);
    write_face(path, 16, 16, colours[5]);
    d.cubemap = dir;
    MS_ASSERT_REFUSED(ms_renderer_create_desc(&d, &r), MS_ERR_INVALID_ARGUMENT,
                      "all of one size (8)");
    ck_assert_ptr_null(r);
    free(h);
    remove_tmpdir();
}
END_TEST

START_TEST(bad_fields_and_shaders_are_refused)
{
    REQUIRE_GL();
    ms_renderer_desc d = top_down("water");
    ms_renderer *r = create_ok(&d);
    float *h = field(N, 0.25f);
    ms_grid g = grid(N);
    h[5 * N + 7] = NAN;
    MS_ASSERT_REFUSED(ms_renderer_draw_field(r, h, &g, 0), MS_ERR_INVALID_ARGUMENT,
                      "at cell (7, 5) is not finite");
    h[5 * N + 7] = 0.25f;
    g.nx = 1;
    MS_ASSERT_REFUSED(ms_renderer_draw_field(r, h, &g, 0), MS_ERR_INVALID_ARGUMENT, "grid nx 1");
    g = grid(N);
    g.dx = 0;
    MS_ASSERT_REFUSED(ms_renderer_draw_field(r, h, &g, 0), MS_ERR_INVALID_ARGUMENT, "grid dx 0");
    g = grid(N);
    MS_ASSERT_REFUSED(ms_renderer_draw_field(r, NULL, &g, 0), MS_ERR_INVALID_ARGUMENT,
                      "height field is NULL");
    MS_ASSERT_REFUSED(ms_renderer_draw_field(r, h, &g, INFINITY), MS_ERR_INVALID_ARGUMENT,
                      "time is inf");
    /* after refusals it still draws */
    draw_ok(r, h, N);
    ms_renderer_destroy(r);
    free(h);

    d.shader = "lava";
    MS_ASSERT_REFUSED(ms_renderer_create_desc(&d, &r), MS_ERR_PLUGIN, "available shaders");
    d.shader = "sphere";
    MS_ASSERT_REFUSED(ms_renderer_create_desc(&d, &r), MS_ERR_PLUGIN, "not a shader");
    d.shader = "water";
    d.shader_params = "{\"ior\": 9}";
    MS_ASSERT_REFUSED(ms_renderer_create_desc(&d, &r), MS_ERR_INVALID_ARGUMENT, "ior 9");
    ck_assert_ptr_null(r);
}
END_TEST

/* A user's shader plugin whose fragment shader has a GLSL error: the
 * refusal carries the compiler's log. */
static const char broken_shader[] =
    "#include <modesplit/plugin.h>\n"
    "static const ms_shader_vtable vt = {\n"
    "    .size = sizeof(ms_shader_vtable), .passes = MS_SHADER_NEEDS_REFLECTION,\n"
    "    .vertex_source = \"#version 120\\nvoid main() { gl_Position = ftransform(); }\\n\",\n"
    "    .fragment_source = \"#version 120\\nvoid main() { gl_FragColor = vec4(undeclared_thing, "
    "1.0); }\\n\"};\n"
    "static const ms_plugin_info info = {.abi = MS_PLUGIN_ABI, .size = sizeof(ms_plugin_info),\n"
    "    .name = \"broken_glsl\", .version = \"1.0\", .kind = MS_PLUGIN_SHADER,\n"
    "    .description = \"a shader that does not compile\", .vtable = &vt};\n"
    "MS_PLUGIN_EXPORT const ms_plugin_info *ms_plugin_entry(void) { return &info; }\n";

START_TEST(a_shader_that_does_not_compile_is_refused_with_its_log)
{
    REQUIRE_GL();
    make_tmpdir();
    char src[320], so[320], cmd[1200];
    snprintf(src, sizeof src, "%s/broken.c", tmpdir);
    snprintf(so, sizeof so, "%s/broken.so", tmpdir);
    FILE *f = fopen(src, "w");
    ck_assert_ptr_nonnull(f);
    fputs(broken_shader, f);
    fclose(f);
    const char *cc = getenv("CC") ? getenv("CC") : "cc";
    snprintf(cmd, sizeof cmd, "%s -std=c11 -shared -fPIC -fvisibility=hidden -Iinclude %s -o %s",
             cc, src, so);
    ck_assert_int_eq(system(cmd), 0);
    ck_assert_int_eq(ms_plugin_load(so), MS_OK);
    ms_renderer_desc d = top_down("broken_glsl");
    ms_renderer *r = NULL;
    MS_ASSERT_REFUSED(ms_renderer_create_desc(&d, &r), MS_ERR_PLUGIN,
                      "shader \"broken_glsl\": the fragment shader does not compile:");
    ck_assert_ptr_nonnull(strstr(ms_last_error(), "undeclared_thing"));
    ck_assert_ptr_null(r);
    remove_tmpdir();
}
END_TEST

START_TEST(a_coarser_mesh_keeps_the_fields_normals)
{
    REQUIRE_GL();
    /* mesh_step 2 draws the field's heights averaged over 2 x 2 blocks but
     * shades with the full field's normals (ms_normal_map): its image is
     * the full mesh's, not that of the averaged field, whose normals lose
     * the ripple of every other cell */
    float *h = field(N, 0.25f), *half = field(N / 2, 0);
    for (int j = 0; j < N; ++j)
        for (int i = 0; i < N; ++i)
            h[j * N + i] += 0.004f * sinf(0.9f * (float)i) * cosf(0.7f * (float)j) +
                            0.002f * sinf(2.6f * (float)i + 1.3f * (float)j);
    for (int j = 0; j < N / 2; ++j)
        for (int i = 0; i < N / 2; ++i)
            half[j * (N / 2) + i] =
                0.25f * (h[2 * j * N + 2 * i] + h[2 * j * N + 2 * i + 1] +
                         h[(2 * j + 1) * N + 2 * i] + h[(2 * j + 1) * N + 2 * i + 1]);
    ms_renderer_desc d = top_down("milk"); /* no caustics: they trace the full field */
    d.mesh_step = 2;
    ms_renderer *r = create_ok(&d);
    draw_ok(r, h, N);
    ms_render_stats st = ms_render_stats_init();
    ms_renderer_get_stats(r, &st);
    ck_assert_int_eq(st.mesh_nx, N / 2);
    ck_assert_int_eq(st.mesh_ny, N / 2);
    unsigned char *coarse = malloc((size_t)W * W * 4);
    memcpy(coarse, ms_renderer_pixels(r, NULL, NULL), (size_t)W * W * 4);
    ms_renderer_destroy(r);
    d.mesh_step = 1;
    unsigned char *full = render(&d, h, N), *averaged = render(&d, half, N / 2);
    const double to_full = box_mean_abs_diff(coarse, full, 0, 0, W, W);
    const double to_averaged = box_mean_abs_diff(coarse, averaged, 0, 0, W, W);
    ck_assert_msg(to_full < 0.5 && to_averaged > 4 * to_full + 1.0,
                  "mean |difference| of the step-2 image: %.2f levels to the full mesh, %.2f "
                  "to the averaged field",
                  to_full, to_averaged);
    free(full);
    free(averaged);
    /* automatic: a small image of a fine, flat field keeps a vertex every
     * MS_MESH_AUTO_PIXELS (32) pixels at most */
    d.mesh_step = 0;
    d.width = d.height = 128;
    r = create_ok(&d);
    float *fine = field(256, 0.25f);
    draw_ok(r, fine, 256);
    ms_renderer_get_stats(r, &st);
    /* 0.94 m of water across 128 pixels: 32 pixels = 23.5 cm, 60 cells */
    ck_assert_int_eq(st.mesh_nx, 256 / 60);
    /* waves 3 cm high, 20 cells long: the block averages of 60 cells would
     * flatten them by far more than MS_MESH_AUTO_ERROR_PX (2) pixels, so
     * the screen-space error lowers the step until the mesh's heights
     * follow the waves */
    for (int j = 0; j < 256; ++j)
        for (int i = 0; i < 256; ++i)
            fine[j * 256 + i] = 0.25f + 0.03f * sinf(0.314f * (float)i) * cosf(0.25f * (float)j);
    draw_ok(r, fine, 256);
    ms_renderer_get_stats(r, &st);
    const ms_grid g256 = grid(256);
    float *scratch = malloc(sizeof *scratch * 128 * 128);
    const int auto_step = ms_mesh_auto_step(&d, fine, &g256, scratch);
    ck_assert_msg(auto_step < 60 && st.mesh_nx == 256 / auto_step,
                  "waves of 3 cm: step %d, mesh %d", auto_step, st.mesh_nx);
    ck_assert_int_ge(auto_step, 2);
    /* the eye straight above the pool: metres per pixel at the water */
    const double px =
        2.0 * (d.eye[2] - d.water_level) * tan(0.5 * d.fov * 3.14159265358979 / 180.0) / d.height;
    const double flat_err = ms_mesh_height_error(fine, &g256, 60, scratch);
    const double auto_err = ms_mesh_height_error(fine, &g256, auto_step, scratch);
    ck_assert_msg(flat_err > MS_MESH_AUTO_ERROR_PX * px && auto_err <= MS_MESH_AUTO_ERROR_PX * px,
                  "height error %.4f m at step 60, %.4f m at step %d; bound %.4f m", flat_err,
                  auto_err, auto_step, MS_MESH_AUTO_ERROR_PX * px);
    free(scratch);
    ms_renderer_destroy(r);
    free(fine);
    free(coarse);
    free(h);
    free(half);
}
END_TEST

START_TEST(floating_discs_are_drawn_on_the_surface)
{
    REQUIRE_GL();
    ms_renderer_desc d = top_down("water");
    ms_renderer *r = create_ok(&d);
    float *h = field(N, 0.25f);
    draw_ok(r, h, N);
    unsigned char *plain = malloc((size_t)W * W * 4);
    memcpy(plain, ms_renderer_pixels(r, NULL, NULL), (size_t)W * W * 4);
    /* a red leaf at the centre, a boat at the lower left */
    const ms_render_disc discs[2] = {{{0.5f, 0.5f, 0.25f}, 0.05f, {0.9f, 0.05f, 0.05f}},
                                     {{0.25f, 0.25f, 0.25f}, 0.08f, {0.4f, 0.2f, 0.1f}}};
    ck_assert_int_eq(ms_renderer_set_discs(r, discs, 2), MS_OK);
    draw_ok(r, h, N);
    const unsigned char *px = ms_renderer_pixels(r, NULL, NULL);
    const unsigned char *c = px + ((size_t)(W / 2) * W + W / 2) * 4;
    ck_assert_msg(c[0] > 150 && c[1] < 80 && c[2] < 80, "the leaf is %d %d %d", c[0], c[1], c[2]);
    /* nothing changed away from the discs */
    ck_assert_int_eq(box_max_abs_diff(px, plain, W / 2 + 20, 8, W - 8, W / 2 - 20), 0);
    /* removed again */
    ck_assert_int_eq(ms_renderer_set_discs(r, NULL, 0), MS_OK);
    draw_ok(r, h, N);
    ck_assert_int_eq(memcmp(ms_renderer_pixels(r, NULL, NULL), plain, (size_t)W * W * 4), 0);
    ms_render_disc bad = discs[0];
    bad.radius = 0;
    MS_ASSERT_REFUSED(ms_renderer_set_discs(r, &bad, 1), MS_ERR_INVALID_ARGUMENT,
                      "disc 0 radius 0 m must be finite and > 0");
    bad = discs[0];
    bad.color[1] = 1.5f;
    MS_ASSERT_REFUSED(ms_renderer_set_discs(r, &bad, 1), MS_ERR_INVALID_ARGUMENT,
                      "disc 0 color[1] 1.5");
    MS_ASSERT_REFUSED(ms_renderer_set_discs(r, discs, -1), MS_ERR_INVALID_ARGUMENT, "discs n -1");
    MS_ASSERT_REFUSED(ms_renderer_set_discs(r, NULL, 1), MS_ERR_INVALID_ARGUMENT, "discs is NULL");
    ms_renderer_destroy(r);
    free(plain);
    free(h);
}
END_TEST

/* Mean over the window's pixels and channels of |a - b| (sRGB levels). */
static double window_mean_abs_diff(const unsigned char *a, const unsigned char *b, int cx, int cy,
                                   int half)
{
    double sum = 0;
    int n = 0;
    for (int y = cy - half; y <= cy + half; ++y)
        for (int x = cx - half; x <= cx + half; ++x)
            for (int k = 0; k < 3; ++k, ++n)
                sum +=
                    abs((int)a[((size_t)y * W + x) * 4 + k] - (int)b[((size_t)y * W + x) * 4 + k]);
    return sum / n;
}

/* The pixel column of world x at height z in top_down's view (centre row
 * for y = 0.5): the eye 2 m up at x = 0.5, 30 degrees across. */
static int top_down_column(float x, float z)
{
    const float half = (2.0f - z) * tanf(15.0f * 3.14159265f / 180.0f);
    return (int)lroundf(0.5f * W * (1.0f + (x - 0.5f) / half));
}

START_TEST(obstacles_and_the_glass_are_drawn_with_their_shapes)
{
    REQUIRE_GL();
    /* a box standing out of the water at x = 0.3 and a glass (the
     * container) at x = 0.7, both on the pool's centre line, moved there
     * by their paths at t = 1 s */
    const char *text =
        "{\"surface\": {\"cells\": [64, 64]},"
        " \"obstacles\": [{\"shape\": \"box\", \"params\": {\"size\": [0.16, 0.16, 0.4]},"
        "   \"path\": {\"points\": [[0.3, 0.2, 0.2], [0.3, 0.5, 0.2]], \"speed\": 0.3}}],"
        " \"effects\": {\"container\": {\"shape\": \"glass\","
        "   \"params\": {\"radius\": 0.1, \"height\": 0.4, \"wall\": 0.01, \"floor\": 0.01},"
        "   \"path\": {\"points\": [[0.7, 0.8, 0.0], [0.7, 0.5, 0.0]], \"speed\": 0.3}}}}";
    ms_scene *sc = NULL;
    ms_status st = ms_scene_parse(text, strlen(text), &sc);
    ck_assert_msg(st == MS_OK, "%s", ms_last_error());
    ms_renderer_desc d = top_down("water");
    /* 5 mm of water: the glass's floor (1 cm) is above it (objects under
     * the surface are not drawn through it yet) */
    float *h = field(N, 0.005f);
    unsigned char *plain = render(&d, h, N);
    ms_renderer *r = create_ok(&d);
    ms_grid g = grid(N);
    st = ms_renderer_draw_scene_field(r, sc, h, &g, 1.0);
    ck_assert_msg(st == MS_OK, "%s: %s", ms_status_name(st), ms_last_error());
    const unsigned char *px = ms_renderer_pixels(r, NULL, NULL);
    /* the box's lid (z = 0.4) covers the water: it is opaque stone */
    const int bx = top_down_column(0.3f, 0.4f), gx = top_down_column(0.7f, 0.4f), half = W / 32;
    const double box = window_mean_abs_diff(px, plain, bx, W / 2, half);
    ck_assert_msg(box > 40, "the box changes its footprint by %.1f levels only", box);
    /* through the glass's floor the pool still shows, tinted: changed,
     * less than by the opaque box */
    const double glass = window_mean_abs_diff(px, plain, gx, W / 2, half);
    ck_assert_msg(glass > 3 && glass < box,
                  "the glass changes its footprint by %.1f levels "
                  "(the box by %.1f)",
                  glass, box);
    /* where neither is (their paths' start at t = 0), nothing changed */
    const double away = window_mean_abs_diff(px, plain, W / 2, W / 2, half);
    ck_assert_msg(away < 1, "the pool's centre changed by %.1f levels", away);
    /* at t = 0 the box is at y = 0.2 (lower in the image): its t = 1
     * footprint shows the water again */
    st = ms_renderer_draw_scene_field(r, sc, h, &g, 0.0);
    ck_assert_msg(st == MS_OK, "%s: %s", ms_status_name(st), ms_last_error());
    const double moved =
        window_mean_abs_diff(ms_renderer_pixels(r, NULL, NULL), plain, bx, W / 2, half);
    ck_assert_msg(moved < 1, "the box left its t = 1 place changed by %.1f levels", moved);
    ms_renderer_destroy(r);
    ms_scene_destroy(sc);
    free(plain);
    free(h);
}
END_TEST

START_TEST(moving_the_camera_is_creating_with_it)
{
    REQUIRE_GL();
    float *h = field(N, 0.25f);
    add_bump(h, N, 0.4f, 0.6f, 0.01f, 0.05f);
    ms_renderer_desc a = top_down("water"), b = a;
    const float eye[3] = {1.6f, -0.4f, 1.1f}, target[3] = {0.5f, 0.5f, 0.2f}, up[3] = {0, 0, 1};
    memcpy(b.eye, eye, sizeof eye);
    memcpy(b.target, target, sizeof target);
    memcpy(b.up, up, sizeof up);
    b.fov = 50;
    unsigned char *want = render(&b, h, N);
    ms_renderer *r = create_ok(&a);
    draw_ok(r, h, N);
    ck_assert_int_eq(ms_renderer_set_camera(r, eye, target, up, 50), MS_OK);
    draw_ok(r, h, N);
    ck_assert_int_eq(memcmp(ms_renderer_pixels(r, NULL, NULL), want, (size_t)W * W * 4), 0);
    /* refused moves leave the camera where it was */
    MS_ASSERT_REFUSED(ms_renderer_set_camera(r, eye, eye, up, 50), MS_ERR_INVALID_ARGUMENT,
                      "equals eye");
    MS_ASSERT_REFUSED(ms_renderer_set_camera(r, eye, target, up, 0), MS_ERR_INVALID_ARGUMENT,
                      "fov 0 degrees");
    MS_ASSERT_REFUSED(ms_renderer_set_camera(r, NULL, target, up, 50), MS_ERR_INVALID_ARGUMENT,
                      "eye is NULL");
    draw_ok(r, h, N);
    ck_assert_int_eq(memcmp(ms_renderer_pixels(r, NULL, NULL), want, (size_t)W * W * 4), 0);
    ms_renderer_destroy(r);
    free(want);
    free(h);
}
END_TEST

typedef struct job {
    const float *h;
    unsigned char *px;
    int ok;
} job;

static void *render_job(void *arg)
{
    job *j = arg;
    ms_renderer_desc d = top_down("water");
    ms_renderer *r = NULL;
    ms_grid g = grid(N);
    j->ok = ms_renderer_create_desc(&d, &r) == MS_OK;
    for (int f = 0; j->ok && f < 3; ++f)
        j->ok = ms_renderer_draw_field(r, j->h, &g, 0.5) == MS_OK;
    if (j->ok)
        memcpy(j->px, ms_renderer_pixels(r, NULL, NULL), (size_t)W * W * 4);
    ms_renderer_destroy(r);
    return NULL;
}

START_TEST(renderers_in_two_threads_draw_what_one_draws)
{
    REQUIRE_GL();
    float *h = field(N, 0.25f);
    add_bump(h, N, 0.6f, 0.4f, 0.01f, 0.05f);
    job jobs[3];
    pthread_t t[2];
    for (int k = 0; k < 3; ++k) {
        jobs[k].h = h;
        jobs[k].px = malloc((size_t)W * W * 4);
        jobs[k].ok = 0;
    }
    render_job(&jobs[2]); /* alone */
    for (int k = 0; k < 2; ++k)
        ck_assert_int_eq(pthread_create(&t[k], NULL, render_job, &jobs[k]), 0);
    for (int k = 0; k < 2; ++k)
        ck_assert_int_eq(pthread_join(t[k], NULL), 0);
    for (int k = 0; k < 3; ++k)
        ck_assert_msg(jobs[k].ok, "job %d failed: %s", k, ms_last_error());
    for (int k = 0; k < 2; ++k)
        ck_assert_int_eq(memcmp(jobs[k].px, jobs[2].px, (size_t)W * W * 4), 0);
    for (int k = 0; k < 3; ++k)
        free(jobs[k].px);
    free(h);
}
END_TEST

/* A small scene of waves only, with a drop, leaves and a boat. */
static const char sim_scene[] =
    "{\"surface\": {\"cells\": [64, 64], \"wave_speed\": 0.3},"
    " \"effects\": {\"drops\": [{\"at\": [0.4, 0.6], \"radius\": 0.05, \"amplitude\": 0.01}],"
    "   \"floaters\": {\"positions\": [[0.3, 0.3], [0.7, 0.3], [0.5, 0.8]]},"
    "   \"boat\": {\"path\": {\"points\": [[0.2, 0.5], [0.8, 0.5]], \"speed\": 0.2},"
    "             \"radius\": 0.04, \"depth\": 0.005}},"
    " \"render\": {\"width\": 128, \"height\": 128, \"caustics\": {\"resolution\": 64},"
    "   \"camera\": {\"eye\": [0.5, 0.5, 2.0], \"target\": [0.5, 0.5, 0.25],"
    "              \"up\": [0, 1, 0], \"fov\": 30}}}";

START_TEST(draw_renders_the_sims_field_with_its_floaters_and_boat)
{
    REQUIRE_GL();
    ms_scene *sc = NULL;
    ck_assert_int_eq(ms_scene_parse(sim_scene, strlen(sim_scene), &sc), MS_OK);
    ms_sim *sim = NULL;
    ms_status st = ms_sim_create_from_scene(sc, 1, &sim);
    ck_assert_msg(st == MS_OK, "%s", ms_last_error());
    ms_renderer *r = NULL;
    st = ms_renderer_create_from_scene(sc, &r);
    ck_assert_msg(st == MS_OK, "%s", ms_last_error());
    MS_ASSERT_REFUSED(ms_renderer_draw(r, sim), MS_ERR_STATE, "step it first");
    MS_ASSERT_REFUSED(ms_renderer_draw(r, NULL), MS_ERR_INVALID_ARGUMENT, "sim is NULL");
    for (int f = 0; f < 10; ++f)
        ck_assert_int_eq(ms_sim_step(sim, 1.0f / 60), MS_OK);
    st = ms_renderer_draw(r, sim);
    ck_assert_msg(st == MS_OK, "%s", ms_last_error());
    /* three leaves as discs, and the boat as a hull */
    ck_assert_int_eq(r->ndiscs, 3);
    int nf = 0;
    const float *xyz = ms_sim_floaters(sim, &nf);
    ck_assert_int_eq(nf, 3);
    ck_assert_float_eq(r->discs[1].pos[0], xyz[3]);
    ck_assert_float_eq(r->discs[1].pos[2], xyz[5]);
    /* the boat has moved 0.2 m/s x the fields' time along its path, its
     * bow along it (+x) */
    ck_assert(r->has_boat);
    ck_assert_float_eq_tol(r->boat_pos[0], 0.2f + 0.2f * (float)ms_sim_time(sim), 1e-5f);
    ck_assert_float_eq_tol(r->boat_radius, 0.04f, 1e-7f);
    ck_assert_float_eq_tol(r->boat_heading[0], 1.0f, 1e-6f);
    ck_assert_float_eq_tol(r->boat_heading[1], 0.0f, 1e-6f);

    /* the same as drawing the sim's combined field with the scene's
     * objects and the same leaves, by hand */
    unsigned char *want = malloc((size_t)W * W * 4);
    memcpy(want, ms_renderer_pixels(r, NULL, NULL), (size_t)W * W * 4);
    ms_render_disc discs[3];
    memcpy(discs, r->discs, sizeof discs);
    ms_renderer_destroy(r);
    ck_assert_int_eq(ms_renderer_create_from_scene(sc, &r), MS_OK);
    ck_assert_int_eq(ms_renderer_set_discs(r, discs, 3), MS_OK);
    int nx, ny;
    const float *h = ms_sim_height(sim, &nx, &ny);
    ms_grid g;
    ck_assert_int_eq(ms_sim_field_grid(sim, MS_FIELD_COMBINED, &g), MS_OK);
    ck_assert_int_eq(g.nx, nx);
    /* draw_scene_field draws the boat but keeps the discs set by hand */
    ck_assert_int_eq(ms_renderer_set_discs(r, discs, 3), MS_OK);
    ck_assert_int_eq(ms_renderer_draw_field(r, h, &g, ms_sim_time(sim)), MS_OK);
    ck_assert_int_gt(box_max_abs_diff(ms_renderer_pixels(r, NULL, NULL), want, 0, 0, W, W), 20);
    ck_assert_int_eq(ms_renderer_draw_scene_field(r, sc, h, &g, ms_sim_time(sim)), MS_OK);
    /* the same picture but for the leaves' shapes: ms_renderer_draw draws
     * the floaters as pointed leaves, hand-set discs are round */
    {
        const unsigned char *got = ms_renderer_pixels(r, NULL, NULL);
        const double half = 1.75 * tan(15 * 3.14159265358979 / 180); /* m at the water */
        int near_leaf = 0, far_off = 0;
        for (int y = 0; y < W; ++y)
            for (int x = 0; x < W; ++x) {
                int leafy = 0;
                for (int k = 0; k < 3; ++k) {
                    double lx = (discs[k].pos[0] - 0.5) / half * (W / 2) + W / 2;
                    double ly = -(discs[k].pos[1] - 0.5) / half * (W / 2) + W / 2;
                    leafy |= fabs(x - lx) <= 6 && fabs(y - ly) <= 6;
                }
                size_t i = 4 * ((size_t)y * W + (size_t)x);
                int dif = abs(got[i] - want[i]) + abs(got[i + 1] - want[i + 1]) +
                          abs(got[i + 2] - want[i + 2]);
                if (leafy)
                    near_leaf = MS_MAX(near_leaf, dif);
                else
                    far_off = MS_MAX(far_off, dif);
            }
        ck_assert_msg(far_off == 0, "away from the leaves the pictures differ by %d", far_off);
        ck_assert_msg(near_leaf > 0, "leaves and round discs look the same");
    }
    /* and the drop shows: the image is not the still pool's */
    float *still = field(64, sc->level);
    ck_assert_int_eq(ms_renderer_draw_field(r, still, &g, 0), MS_OK);
    ck_assert_int_gt(box_max_abs_diff(ms_renderer_pixels(r, NULL, NULL), want, 0, 0, W, W), 20);
    free(still);
    free(want);
    ms_renderer_destroy(r);
    ms_sim_destroy(sim);
    ms_scene_destroy(sc);
}
END_TEST

START_TEST(a_scene_renders_and_every_shader_draws)
{
    REQUIRE_GL();
    const char *text = "{\"surface\": {\"cells\": [64, 64]},"
                       " \"render\": {\"width\": 64, \"height\": 64, \"shader\": \"oil\"}}";
    ms_scene *sc = NULL;
    ck_assert_int_eq(ms_scene_parse(text, strlen(text), &sc), MS_OK);
    ms_renderer *r = NULL;
    ck_assert_int_eq(ms_renderer_create_from_scene(sc, &r), MS_OK);
    float *h = field(N, 0.25f);
    add_bump(h, N, 0.5f, 0.5f, 0.01f, 0.05f);
    draw_ok(r, h, N);
    int w, hh;
    ck_assert_ptr_nonnull(ms_renderer_pixels(r, &w, &hh));
    ck_assert_int_eq(w, 64);
    ck_assert_int_eq(hh, 64);
    ms_renderer_destroy(r);
    ms_scene_destroy(sc);
    /* each shipped shader: the liquid's colour at the image's centre */
    static const char *const shaders[] = {"water", "milk", "oil", "honey"};
    float lum[4], rgb[4][3];
    for (int s = 0; s < 4; ++s) {
        ms_renderer_desc d = top_down(shaders[s]);
        const float low_sun[3] = {1, 0, -0.3f}; /* its glint out of view */
        memcpy(d.light_dir, low_sun, sizeof low_sun);
        unsigned char *px = render(&d, h, N);
        const unsigned char *c = px + ((size_t)(W / 2) * W + W / 4) * 4;
        for (int k = 0; k < 3; ++k)
            rgb[s][k] = (float)srgb_to_linear(c[k]);
        lum[s] = 0.2126f * rgb[s][0] + 0.7152f * rgb[s][1] + 0.0722f * rgb[s][2];
        free(px);
    }
    ck_assert_msg(rgb[0][2] > rgb[0][0], "water is not blue");
    ck_assert_msg(lum[1] > lum[0] && lum[1] > lum[2] && lum[1] > lum[3],
                  "milk is not the brightest");
    ck_assert_msg(lum[2] < 0.1f, "oil is not dark: %g", lum[2]);
    ck_assert_msg(rgb[3][0] > rgb[3][1] && rgb[3][1] > rgb[3][2], "honey is not amber");
    free(h);
}
END_TEST

/* Ripples over the whole pool: 2 mm, 8 cm by 11 cm wavelengths. */
static void add_ripples(float *h, int n, float amp)
{
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            float x = ((float)i + 0.5f) / (float)n, y = ((float)j + 0.5f) / (float)n;
            h[j * n + i] += amp * sinf(6.2831853f * x / 0.08f) * cosf(6.2831853f * y / 0.11f);
        }
}

/* The same field through OSMesa and through EGL (surfaceless Mesa): both
 * llvmpipe, so the same bytes; the stats name the backend that drew. A
 * backend this build lacks is refused naming it, and the case is skipped. */
START_TEST(each_backend_draws_the_same_picture)
{
    REQUIRE_GL();
    float *h = field(N, 0.25f);
    add_ripples(h, N, 0.002f);
    static const char *const names[2] = {"osmesa", "egl"};
    static const int built[2] = {MS_HAVE_OSMESA, MS_HAVE_EGL};
    unsigned char *img[2] = {NULL, NULL};
    for (int b = 0; b < 2; ++b) {
        ms_renderer_desc d = top_down("water");
        d.backend = names[b];
        ms_renderer *r = NULL;
        if (!built[b]) {
            MS_ASSERT_REFUSED(ms_renderer_create_desc(&d, &r), MS_ERR_UNSUPPORTED,
                              "not in this build");
            continue;
        }
        r = create_ok(&d);
        draw_ok(r, h, N);
        ms_render_stats st = ms_render_stats_init();
        ms_renderer_get_stats(r, &st);
        ck_assert_str_eq(st.backend, names[b]);
        size_t bytes = (size_t)W * W * 4;
        img[b] = malloc(bytes);
        ck_assert_ptr_nonnull(img[b]);
        memcpy(img[b], ms_renderer_pixels(r, NULL, NULL), bytes);
        ms_renderer_destroy(r);
    }
    ms_renderer_desc d = top_down("water");
    d.backend = "vulkan";
    ms_renderer *r = NULL;
    MS_ASSERT_REFUSED(ms_renderer_create_desc(&d, &r), MS_ERR_INVALID_ARGUMENT, "backend");
    /* "auto" draws with one of them */
    d.backend = "auto";
    r = create_ok(&d);
    ms_render_stats st = ms_render_stats_init();
    ms_renderer_get_stats(r, &st);
    ck_assert(!strcmp(st.backend, "osmesa") || !strcmp(st.backend, "egl"));
    ms_renderer_destroy(r);
    free(h);
    if (!img[0] || !img[1]) {
        free(img[0]);
        free(img[1]);
        MS_SKIP("this build has one GL backend only: nothing to compare it with");
    }
    int most = box_max_abs_diff(img[0], img[1], 0, 0, W, W);
    ck_assert_msg(most <= 1, "OSMesa and EGL pictures differ by %d levels", most);
    free(img[0]);
    free(img[1]);
}
END_TEST

/* Luma (Rec. 601, of the sRGB bytes) of pixel i. */
static double luma(const unsigned char *px, size_t i)
{
    return 0.299 * px[4 * i] + 0.587 * px[4 * i + 1] + 0.114 * px[4 * i + 2];
}

typedef struct look {
    double clipped;  /* share of pixels with a channel at 255 */
    double mean, sd; /* luma, levels */
    double rgb[3];   /* mean bytes */
} look;

/* The look of the middle of a top-down image (all liquid). */
static look measure_look(const unsigned char *px)
{
    look k = {0, 0, 0, {0, 0, 0}};
    double s = 0, s2 = 0;
    long n = 0, clipped = 0;
    for (int y = W / 5; y < 4 * W / 5; ++y)
        for (int x = W / 5; x < 4 * W / 5; ++x, ++n) {
            size_t i = (size_t)y * W + (size_t)x;
            clipped += px[4 * i] == 255 || px[4 * i + 1] == 255 || px[4 * i + 2] == 255;
            double l = luma(px, i);
            s += l, s2 += l * l;
            for (int c = 0; c < 3; ++c)
                k.rgb[c] += px[4 * i + (size_t)c];
        }
    k.clipped = (double)clipped / (double)n;
    k.mean = s / (double)n;
    k.sd = sqrt(MS_MAX(s2 / (double)n - k.mean * k.mean, 0.0));
    for (int c = 0; c < 3; ++c)
        k.rgb[c] /= (double)n;
    return k;
}

/* Every shader on ripples (2 mm, 8 x 11 cm), the sun at the side, seen from
 * above: at most 1 % of the liquid's pixels clip at 255 in any channel, the
 * ripples show (luma standard deviation at least MIN_RIPPLE_SD levels);
 * milk is brighter than water and hides the floor (a floor 10 times
 * brighter changes it by under a quarter of what it changes water); honey
 * is darker than water and warmer (red over blue). */
#define MIN_RIPPLE_SD 3.0
START_TEST(each_shader_shows_its_ripples_unclipped)
{
    REQUIRE_GL();
    float *h = field(2 * N, 0.25f);
    add_ripples(h, 2 * N, 0.002f);
    static const char *const names[4] = {"water", "milk", "oil", "honey"};
    look k[4], dark[4];
    for (int s = 0; s < 4; ++s) {
        ms_renderer_desc d = top_down(names[s]);
        const float side_sun[3] = {0.6f, 0.3f, -1.0f};
        memcpy(d.light_dir, side_sun, sizeof side_sun);
        unsigned char *px = render(&d, h, 2 * N);
        k[s] = measure_look(px);
        free(px);
        for (int c = 0; c < 3; ++c)
            d.floor_color[c] = 0.1f * d.floor_color[c];
        px = render(&d, h, 2 * N);
        dark[s] = measure_look(px);
        free(px);
    }
    for (int s = 0; s < 4; ++s) {
        ck_assert_msg(k[s].clipped <= 0.01, "%s: %.2f %% of the liquid clips at 255", names[s],
                      100 * k[s].clipped);
        ck_assert_msg(k[s].sd >= MIN_RIPPLE_SD, "%s: ripples show only %.2f levels of luma",
                      names[s], k[s].sd);
    }
    ck_assert_msg(k[1].mean > k[0].mean, "milk %.1f is not brighter than water %.1f", k[1].mean,
                  k[0].mean);
    double water_sees = k[0].mean - dark[0].mean, milk_sees = fabs(k[1].mean - dark[1].mean);
    ck_assert_msg(water_sees > 5 && milk_sees < 0.25 * water_sees,
                  "the floor changes water by %.1f levels, milk by %.1f", water_sees, milk_sees);
    ck_assert_msg(k[3].mean < k[0].mean, "honey %.1f is not darker than water %.1f", k[3].mean,
                  k[0].mean);
    ck_assert_msg(k[3].rgb[0] > k[3].rgb[2] + 20 && k[0].rgb[2] > k[0].rgb[0],
                  "honey is not warmer than water: honey rgb %.0f %.0f %.0f, water %.0f %.0f %.0f",
                  k[3].rgb[0], k[3].rgb[1], k[3].rgb[2], k[0].rgb[0], k[0].rgb[1], k[0].rgb[2]);
    free(h);
}
END_TEST

/* A fixed, scene-independent surface for the golden images: ripples of
 * 2 mm and two bumps of 1 cm over still water (so a change of the sim does
 * not change the pictures; a change of the look does). */
static float *golden_field(const ms_renderer_desc *d, int n, ms_grid *g)
{
    const float lx = d->pool_max[0] - d->pool_min[0], ly = d->pool_max[1] - d->pool_min[1];
    *g = (ms_grid){n, n, lx / (float)n, ly / (float)n, {d->pool_min[0], d->pool_min[1]}};
    float *h = field(n, d->water_level - d->pool_min[2]);
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            float x = ((float)i + 0.5f) / (float)n, y = ((float)j + 0.5f) / (float)n;
            float r1 = (x - 0.35f) * (x - 0.35f) + (y - 0.6f) * (y - 0.6f);
            float r2 = (x - 0.7f) * (x - 0.7f) + (y - 0.35f) * (y - 0.35f);
            h[j * n + i] += 0.002f * sinf(6.2831853f * x / 0.09f) * cosf(6.2831853f * y / 0.13f) +
                            0.01f * expf(-r1 / 0.004f) - 0.008f * expf(-r2 / 0.006f);
        }
    return h;
}

#define GOLDEN_SIDE 160
#define MIN_RIPPLE_CHANGE 2.0 /* levels of luma: the ripples against still water */
/* ... where the scene looks the refraction up through the point the ray
 * meets (the water shader's parallax 1: stir): the 2 mm ripples move
 * stir's floor, 12 cm down, by ~1 mm, under a pixel at 160 x 160; they
 * show in the reflection and the glints (0.79 levels) */
#define MIN_RIPPLE_CHANGE_PARALLAX 0.5
#define GOLDEN_MEAN_TOL 1.5    /* levels: mean |difference| over all channels */
#define GOLDEN_FAR_TOL 24      /* levels: a channel this far off is a visible change... */
#define GOLDEN_FAR_SHARE 0.005 /* ...allowed on at most this share of the pixels */

/* Each shipped scene's render section draws the golden field (at 160 x 160,
 * with the scene's boat at t = 1 s): the liquid in the middle of the
 * picture is not clipped (at most 1 % of pixels at 255) and shows the
 * ripples (its luma differs from still water's by MIN_RIPPLE_CHANGE levels
 * on average), and the picture matches
 * tests/data/golden/<scene>.png within a tolerance. `make golden` (which
 * sets MS_GOLDEN_WRITE=1) writes the pictures afresh: a deliberate step,
 * so a change of the look is a visible diff in review. */
START_TEST(the_shipped_scenes_render_their_golden_pictures)
{
    REQUIRE_GL();
    static const char *const scenes[] = {"fig1", "fig9a", "fig9b", "fig10", "sky", "glass",
                                         /* every shipped look (the _x10 variants
                                          * draw as their scenes) */
                                         "default", "fig3", "fig4c", "stir"};
    const int write = getenv("MS_GOLDEN_WRITE") && !strcmp(getenv("MS_GOLDEN_WRITE"), "1");
    for (size_t k = 0; k < sizeof scenes / sizeof scenes[0]; ++k) {
        char path[128], golden[128];
        snprintf(path, sizeof path, "data/scenes/%s.json", scenes[k]);
        snprintf(golden, sizeof golden, "tests/data/golden/%s.png", scenes[k]);
        ms_scene *sc = NULL;
        ms_status st = ms_scene_load(path, &sc);
        ck_assert_msg(st == MS_OK, "%s: %s", path, ms_last_error());
        ck_assert(ms_scene_has_render(sc));
        ms_renderer_desc d = ms_renderer_desc_default();
        ck_assert_int_eq(ms_renderer_desc_from_scene(sc, &d), MS_OK);
        d.width = d.height = GOLDEN_SIDE;
        d.caustics_resolution = 128;
        ms_renderer *r = NULL;
        st = ms_renderer_create_desc(&d, &r);
        ck_assert_msg(st == MS_OK, "%s: %s", path, ms_last_error());
        ms_grid g;
        float *flat = field(128, d.water_level - d.pool_min[2]);
        float *h = golden_field(&d, 128, &g);
        st = ms_renderer_draw_scene_field(r, sc, flat, &g, 1.0);
        ck_assert_msg(st == MS_OK, "%s: %s", path, ms_last_error());
        const size_t bytes = (size_t)GOLDEN_SIDE * GOLDEN_SIDE * 4;
        unsigned char *still = malloc(bytes);
        ck_assert_ptr_nonnull(still);
        memcpy(still, ms_renderer_pixels(r, NULL, NULL), bytes);
        st = ms_renderer_draw_scene_field(r, sc, h, &g, 1.0);
        ck_assert_msg(st == MS_OK, "%s: %s", path, ms_last_error());
        const unsigned char *px = ms_renderer_pixels(r, NULL, NULL);
        /* the liquid: the middle of the picture (every shipped camera
         * looks at the pool's centre); stir's paddle stands there, so its
         * liquid is the band in front of the paddle */
        const int band = strcmp(scenes[k], "stir") ? 2 : 3;
        long n = 0, clipped = 0;
        double moved = 0;
        for (int y = band * GOLDEN_SIDE / 5; y < (band + 1) * GOLDEN_SIDE / 5; ++y)
            for (int x = GOLDEN_SIDE / 4; x < 3 * GOLDEN_SIDE / 4; ++x, ++n) {
                size_t i = (size_t)y * GOLDEN_SIDE + (size_t)x;
                clipped += px[4 * i] == 255 || px[4 * i + 1] == 255 || px[4 * i + 2] == 255;
                moved += fabs(luma(px, i) - luma(still, i));
            }
        free(still);
        free(flat);
        ck_assert_msg(clipped <= n / 100, "%s: %ld of %ld liquid pixels clip", scenes[k], clipped,
                      n);
        const double least =
            strcmp(scenes[k], "stir") ? MIN_RIPPLE_CHANGE : MIN_RIPPLE_CHANGE_PARALLAX;
        ck_assert_msg(moved / (double)n >= least,
                      "%s: the ripples change the liquid by %.2f levels of luma only", scenes[k],
                      moved / (double)n);
        if (write) {
            mkdir("tests/data/golden", 0777);
            ck_assert_int_eq(ms_renderer_write_png(r, golden), MS_OK);
        } else {
            png_image img;
            memset(&img, 0, sizeof img);
            img.version = PNG_IMAGE_VERSION;
            ck_assert_msg(png_image_begin_read_from_file(&img, golden),
                          "%s: no golden picture (run `make golden`): %s", golden, img.message);
            img.format = PNG_FORMAT_RGBA;
            ck_assert_int_eq(img.width, GOLDEN_SIDE);
            ck_assert_int_eq(img.height, GOLDEN_SIDE);
            unsigned char *want = malloc((size_t)GOLDEN_SIDE * GOLDEN_SIDE * 4);
            ck_assert_ptr_nonnull(want);
            ck_assert(png_image_finish_read(&img, NULL, want, 0, NULL));
            double sum = 0;
            long far = 0;
            for (size_t i = 0; i < (size_t)GOLDEN_SIDE * GOLDEN_SIDE; ++i) {
                int worst = 0;
                for (int c = 0; c < 3; ++c) {
                    int dlt = abs((int)px[4 * i + (size_t)c] - (int)want[4 * i + (size_t)c]);
                    sum += dlt;
                    worst = MS_MAX(worst, dlt);
                }
                far += worst > GOLDEN_FAR_TOL;
            }
            free(want);
            double mean_diff = sum / (3.0 * GOLDEN_SIDE * GOLDEN_SIDE);
            ck_assert_msg(mean_diff <= GOLDEN_MEAN_TOL &&
                              far <= (long)(GOLDEN_FAR_SHARE * GOLDEN_SIDE * GOLDEN_SIDE),
                          "%s differs from %s: mean %.2f levels, %ld pixels off by > %d (the "
                          "look changed: check it, then `make golden`)",
                          scenes[k], golden, mean_diff, far, GOLDEN_FAR_TOL);
        }
        ms_renderer_destroy(r);
        ms_scene_destroy(sc);
        free(h);
    }
}
END_TEST

/* A camera under flat water looking straight up sees the sky through
 * Snell's window, a disc of half-angle asin(1 / n) = 48.6 degrees, and the
 * floor mirrored by total internal reflection outside it: the window's
 * edge is measured where the image turns from the white sky to the dark
 * floor, along four directions. */
START_TEST(under_water_the_sky_shows_through_snells_window)
{
    REQUIRE_GL();
    make_tmpdir();
    static const unsigned char white[6][3] = {{255, 255, 255}, {255, 255, 255}, {255, 255, 255},
                                              {255, 255, 255}, {255, 255, 255}, {255, 255, 255}};
    char sky[300];
    snprintf(sky, sizeof sky, "%s/white", tmpdir);
    write_cubemap_dir(sky, white);
    ms_renderer_desc d = ms_renderer_desc_default();
    const int side = 256;
    d.width = d.height = side;
    d.caustics = 0;
    d.cubemap = sky;
    d.floor_color[0] = d.floor_color[1] = d.floor_color[2] = 0.1f;
    const float eye[3] = {0.5f, 0.5f, 0.1f}, target[3] = {0.5f, 0.5f, 0.25f}, up[3] = {0, 1, 0};
    memcpy(d.eye, eye, sizeof eye);
    memcpy(d.target, target, sizeof target);
    memcpy(d.up, up, sizeof up);
    d.fov = 120;
    float *h = field(N, 0.25f);
    ms_renderer *r = create_ok(&d);
    draw_ok(r, h, N);
    const unsigned char *px = ms_renderer_pixels(r, NULL, NULL);
    const double focal = 0.5 * side / tan(60 * 3.14159265358979 / 180); /* pixels */
    const double want = focal * tan(asin(1 / 1.333));
    const int dirs[4][2] = {{1, 0}, {-1, 0}, {0, 1}, {0, -1}};
    for (int k = 0; k < 4; ++k) {
        double inside = luma(px, (size_t)(side / 2) * side + side / 2), edge = -1;
        for (int q = 1; q < side / 2; ++q) {
            int x = side / 2 + dirs[k][0] * q, y = side / 2 + dirs[k][1] * q;
            if (luma(px, (size_t)y * side + (size_t)x) < 0.5 * inside) {
                edge = q;
                break;
            }
        }
        ck_assert_msg(fabs(edge - want) <= 3, "direction %d: the window ends at %g px, Snell: %g",
                      k, edge, want);
    }
    /* outside the window: the floor, mirrored, not the sky */
    double outside = luma(px, (size_t)(side / 2) * side + (size_t)(side / 2 + (int)want + 20));
    ck_assert_msg(outside < 120, "outside Snell's window luma %g: no total internal reflection",
                  outside);
    ms_renderer_destroy(r);
    free(h);
    remove_tmpdir();
}
END_TEST

/* The refracted grout lines of the floor in a top-down image: for each
 * dark column of the image's mean profile, the darkness-weighted centre of
 * the line in every row of the central band, fitted by a straight line;
 * *lines gets how many were found, the result is the largest distance
 * (pixels) of a row's centre from its line's fit. */
static double grout_line_residual(const unsigned char *px, int *lines)
{
    enum { LO = W / 8, HI = W - W / 8, HALF = 6 };
    double profile[W];
    for (int x = 0; x < W; ++x) {
        profile[x] = 0;
        for (int y = LO; y < HI; ++y)
            profile[x] += luma(px, (size_t)y * W + (size_t)x) / (HI - LO);
    }
    double mean = 0;
    for (int x = LO; x < HI; ++x)
        mean += profile[x] / (HI - LO);
    double worst = 0;
    *lines = 0;
    for (int xc = LO + HALF; xc < HI - HALF; ++xc) {
        int is_min = profile[xc] < mean - 2.0;
        for (int k = -HALF; k <= HALF; ++k)
            is_min &= k == 0 || profile[xc] < profile[xc + k] ||
                      (k > 0 && profile[xc] == profile[xc + k]);
        if (!is_min)
            continue;
        ++*lines;
        double ys[W], cs[W];
        int n = 0;
        for (int y = LO; y < HI; ++y) {
            double top = 0, sw = 0, sx = 0;
            for (int x = xc - HALF; x <= xc + HALF; ++x)
                top = fmax(top, luma(px, (size_t)y * W + (size_t)x));
            for (int x = xc - HALF; x <= xc + HALF; ++x) {
                double w = top - luma(px, (size_t)y * W + (size_t)x);
                sw += w, sx += w * x;
            }
            if (sw > 0)
                ys[n] = y, cs[n++] = sx / sw;
        }
        double my = 0, mc = 0, syy = 0, syc = 0;
        for (int i = 0; i < n; ++i)
            my += ys[i] / n, mc += cs[i] / n;
        for (int i = 0; i < n; ++i)
            syy += (ys[i] - my) * (ys[i] - my), syc += (ys[i] - my) * (cs[i] - mc);
        const double b = syc / syy;
        for (int i = 0; i < n; ++i)
            worst = fmax(worst, fabs(cs[i] - (mc + b * (ys[i] - my))));
    }
    return worst;
}

START_TEST(refracted_tile_edges_are_straight_lines)
{
    REQUIRE_GL();
    /* still water, and water tilted as one plane (a constant gradient):
     * the refracted floor's grout lines stay straight, with the full mesh
     * and with a vertex every 4 cells (the shading normal of the normal
     * map, which must not show the mesh's triangles). Measured: 0.44 pixel
     * here (the centre of a blurred 7-level grout line, row by row), 2.9
     * for water bent as 0.5 (x - 0.5) (y - 0.5)^2, whose lines curve */
    float *h = field(N, 0.25f);
    for (int tilted = 0; tilted < 2; ++tilted) {
        for (int j = 0; j < N; ++j)
            for (int i = 0; i < N; ++i)
                h[j * N + i] = 0.25f + (float)tilted * 0.02f * (((float)i + 0.5f) / N - 0.5f);
        for (int step = 1; step <= 4; step += 3) {
            ms_renderer_desc d = top_down("water");
            d.caustics = 0;
            d.tile_size = 0.2f; /* about 27 pixels a tile, grout 3 pixels wide */
            d.mesh_step = step;
            unsigned char *px = render(&d, h, N);
            int lines = 0;
            double off = grout_line_residual(px, &lines);
            ck_assert_msg(lines >= 3, "%d grout lines found (tilted %d, step %d)", lines, tilted,
                          step);
            ck_assert_msg(off < 0.75,
                          "a refracted grout line leaves its straight fit by %.2f pixels "
                          "(tilted %d, step %d, %d lines)",
                          off, tilted, step, lines);
            free(px);
        }
    }
    free(h);
}
END_TEST

/* Where the liquid is dry (depth under MS_RENDER_DRY_DEPTH)
 * nothing of it is drawn, so the floor is seen directly. An all-dry field
 * (half a dry depth everywhere) draws the same bytes with the clear water
 * shader and the opaque white milk shader (any sheet of milk would whiten
 * the floor: 128 levels before the fix); a field dry on its left half and
 * 25 cm deep on its right draws the left half as the all-dry field does,
 * and the right half as liquid. */
START_TEST(a_dry_floor_is_seen_directly)
{
    REQUIRE_GL();
    /* dry but not exactly 0: a sheet at the floor's own depth would hide
     * behind the floor (drawn after it, GL_LEQUAL), one half a dry depth
     * above it shows */
    const float damp = 0.5f * MS_RENDER_DRY_DEPTH;
    float *dry = field(N, damp), *half = field(N, damp);
    for (int j = 0; j < N; ++j)
        for (int i = N / 2; i < N; ++i)
            half[j * N + i] = 0.25f;
    const char *const shaders[2] = {"water", "milk"};
    unsigned char *bare[2];
    for (int s = 0; s < 2; ++s) {
        ms_renderer_desc d = top_down(shaders[s]);
        bare[s] = render(&d, dry, N);
    }
    int shader_diff = box_max_abs_diff(bare[0], bare[1], 0, 0, W, W);
    ck_assert_msg(shader_diff == 0, "a dry pool's picture depends on the shader by %d levels",
                  shader_diff);
    /* the left half's floor (x < 0.45 m at the floor, clear of the step
     * between the dry and the wet cell centres at x = 0.49, 0.51 m), the
     * right half's water surface */
    const int x_dry = W / 2 - 12, x_wet = W / 2 + 12;
    for (int s = 0; s < 2; ++s) {
        ms_renderer_desc d = top_down(shaders[s]);
        unsigned char *px = render(&d, half, N);
        int left = box_max_abs_diff(px, bare[s], 6, 6, x_dry, W - 6);
        double right = box_mean_abs_diff(px, bare[s], x_wet, 6, W - 6, W - 6);
        ck_assert_msg(left == 0, "%s: the dry half differs from the bare floor by %d levels",
                      shaders[s], left);
        ck_assert_msg(right > 5, "%s: the wet half looks like the bare floor (%g levels)",
                      shaders[s], right);
        free(px);
    }
    free(bare[0]);
    free(bare[1]);
    free(dry);
    free(half);
}
END_TEST

static Suite *render_suite(void)
{
    Suite *s = suite_create("render");
    TCase *tc = tcase_create("render");
    tcase_set_timeout(tc, 120);
    tcase_add_test(tc, a_scene_gives_the_desc_of_its_render_section);
    tcase_add_test(tc, bad_descs_are_refused_with_the_value);
#if !MS_HAVE_GL
    tcase_add_test(tc, without_osmesa_create_says_so);
#endif
    tcase_add_test(tc, flat_water_reflects_the_fresnel_share_of_the_sky);
    tcase_add_test(tc, a_bump_changes_the_image_where_it_is_only);
    tcase_add_test(tc, milk_hides_the_floor_that_water_shows);
    tcase_add_test(tc, caustics_brighten_the_floor_under_a_lens);
    tcase_add_test(tc, the_same_field_gives_the_same_bytes_for_any_thread_count);
    tcase_add_test(tc, png_round_trips);
    tcase_add_test(tc, cubemaps_load_from_a_directory_or_a_strip);
    tcase_add_test(tc, bad_fields_and_shaders_are_refused);
    tcase_add_test(tc, obstacles_and_the_glass_are_drawn_with_their_shapes);
    tcase_add_test(tc, a_shader_that_does_not_compile_is_refused_with_its_log);
    tcase_add_test(tc, a_coarser_mesh_keeps_the_fields_normals);
    tcase_add_test(tc, refracted_tile_edges_are_straight_lines);
    tcase_add_test(tc, a_dry_floor_is_seen_directly);
    tcase_add_test(tc, floating_discs_are_drawn_on_the_surface);
    tcase_add_test(tc, the_shipped_scenes_render_their_golden_pictures);
    tcase_add_test(tc, draw_renders_the_sims_field_with_its_floaters_and_boat);
    tcase_add_test(tc, moving_the_camera_is_creating_with_it);
    tcase_add_test(tc, renderers_in_two_threads_draw_what_one_draws);
    tcase_add_test(tc, a_scene_renders_and_every_shader_draws);
    tcase_add_test(tc, each_backend_draws_the_same_picture);
    tcase_add_test(tc, each_shader_shows_its_ripples_unclipped);
    tcase_add_test(tc, under_water_the_sky_shows_through_snells_window);
    suite_add_tcase(s, tc);
    return s;
}

int main(void)
{
    return ms_test_run(render_suite());
}
