/* The "render" section of the scene schema: image size, shader, cubemap,
 * caustics, camera and GL backend (the table of data/scenes/README.md;
 * keep both in step). */
#include <errno.h>
#include <stdio.h>
#include <string.h>
#include <sys/stat.h>

#include "core/core_internal.h"
#include "modesplit/plugin.h"
#include "modesplit/render.h"
#include "plugin/plugin_internal.h"
#include "scene/reader.h"
#include "scene/scene_internal.h"
#include "scene/sections.h"

#define BIG MS_SCENE_BIG

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

const char *const ms_scene_render_backends[] = {"auto", "osmesa", "egl", NULL};

ms_status ms_scene_read_render(ms_scene_ctx *c, json_t *root, ms_scene *sc, const char *dir)
{
    static const char *const keys[] = {"width",    "height", "shader",  "cubemap",
                                       "caustics", "camera", "backend", NULL};
    static const char *const ckeys[] = {"resolution", "intensity", "light", NULL};
    static const char *const camkeys[] = {"eye", "target", "up", "fov", NULL};
    static const float light[3] = {0.3f, 0.2f, -1.0f}, up[3] = {0, 0, 1};
    ms_scene_render *r = &sc->render;
    json_t *o, *caus, *cam;
    long w, h;
    const char *shader, *cubemap;
    MS_TRY(ms_scene_get_object(c, root, "render", &o));
    if (!o)
        return MS_OK;
    sc->has_render = 1;
    ms_scene_push_key(c, "render");
    MS_TRY(ms_scene_check_keys(c, o, keys));
    MS_TRY(ms_scene_get_int(c, o, "width", 950, 16, 8192, &w));
    MS_TRY(ms_scene_get_int(c, o, "height", 950, 16, 8192, &h));
    r->width = (int)w;
    r->height = (int)h;
    MS_TRY(ms_scene_get_string(c, o, "shader", "water", &shader));
    MS_TRY(check_shader(c, shader));
    MS_TRY(ms_scene_get_string(c, o, "cubemap", "builtin", &cubemap));
    MS_TRY(ms_scene_get_enum(c, o, "backend", ms_scene_render_backends, 0, &r->backend));
    r->shader = ms_strdup(shader);
    if (strcmp(cubemap, "builtin") == 0) {
        r->cubemap = ms_strdup(cubemap);
    } else {
        size_t n = strlen(dir) + strlen(cubemap) + 2;
        r->cubemap = ms_alloc(n);
        if (r->cubemap)
            snprintf(r->cubemap, n, "%s%s", cubemap[0] == '/' ? "" : dir, cubemap);
        /* what the renderer will require of the path's files (kind and
         * faces, not yet their pixels), so check refuses what run refuses;
         * absolute paths are allowed (docs/scenes.md says why) */
        if (r->cubemap && (!cubemap[0] || ms_cubemap_check_path(r->cubemap) != MS_OK)) {
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
    if (!r->shader || !r->cubemap)
        return ms_fail(MS_ERR_OUT_OF_MEMORY, "scene: out of memory for the render section");
    MS_TRY(ms_scene_get_object(c, o, "caustics", &caus));
    r->has_caustics = caus != NULL;
    memcpy(r->light_dir, light, sizeof light);
    r->caustics_resolution = 512;
    r->caustics_intensity = 1;
    if (caus) {
        long res;
        ms_scene_push_key(c, "caustics");
        MS_TRY(ms_scene_check_keys(c, caus, ckeys));
        MS_TRY(ms_scene_get_int(c, caus, "resolution", 512, 16, 4096, &res));
        r->caustics_resolution = (int)res;
        MS_TRY(ms_scene_get_float(c, caus, "intensity", 1, 0, 100, 0, "", &r->caustics_intensity));
        MS_TRY(ms_scene_get_vec(c, caus, "light", 3, light, -1e3, 1e3, "", r->light_dir));
        ms_scene_pop(c);
    }
    double ln =
        sqrt((double)r->light_dir[0] * r->light_dir[0] + (double)r->light_dir[1] * r->light_dir[1] +
             (double)r->light_dir[2] * r->light_dir[2]);
    if (!(ln > 1e-6)) {
        ms_scene_push_key(c, "caustics");
        ms_scene_push_key(c, "light");
        return ms_scene_fail(c, MS_ERR_INVALID_ARGUMENT,
                             "is the zero vector; allowed: a direction [x, y, z], not all 0");
    }
    for (int k = 0; k < 3; ++k)
        r->light_dir[k] = (float)(r->light_dir[k] / ln);
    /* camera: default looks at the domain's centre from the -y side, above */
    float ctr[3], ext = 0;
    for (int k = 0; k < 3; ++k) {
        ctr[k] = 0.5f * (sc->domain_min[k] + sc->domain_max[k]);
        ext = MS_MAX(ext, sc->domain_max[k] - sc->domain_min[k]);
    }
    float eye[3] = {ctr[0], ctr[1] - 1.2f * ext, ctr[2] + 1.0f * ext};
    memcpy(r->eye, eye, sizeof eye);
    memcpy(r->target, ctr, sizeof ctr);
    memcpy(r->up, up, sizeof up);
    r->fov = 45;
    MS_TRY(ms_scene_get_object(c, o, "camera", &cam));
    if (cam) {
        ms_scene_push_key(c, "camera");
        MS_TRY(ms_scene_check_keys(c, cam, camkeys));
        MS_TRY(ms_scene_get_vec(c, cam, "eye", 3, eye, -BIG, BIG, "m", r->eye));
        MS_TRY(ms_scene_get_vec(c, cam, "target", 3, ctr, -BIG, BIG, "m", r->target));
        MS_TRY(ms_scene_get_vec(c, cam, "up", 3, up, -1e3, 1e3, "", r->up));
        MS_TRY(ms_scene_get_float(c, cam, "fov", 45, 1, 179, 0, "degrees", &r->fov));
        double d = 0;
        for (int k = 0; k < 3; ++k)
            d += (double)(r->eye[k] - r->target[k]) * (r->eye[k] - r->target[k]);
        if (!(d > 1e-12)) {
            ms_scene_push_key(c, "target");
            return ms_scene_fail(c, MS_ERR_INVALID_ARGUMENT,
                                 "equals camera.eye; allowed: a point away from the eye");
        }
        ms_scene_pop(c);
    }
    ms_scene_pop(c);
    return MS_OK;
}
