/* Shader plugins: each loads, describes itself, declares the passes it
 * needs consistently with its source, sets exactly its own uniforms, and
 * refuses bad parameters naming the key. With OSMesa, each program
 * compiles, links and draws a surface of the expected character (milk
 * bright, oil dark, water blue, honey amber). */
#include <check.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/core_internal.h"
#include "modesplit/plugin.h"
#include "plugin/plugin_internal.h"
#include "support.h"

#if defined(__SANITIZE_ADDRESS__)
#include <sanitizer/lsan_interface.h>
/* Mesa's OSMesa keeps the framebuffer it makes for a buffer after the
 * context is destroyed: not ours to report. */
#define MESA_LEAKS_BEGIN() __lsan_disable()
#define MESA_LEAKS_END() __lsan_enable()
#else
#define MESA_LEAKS_BEGIN() ((void)0)
#define MESA_LEAKS_END() ((void)0)
#endif

#if MS_HAVE_OSMESA
#define GL_GLEXT_PROTOTYPES 1
#include <GL/osmesa.h>
#include <GL/gl.h>
#include <GL/glext.h>
#endif

static const char *const shaders[] = {"water", "milk", "oil", "honey"};
#define N_SHADERS 4

/* The uniforms the renderer provides (plugin.h's contract). */
static const char *const contract[] = {"ms_eye",
                                       "ms_light_dir",
                                       "ms_light_color",
                                       "ms_time",
                                       "ms_viewport",
                                       "ms_env",
                                       "ms_floor_z",
                                       "ms_pool",
                                       "ms_caustics",
                                       "ms_normal_map",
                                       "ms_field",
                                       "ms_caustics_walls",
                                       "ms_foam",
                                       "ms_foam_field",
                                       "ms_foam_on",
                                       "ms_pool_depth",
                                       "ms_caustics_wall_rows",
                                       "ms_side",
                                       "ms_env_refracted_eye",
                                       NULL};

/* Records the names set_uniforms sets. */
typedef struct recorder {
    char names[32][64];
    int n;
    int bad_values;
} recorder;

static void record(recorder *r, const char *name, const float *v, int n)
{
    if (r->n < 32)
        snprintf(r->names[r->n++], sizeof r->names[0], "%s", name);
    for (int i = 0; i < n; ++i)
        r->bad_values += !isfinite(v[i]);
}
static void rec_float(void *ctx, const char *name, float v)
{
    record(ctx, name, &v, 1);
}
static void rec_vec3(void *ctx, const char *name, float x, float y, float z)
{
    record(ctx, name, (float[3]){x, y, z}, 3);
}
static void rec_int(void *ctx, const char *name, int v)
{
    float f = (float)v;
    record(ctx, name, &f, 1);
}
static void rec_vec4(void *ctx, const char *name, float x, float y, float z, float w)
{
    record(ctx, name, (float[4]){x, y, z, w}, 4);
}

/* Does the GLSL source declare "uniform <type> name;"? */
static int declares(const char *src, const char *name)
{
    for (const char *p = src; (p = strstr(p, "uniform ")); ++p) {
        const char *sp = strchr(p + 8, ' ');
        if (sp && strncmp(sp + 1, name, strlen(name)) == 0 && sp[1 + strlen(name)] == ';')
            return 1;
    }
    return 0;
}

static int uses(const ms_shader_vtable *vt, const char *name)
{
    return declares(vt->vertex_source, name) || declares(vt->fragment_source, name);
}

START_TEST(each_shader_loads_and_describes_itself)
{
    int found = 0;
    for (int i = 0; i < ms_plugin_count(); ++i) {
        ms_plugin_description d = ms_plugin_description_init();
        ck_assert_int_eq(ms_plugin_describe(i, &d), MS_OK);
        for (int k = 0; k < N_SHADERS; ++k)
            if (strcmp(d.name, shaders[k]) == 0) {
                ck_assert_str_eq(d.kind, "shader");
                ck_assert_str_eq(d.version, "1.0");
                ck_assert_int_gt(strlen(d.description), 20);
                ck_assert_ptr_nonnull(strstr(d.path, "shader_"));
                ++found;
            }
    }
    ck_assert_int_eq(found, N_SHADERS);
}
END_TEST

START_TEST(passes_match_what_each_shader_is)
{
    const unsigned want[N_SHADERS] = {
        MS_SHADER_NEEDS_REFLECTION | MS_SHADER_NEEDS_REFRACTION | MS_SHADER_NEEDS_CAUSTICS,
        MS_SHADER_NEEDS_REFLECTION, /* milk: opaque, no refraction or caustics */
        MS_SHADER_NEEDS_REFLECTION, /* oil: opaque */
        MS_SHADER_NEEDS_REFLECTION | MS_SHADER_NEEDS_REFRACTION};
    for (int k = 0; k < N_SHADERS; ++k) {
        ms_shader_instance in;
        ck_assert_int_eq(ms_shader_instance_create(shaders[k], NULL, &in), MS_OK);
        const ms_shader_vtable *vt = in.vt;
        ck_assert_uint_eq(vt->passes, want[k]);
        ck_assert_int_eq(strncmp(vt->vertex_source, "#version 120\n", 13), 0);
        ck_assert_int_eq(strncmp(vt->fragment_source, "#version 120\n", 13), 0);
        ck_assert_ptr_nonnull(strstr(vt->vertex_source, "gl_Position"));
        ck_assert_ptr_nonnull(strstr(vt->fragment_source, "gl_FragColor"));
        /* a texture the renderer only makes for a pass the flags ask for */
        ck_assert_int_eq(uses(vt, "ms_caustics"), (vt->passes & MS_SHADER_NEEDS_CAUSTICS) != 0);
        if (uses(vt, "ms_env"))
            ck_assert(vt->passes & (MS_SHADER_NEEDS_REFLECTION | MS_SHADER_NEEDS_REFRACTION));
        /* refraction means a ray refracted by Snell's law */
        ck_assert_int_eq(strstr(vt->fragment_source, "refract(") != NULL,
                         (vt->passes & MS_SHADER_NEEDS_REFRACTION) != 0);
        ms_shader_instance_destroy(&in);
    }
}
END_TEST

START_TEST(each_shader_sets_exactly_its_own_uniforms)
{
    for (int k = 0; k < N_SHADERS; ++k) {
        ms_shader_instance in;
        ck_assert_int_eq(ms_shader_instance_create(shaders[k], NULL, &in), MS_OK);
        recorder r = {.n = 0};
        ms_shader_uniforms u = {sizeof u, &r, rec_float, rec_vec3, rec_int, rec_vec4};
        in.vt->set_uniforms(in.self, &u);
        ck_assert_int_gt(r.n, 1);
        ck_assert_int_eq(r.bad_values, 0);
        for (int i = 0; i < r.n; ++i) {
            ck_assert_msg(uses(in.vt, r.names[i]), "%s sets %s, which it does not declare",
                          shaders[k], r.names[i]);
            ck_assert_msg(strncmp(r.names[i], "ms_", 3) != 0, "%s sets the renderer's %s",
                          shaders[k], r.names[i]);
        }
        /* every uniform it declares is its own (and set) or the renderer's */
        const char *src = in.vt->fragment_source;
        for (const char *p = src; (p = strstr(p, "uniform ")); ++p) {
            const char *sp = strchr(p + 8, ' ') + 1, *semi = strchr(sp, ';');
            char name[64];
            snprintf(name, sizeof name, "%.*s", (int)(semi - sp), sp);
            int known = 0;
            for (int i = 0; contract[i]; ++i)
                known |= strcmp(contract[i], name) == 0;
            for (int i = 0; i < r.n; ++i)
                known |= strcmp(r.names[i], name) == 0;
            ck_assert_msg(known, "%s declares %s: neither the renderer's nor set by it", shaders[k],
                          name);
        }
        ms_shader_instance_destroy(&in);
    }
}
END_TEST

START_TEST(bad_parameters_name_the_key)
{
    ms_shader_instance in;
    MS_ASSERT_REFUSED(ms_shader_instance_create("water", "{\"color\": [2, 0, 0]}", &in),
                      MS_ERR_INVALID_ARGUMENT, "shader water: color[0] 2");
    MS_ASSERT_REFUSED(ms_shader_instance_create("water", "{\"ior\": 0.5}", &in),
                      MS_ERR_INVALID_ARGUMENT, "ior 0.5");
    MS_ASSERT_REFUSED(ms_shader_instance_create("milk", "{\"colour\": [1, 1, 1]}", &in),
                      MS_ERR_INVALID_ARGUMENT, "unknown key \"colour\"");
    MS_ASSERT_REFUSED(ms_shader_instance_create("honey", "{\"density\": -1}", &in),
                      MS_ERR_INVALID_ARGUMENT, "density -1 1/m");
    MS_ASSERT_REFUSED(ms_shader_instance_create("oil", "{\"shininess\": \"high\"}", &in),
                      MS_ERR_PARSE, "shininess must be a number");
    MS_ASSERT_REFUSED(ms_shader_instance_create("lava", NULL, &in), MS_ERR_PLUGIN,
                      "available shaders: honey, milk, oil, water");
    MS_ASSERT_REFUSED(ms_shader_instance_create("sphere", NULL, &in), MS_ERR_PLUGIN,
                      "is a shape plugin, not a shader");
    ck_assert_int_eq(ms_shader_instance_create("oil",
                                               "{\"color\": [0.1, 0.1, 0.1], "
                                               "\"shininess\": 50}",
                                               &in),
                     MS_OK);
    ms_shader_instance_destroy(&in);
}
END_TEST

#if MS_HAVE_OSMESA
typedef struct gl_ctx {
    GLuint prog;
} gl_ctx;

static void gl_float(void *c, const char *name, float v)
{
    glUniform1f(glGetUniformLocation(((gl_ctx *)c)->prog, name), v);
}
static void gl_vec3(void *c, const char *name, float x, float y, float z)
{
    glUniform3f(glGetUniformLocation(((gl_ctx *)c)->prog, name), x, y, z);
}
static void gl_int(void *c, const char *name, int v)
{
    glUniform1i(glGetUniformLocation(((gl_ctx *)c)->prog, name), v);
}
static void gl_vec4(void *c, const char *name, float x, float y, float z, float w)
{
    glUniform4f(glGetUniformLocation(((gl_ctx *)c)->prog, name), x, y, z, w);
}

static GLuint compile(GLenum type, const char *src, const char *what)
{
    GLuint s = glCreateShader(type);
    glShaderSource(s, 1, &src, NULL);
    glCompileShader(s);
    GLint ok = 0;
    glGetShaderiv(s, GL_COMPILE_STATUS, &ok);
    char log[2048] = "";
    glGetShaderInfoLog(s, sizeof log, NULL, log);
    ck_assert_msg(ok, "%s does not compile: %s", what, log);
    return s;
}

/* Draws the whole 32 x 32 viewport as a flat liquid surface at z = 0
 * seen from 2 m above, under a sky-blue environment and a light from the
 * side; returns the mean colour (0..1). */
static void draw(const char *name, float rgb[3])
{
    enum { W = 32, H = 32 };
    static unsigned char pixels[W * H * 4];
    MESA_LEAKS_BEGIN();
    OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 16, 0, 0, NULL);
    int current = ctx && OSMesaMakeCurrent(ctx, pixels, GL_UNSIGNED_BYTE, W, H);
    MESA_LEAKS_END();
    ck_assert_ptr_nonnull(ctx);
    ck_assert(current);
    ms_shader_instance in;
    ck_assert_int_eq(ms_shader_instance_create(name, NULL, &in), MS_OK);
    GLuint vs = compile(GL_VERTEX_SHADER, in.vt->vertex_source, name);
    GLuint fs = compile(GL_FRAGMENT_SHADER, in.vt->fragment_source, name);
    gl_ctx g = {glCreateProgram()};
    glAttachShader(g.prog, vs);
    glAttachShader(g.prog, fs);
    glLinkProgram(g.prog);
    GLint ok = 0;
    glGetProgramiv(g.prog, GL_LINK_STATUS, &ok);
    char log[2048] = "";
    glGetProgramInfoLog(g.prog, sizeof log, NULL, log);
    ck_assert_msg(ok, "%s does not link: %s", name, log);
    glUseProgram(g.prog);
    /* the environment: a sky-blue cubemap (unit 0), caustics map of 1 (unit 1) */
    GLuint tex[2];
    glGenTextures(2, tex);
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_CUBE_MAP, tex[0]);
    const unsigned char sky[3] = {128, 160, 210};
    for (int f = 0; f < 6; ++f)
        glTexImage2D(GL_TEXTURE_CUBE_MAP_POSITIVE_X + (GLenum)f, 0, GL_RGB, 1, 1, 0, GL_RGB,
                     GL_UNSIGNED_BYTE, sky);
    glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glActiveTexture(GL_TEXTURE1);
    glBindTexture(GL_TEXTURE_2D, tex[1]);
    const unsigned char one = 255;
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_LUMINANCE, 1, 1, 0, GL_LUMINANCE, GL_UNSIGNED_BYTE, &one);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    /* a flat surface: a gradient of 0 everywhere (unit 2) */
    GLuint flat;
    glGenTextures(1, &flat);
    glActiveTexture(GL_TEXTURE2);
    glBindTexture(GL_TEXTURE_2D, flat);
    const float zero[2] = {0, 0};
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RG32F, 1, 1, 0, GL_RG, GL_FLOAT, zero);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glActiveTexture(GL_TEXTURE0);
    ms_shader_uniforms u = {sizeof u, &g, gl_float, gl_vec3, gl_int, gl_vec4};
    u.set_int(&g, "ms_normal_map", 2);
    u.set_vec4(&g, "ms_field", -1, -1, 0.5f, 0.5f);
    u.set_vec3(&g, "ms_eye", 0, 0, 2);
    u.set_vec3(&g, "ms_light_dir", 0.6f, 0, 0.8f);
    u.set_vec3(&g, "ms_light_color", 1, 1, 1);
    u.set_float(&g, "ms_time", 0);
    u.set_vec4(&g, "ms_viewport", W, H, 1.0f / W, 1.0f / H);
    u.set_int(&g, "ms_env", 0);
    u.set_vec3(&g, "ms_env_refracted_eye", 0, 0, 2.5f);
    u.set_int(&g, "ms_caustics", 1);
    u.set_int(&g, "ms_caustics_walls", 1); /* not read: the walls not traced */
    u.set_int(&g, "ms_foam", 1);           /* a 2D texture; no foam */
    u.set_float(&g, "ms_foam_on", 0);
    u.set_vec4(&g, "ms_foam_field", -1, -1, 0.5f, 0.5f);
    u.set_float(&g, "ms_pool_depth", 0);
    u.set_float(&g, "ms_caustics_wall_rows", 0);
    u.set_float(&g, "ms_floor_z", -0.5f);
    u.set_vec4(&g, "ms_pool", -1, -1, 2, 2);
    in.vt->set_uniforms(in.self, &u);
    glClearColor(1, 0, 1, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    glBegin(GL_QUADS); /* world = clip space here: the identity matrices */
    glNormal3f(0, 0, 1);
    glVertex3f(-1, -1, 0);
    glVertex3f(1, -1, 0);
    glVertex3f(1, 1, 0);
    glVertex3f(-1, 1, 0);
    glEnd();
    glFinish();
    ck_assert_int_eq(glGetError(), GL_NO_ERROR);
    double sum[3] = {0, 0, 0};
    for (int i = 0; i < W * H; ++i)
        for (int c = 0; c < 3; ++c)
            sum[c] += pixels[4 * i + c] / 255.0;
    for (int c = 0; c < 3; ++c)
        rgb[c] = (float)(sum[c] / (W * H));
    glDeleteTextures(2, tex);
    glDeleteTextures(1, &flat);
    glDeleteProgram(g.prog);
    glDeleteShader(vs);
    glDeleteShader(fs);
    ms_shader_instance_destroy(&in);
    OSMesaMakeCurrent(NULL, NULL, GL_UNSIGNED_BYTE, 0, 0);
    OSMesaDestroyContext(ctx);
}

START_TEST(each_shader_compiles_and_draws_its_liquid)
{
    float c[N_SHADERS][3];
    for (int k = 0; k < N_SHADERS; ++k) {
        draw(shaders[k], c[k]);
        /* drawn everywhere: no magenta clear colour left */
        ck_assert_msg(!(c[k][0] > 0.95f && c[k][1] < 0.05f), "%s drew nothing", shaders[k]);
    }
    float lum[N_SHADERS];
    for (int k = 0; k < N_SHADERS; ++k)
        lum[k] = 0.3f * c[k][0] + 0.59f * c[k][1] + 0.11f * c[k][2];
    ck_assert_msg(c[0][2] > c[0][0], "water is not blue: %g %g %g", c[0][0], c[0][1], c[0][2]);
    ck_assert_msg(lum[1] > 0.6f, "milk is not bright: %g", lum[1]);
    ck_assert_msg(lum[2] < 0.2f, "oil is not dark: %g", lum[2]);
    ck_assert_msg(c[3][0] > c[3][1] && c[3][1] > c[3][2], "honey is not amber: %g %g %g", c[3][0],
                  c[3][1], c[3][2]);
    ck_assert_msg(lum[1] > lum[0] && lum[0] > lum[2], "luma milk %g, water %g, oil %g", lum[1],
                  lum[0], lum[2]);
}
END_TEST
#else
START_TEST(each_shader_compiles_and_draws_its_liquid)
{
    MS_SKIP("built without OSMesa: this case drives an OSMesa context directly (the "
            "renderer's EGL path draws every shader in test_render)");
}
END_TEST
#endif

static Suite *shaders_suite(void)
{
    Suite *s = suite_create("shaders");
    TCase *tc = tcase_create("shaders");
    tcase_set_timeout(tc, 60);
    tcase_add_test(tc, each_shader_loads_and_describes_itself);
    tcase_add_test(tc, passes_match_what_each_shader_is);
    tcase_add_test(tc, each_shader_sets_exactly_its_own_uniforms);
    tcase_add_test(tc, bad_parameters_name_the_key);
    tcase_add_test(tc, each_shader_compiles_and_draws_its_liquid);
    suite_add_tcase(s, tc);
    return s;
}

int main(void)
{
    return ms_test_run(shaders_suite());
}
