/* The "render" section of the scene schema: image size, shader, cubemap,
 * caustics, camera and GL backend (the table of data/scenes/README.md;
 * keep both in step), read into the scene's ms_renderer_desc over
 * ms_renderer_desc_default(), whose defaults it takes. The ranges are the
 * renderer's (ms_renderer_desc_check_fields): the section reads each key's
 * type, then has the desc checked and names a refusal at the key that set
 * the field, with the renderer's sentence. */
#include <float.h>
#include <limits.h>
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "core/core_internal.h"
#include "modesplit/plugin.h"
#include "modesplit/render.h"
#include "plugin/plugin_internal.h"
#include "render/render_internal.h"
#include "scene/reader.h"
#include "scene/scene_internal.h"
#include "scene/sections.h"

/* Any finite number, any int: the renderer's check has the ranges. */
#define ANY_F FLT_MAX
#define ANY_I INT_MAX

/* Is there at least one plugin of this kind? */
static int have_plugins_of_kind(const char *kind)
{
    int n = ms_plugin_count();
    for (int i = 0; i < n; ++i) {
        ms_plugin_description d = ms_plugin_description_init();
        if (ms_plugin_describe(i, &d) == MS_OK && strcmp(d.kind, kind) == 0)
            return 1;
    }
    return 0;
}

/* render.shader_params: the shader's own keys, as compact JSON text, made
 * into an instance once here (when the plugin is found) so that `check`
 * refuses what the renderer would, with the shader's sentence. */
static ms_status read_shader_params(ms_scene_ctx *c, json_t *o, const char *name, char **out)
{
    json_t *p;
    MS_TRY(ms_scene_get_object(c, o, "shader_params", &p));
    if (!p)
        return MS_OK;
    *out = ms_json_text(p, JSON_COMPACT | JSON_SORT_KEYS);
    if (!*out)
        return ms_fail(MS_ERR_OUT_OF_MEMORY, "scene: out of memory for render.shader_params");
    const ms_plugin_rec *rec;
    if (!have_plugins_of_kind("shader") ||
        ms_plugin_find("scene", name, MS_PLUGIN_SHADER, &rec) != MS_OK)
        return MS_OK; /* the renderer reports the name when it loads it */
    ms_shader_instance in;
    ms_status st = ms_shader_instance_create(name, *out, &in);
    if (st != MS_OK) {
        char why[512];
        snprintf(why, sizeof why, "%s", ms_last_error());
        ms_scene_push_key(c, "shader_params");
        return ms_scene_fail(c, st, "%s", why);
    }
    ms_shader_instance_destroy(&in);
    return MS_OK;
}

static ms_status check_shader(ms_scene_ctx *c, const char *name)
{
    ms_status st = MS_OK;
    const ms_plugin_rec *rec;
    ms_scene_push_key(c, "shader");
    if (!name[0] || strlen(name) > 64)
        st = ms_scene_fail(c, MS_ERR_INVALID_ARGUMENT,
                           "\"%.64s\" is not a shader name; allowed: 1 to 64 characters", name);
    /* Checked against the plugin registry, which lists the available
     * shaders in its sentence. A build without any shader plugin cannot
     * tell; the renderer then reports the name when it loads it. */
    else if (have_plugins_of_kind("shader") &&
             ms_plugin_find("scene", name, MS_PLUGIN_SHADER, &rec) != MS_OK)
        st = ms_scene_fail(c, MS_ERR_INVALID_ARGUMENT, "\"%.64s\" is not a shader plugin (%s)",
                           name, ms_last_error());
    ms_scene_pop(c);
    return st;
}

/* The renderer's desc of the scene, over ms_renderer_desc_default(): the
 * pool is the domain (floor at domain.min z, the still water at the
 * scene's level, the rim a little above it), and without a render section
 * the camera looks at the domain's centre from the -y side, no caustics. */
static void pool_and_camera(ms_scene *sc)
{
    ms_renderer_desc *d = &sc->render;
    const float *lo = sc->domain_min, *hi = sc->domain_max;
    float ext_xy = MS_MIN(hi[0] - lo[0], hi[1] - lo[1]);
    d->pool_min[0] = lo[0];
    d->pool_min[1] = lo[1];
    d->pool_min[2] = lo[2];
    d->pool_max[0] = hi[0];
    d->pool_max[1] = hi[1];
    d->water_level = lo[2] + sc->level;
    /* the rim a little above still water (so the walls hide little of
     * it), within the domain */
    d->pool_max[2] = MS_MIN(hi[2], d->water_level + 0.05f * ext_xy);
    if (!(d->pool_max[2] > lo[2]))
        d->pool_max[2] = hi[2];
    /* A fill that rises above that rim (a dam break, Fig. 4c) is liquid
     * that runs up the walls: the walls then go up to the domain's top,
     * the highest the particles can reach, so the liquid stays inside the
     * pool and is not drawn over the deck. */
    for (int i = 0; i < sc->nfill; ++i)
        if (sc->has_volume && sc->fill_hi[i][2] > d->pool_max[2])
            d->pool_max[2] = hi[2];
    if (sc->has_render)
        return;
    float ext = 0;
    for (int k = 0; k < 3; ++k) {
        d->target[k] = 0.5f * (lo[k] + hi[k]);
        ext = MS_MAX(ext, hi[k] - lo[k]);
    }
    d->eye[0] = d->target[0];
    d->eye[1] = d->target[1] - 1.2f * ext;
    d->eye[2] = d->target[2] + 1.0f * ext;
    d->caustics = 0;
}

static ms_status read_render(ms_scene_ctx *c, json_t *root, ms_scene *sc, const char *dir)
{
    static const char *const keys[] = {"width",         "height",  "shader",
                                       "shader_params", "cubemap", "caustics",
                                       "camera",        "backend", NULL};
    static const char *const ckeys[] = {"resolution", "intensity", "light", NULL};
    static const char *const camkeys[] = {"eye", "target", "up", "fov", NULL};
    static const char *const backends[] = {"auto", "osmesa", "egl", NULL};
    ms_renderer_desc *r = &sc->render;
    const float light[3] = {r->light_dir[0], r->light_dir[1], r->light_dir[2]};
    const float up[3] = {r->up[0], r->up[1], r->up[2]};
    json_t *o, *caus, *cam;
    long w, h;
    int backend;
    const char *shader, *cubemap;
    MS_TRY(ms_scene_get_object(c, root, "render", &o));
    if (!o)
        return MS_OK;
    sc->has_render = 1;
    ms_scene_push_key(c, "render");
    MS_TRY(ms_scene_check_keys(c, o, keys));
    MS_TRY(ms_scene_get_int(c, o, "width", r->width, -ANY_I, ANY_I, &w));
    MS_TRY(ms_scene_get_int(c, o, "height", r->height, -ANY_I, ANY_I, &h));
    r->width = (int)w;
    r->height = (int)h;
    MS_TRY(ms_scene_get_string(c, o, "shader", r->shader, &shader));
    MS_TRY(check_shader(c, shader));
    MS_TRY(ms_scene_get_string(c, o, "cubemap", r->cubemap, &cubemap));
    MS_TRY(ms_scene_get_enum(c, o, "backend", backends, 0, &backend));
    r->backend = backends[backend];
    sc->render_shader = ms_strdup(shader);
    MS_TRY(read_shader_params(c, o, shader, &sc->render_shader_params));
    r->shader_params = sc->render_shader_params;
    if (strcmp(cubemap, "builtin") == 0) {
        sc->render_cubemap = ms_strdup(cubemap);
    } else {
        size_t n = strlen(dir) + strlen(cubemap) + 2;
        sc->render_cubemap = ms_alloc(n);
        if (sc->render_cubemap)
            snprintf(sc->render_cubemap, n, "%s%s", cubemap[0] == '/' ? "" : dir, cubemap);
        /* what the renderer will require of the path's files (kind and
         * faces, not yet their pixels), so check refuses what run refuses;
         * absolute paths are allowed (docs/scenes.md says why) */
        if (sc->render_cubemap &&
            (!cubemap[0] || ms_cubemap_check_path(sc->render_cubemap) != MS_OK)) {
            /* a copy (the refusal below rewrites ms_last_error), without
             * the renderer's "render: cubemap " since the key names it */
            const char *e = ms_last_error(), *head = "render: cubemap ";
            if (!strncmp(e, head, strlen(head)))
                e += strlen(head);
            char why[600];
            snprintf(why, sizeof why, "%s", cubemap[0] ? e : "\"\" is an empty name");
            ms_scene_push_key(c, "cubemap");
            return ms_scene_fail(c, MS_ERR_INVALID_ARGUMENT,
                                 "%s (a relative path is relative to the scene file)", why);
        }
    }
    if (!sc->render_shader || !sc->render_cubemap)
        return ms_fail(MS_ERR_OUT_OF_MEMORY, "scene: out of memory for the render section");
    r->shader = sc->render_shader;
    r->cubemap = sc->render_cubemap;
    MS_TRY(ms_scene_get_object(c, o, "caustics", &caus));
    r->caustics = caus != NULL;
    if (caus) {
        long res;
        ms_scene_push_key(c, "caustics");
        MS_TRY(ms_scene_check_keys(c, caus, ckeys));
        MS_TRY(
            ms_scene_get_int(c, caus, "resolution", r->caustics_resolution, -ANY_I, ANY_I, &res));
        r->caustics_resolution = (int)res;
        MS_TRY(ms_scene_get_float(c, caus, "intensity", r->caustics_intensity, -ANY_F, ANY_F, 0, "",
                                  &r->caustics_intensity));
        MS_TRY(ms_scene_get_vec(c, caus, "light", 3, light, -ANY_F, ANY_F, "", r->light_dir));
        ms_scene_pop(c);
    }
    /* camera: default looks at the domain's centre from the -y side, above */
    float ctr[3], ext = 0;
    for (int k = 0; k < 3; ++k) {
        ctr[k] = 0.5f * (sc->domain_min[k] + sc->domain_max[k]);
        ext = MS_MAX(ext, sc->domain_max[k] - sc->domain_min[k]);
    }
    float eye[3] = {ctr[0], ctr[1] - 1.2f * ext, ctr[2] + 1.0f * ext};
    memcpy(r->eye, eye, sizeof eye);
    memcpy(r->target, ctr, sizeof ctr);
    MS_TRY(ms_scene_get_object(c, o, "camera", &cam));
    if (cam) {
        ms_scene_push_key(c, "camera");
        MS_TRY(ms_scene_check_keys(c, cam, camkeys));
        MS_TRY(ms_scene_get_vec(c, cam, "eye", 3, eye, -ANY_F, ANY_F, "m", r->eye));
        MS_TRY(ms_scene_get_vec(c, cam, "target", 3, ctr, -ANY_F, ANY_F, "m", r->target));
        MS_TRY(ms_scene_get_vec(c, cam, "up", 3, up, -ANY_F, ANY_F, "", r->up));
        MS_TRY(ms_scene_get_float(c, cam, "fov", r->fov, -ANY_F, ANY_F, 0, "degrees", &r->fov));
        ms_scene_pop(c);
    }
    ms_scene_pop(c);
    return MS_OK;
}

/* A render desc field and the key under "render" that sets it (sub: the
 * object it is in, or NULL); a field of none (the pool, the still water
 * level) comes from the domain. */
static const struct {
    const char *field, *sub, *key;
} render_keys[] = {
    {"width", NULL, "width"},
    {"height", NULL, "height"},
    {"shader", NULL, "shader"},
    {"cubemap", NULL, "cubemap"},
    {"backend", NULL, "backend"},
    {"caustics_resolution", "caustics", "resolution"},
    {"caustics_intensity", "caustics", "intensity"},
    {"light_dir", "caustics", "light"},
    {"eye", "camera", "eye"},
    {"target", "camera", "target"},
    {"up", "camera", "up"},
    {"fov", "camera", "fov"},
};

/* ms_renderer_desc_check_fields of the scene's desc; a refusal named at
 * the key that set the field ("eye[1]" at camera.eye). */
static ms_status check_render(ms_scene_ctx *c, const ms_renderer_desc *r)
{
    ms_status st = ms_renderer_desc_check_fields(r);
    if (st == MS_OK)
        return MS_OK;
    char field[64], why[640];
    snprintf(field, sizeof field, "%s", ms_last_error_key());
    field[strcspn(field, "[")] = '\0';
    snprintf(why, sizeof why, "%s", ms_last_error());
    const int depth = c->depth;
    c->depth = 0;
    int found = 0;
    for (size_t i = 0; i < sizeof render_keys / sizeof render_keys[0] && !found; ++i)
        if (strcmp(render_keys[i].field, field) == 0) {
            ms_scene_push_key(c, "render");
            if (render_keys[i].sub)
                ms_scene_push_key(c, render_keys[i].sub);
            ms_scene_push_key(c, render_keys[i].key);
            found = 1;
        }
    if (!found)
        ms_scene_push_key(c, "domain");
    st = ms_scene_fail(c, st, "is refused: %s", why);
    c->depth = depth;
    return st;
}

ms_status ms_scene_read_render(ms_scene_ctx *c, json_t *root, ms_scene *sc, const char *dir)
{
    sc->render = ms_renderer_desc_default();
    MS_TRY(read_render(c, root, sc, dir));
    pool_and_camera(sc);
    MS_TRY(check_render(c, &sc->render));
    /* the light as a unit vector (checked not zero) */
    ms_renderer_desc *r = &sc->render;
    const double ln =
        sqrt((double)r->light_dir[0] * r->light_dir[0] + (double)r->light_dir[1] * r->light_dir[1] +
             (double)r->light_dir[2] * r->light_dir[2]);
    for (int k = 0; k < 3; ++k)
        r->light_dir[k] = (float)(r->light_dir[k] / ln);
    return MS_OK;
}
