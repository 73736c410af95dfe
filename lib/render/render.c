/* The renderer's public calls that need no GL: the desc, its defaults and
 * checks, the desc of a scene, the pixels, the PNG, the statistics. The GL
 * side (gl_*.c) exists only in a build with OSMesa; without it create
 * returns MS_ERR_UNSUPPORTED with a sentence saying so. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "core/core_internal.h"
#include "render/render_sizes.h"
#include "render/render_internal.h"
#include "scene/scene_internal.h"

#define PART "render"
#define MAX_FIELD_CELLS (1L << 24) /* 4096 x 4096 */

ms_renderer_desc ms_renderer_desc_default(void)
{
    ms_renderer_desc d = {
        .size = (uint32_t)sizeof(ms_renderer_desc),
        .width = 950,
        .height = 950,
        .shader = "water",
        .shader_params = NULL,
        .cubemap = "builtin",
        .caustics = 1,
        .caustics_resolution = 512,
        .caustics_intensity = 1.0f,
        .light_dir = {0.3f, 0.2f, -1.0f},
        .light_color = {1.0f, 1.0f, 1.0f},
        .ior = 1.333f,
        .eye = {0.5f, -0.7f, 1.25f},
        .target = {0.5f, 0.5f, 0.15f},
        .up = {0.0f, 0.0f, 1.0f},
        .fov = 45.0f,
        .pool_min = {0.0f, 0.0f, 0.0f},
        .pool_max = {1.0f, 1.0f, 0.3f},
        .water_level = 0.25f,
        .tile_size = 0.0f,
        .floor_color = {0.30f, 0.52f, 0.60f},
        .mesh_step = 0,
        .backend = "auto",
    };
    return d;
}

ms_status ms_renderer_desc_from_scene(const ms_scene *sc, ms_renderer_desc *out)
{
    ms_status st;
    if ((st = ms_check_not_null(PART, "scene", sc)) != MS_OK ||
        (st = ms_check_not_null(PART, "out", out)) != MS_OK)
        return st;
    size_t size = ms_struct_out(out, MS_SIZES_RENDERER_DESC, PART);
    if (!size)
        return MS_ERR_INVALID_ARGUMENT; /* the sentence is set */
    /* the scene made it from its render section (lib/scene/section_render.c) */
    ms_struct_write(out, &sc->render, size);
    return MS_OK;
}

ms_status ms_scene_renderer_desc(const ms_scene *sc, ms_renderer_desc *out)
{
    return ms_renderer_desc_from_scene(sc, out);
}

static double norm3(const float v[3])
{
    return sqrt((double)v[0] * v[0] + (double)v[1] * v[1] + (double)v[2] * v[2]);
}

static ms_status check_vec(const char *key, const float v[3], double lo, double hi,
                           const char *unit)
{
    static const char axis[3] = {'0', '1', '2'};
    for (int k = 0; k < 3; ++k) {
        char name[64];
        snprintf(name, sizeof name, "%s[%c]", key, axis[k]);
        ms_status st = ms_check_range(PART, name, v[k], lo, hi, unit);
        if (st != MS_OK)
            return st;
    }
    return MS_OK;
}

static ms_status check_camera(const float eye[3], const float target[3], const float up[3],
                              float fov)
{
    ms_status st;
    const double big = 1e6; /* m */
    if ((st = check_vec("eye", eye, -big, big, "m")) != MS_OK ||
        (st = check_vec("target", target, -big, big, "m")) != MS_OK ||
        (st = check_vec("up", up, -big, big, "")) != MS_OK ||
        (st = ms_check_range(PART, "fov", fov, 1, 179, "degrees")) != MS_OK)
        return st;
    float view[3], side[3];
    for (int k = 0; k < 3; ++k)
        view[k] = target[k] - eye[k];
    double lv = norm3(view);
    if (!(lv > 1e-9))
        return ms_fail_key(MS_ERR_INVALID_ARGUMENT, "target",
                           "render: target [%g, %g, %g] m equals eye; it must be away from the eye",
                           (double)target[0], (double)target[1], (double)target[2]);
    side[0] = view[1] * up[2] - view[2] * up[1];
    side[1] = view[2] * up[0] - view[0] * up[2];
    side[2] = view[0] * up[1] - view[1] * up[0];
    if (!(norm3(side) > 1e-6 * lv * norm3(up)) || !(norm3(up) > 0))
        return ms_fail_key(MS_ERR_INVALID_ARGUMENT, "up",
                           "render: up [%g, %g, %g] is zero or along the view direction; it must "
                           "point across it",
                           (double)up[0], (double)up[1], (double)up[2]);
    return MS_OK;
}

/* Every field's range (render_internal.h): the one owner of the desc's
 * ranges, which the scene's render section maps to its keys. Each refusal
 * names its field (ms_last_error_key). */
ms_status ms_renderer_desc_check_fields(const ms_renderer_desc *d)
{
    ms_status st;
    const double big = 1e6; /* m */
    if ((st = ms_check_int_range(PART, "width", d->width, 16, MS_RENDER_MAX_SIDE)) != MS_OK ||
        (st = ms_check_int_range(PART, "height", d->height, 16, MS_RENDER_MAX_SIDE)) != MS_OK)
        return st;
    if ((long)d->width * d->height > MS_RENDER_MAX_PIXELS)
        return ms_fail_key(MS_ERR_INVALID_ARGUMENT, "width",
                           "render: image %d x %d pixels is over %ld pixels", d->width, d->height,
                           MS_RENDER_MAX_PIXELS);
    if ((st = ms_check_not_null(PART, "shader", d->shader)) != MS_OK ||
        (st = ms_check_not_null(PART, "cubemap", d->cubemap)) != MS_OK)
        return st;
    if (!d->shader[0])
        return ms_fail_key(MS_ERR_INVALID_ARGUMENT, "shader",
                           "render: shader \"\" is empty; name a shader plugin (\"water\", "
                           "\"milk\", \"oil\")");
    if (d->backend && strcmp(d->backend, "auto") != 0 && strcmp(d->backend, "osmesa") != 0 &&
        strcmp(d->backend, "egl") != 0)
        return ms_fail_key(MS_ERR_INVALID_ARGUMENT, "backend",
                           "render: backend \"%.40s\" is unknown; allowed: \"auto\", \"osmesa\", "
                           "\"egl\"",
                           d->backend);
    if (!d->cubemap[0])
        return ms_fail_key(MS_ERR_INVALID_ARGUMENT, "cubemap",
                           "render: cubemap \"\" is empty; allowed: \"builtin\", a directory of "
                           "six PNG faces or one PNG strip");
    if ((st = ms_check_int_range(PART, "caustics", d->caustics, 0, 1)) != MS_OK ||
        (st = ms_check_int_range(PART, "caustics_resolution", d->caustics_resolution, 16,
                                 MS_RENDER_MAX_CAUSTICS)) != MS_OK ||
        (st = ms_check_range(PART, "caustics_intensity", d->caustics_intensity, 0, 100, "")) !=
            MS_OK ||
        (st = check_vec("light_dir", d->light_dir, -big, big, "")) != MS_OK ||
        (st = check_vec("light_color", d->light_color, 0, 100, "")) != MS_OK ||
        (st = ms_check_range(PART, "ior", d->ior, 1, 3, "")) != MS_OK ||
        (st = check_vec("pool_min", d->pool_min, -big, big, "m")) != MS_OK ||
        (st = check_vec("pool_max", d->pool_max, -big, big, "m")) != MS_OK ||
        (st = ms_check_range(PART, "tile_size", d->tile_size, 0, big, "m")) != MS_OK ||
        (st = check_vec("floor_color", d->floor_color, 0, 1, "")) != MS_OK ||
        (st = ms_check_int_range(PART, "mesh_step", d->mesh_step, 0, 64)) != MS_OK)
        return st;
    if (!(norm3(d->light_dir) > 1e-6))
        return ms_fail_key(MS_ERR_INVALID_ARGUMENT, "light_dir",
                           "render: light_dir [%g, %g, %g] is the zero vector; it must be a "
                           "direction",
                           (double)d->light_dir[0], (double)d->light_dir[1],
                           (double)d->light_dir[2]);
    for (int k = 0; k < 3; ++k)
        if (!(d->pool_max[k] > d->pool_min[k]))
            return ms_fail_key(MS_ERR_INVALID_ARGUMENT, "pool_max",
                               "render: pool_max[%d] %g m must be above pool_min[%d] %g m", k,
                               (double)d->pool_max[k], k, (double)d->pool_min[k]);
    if ((st = ms_check_range(PART, "water_level", d->water_level, d->pool_min[2], d->pool_max[2],
                             "m")) != MS_OK)
        return st;
    return check_camera(d->eye, d->target, d->up, d->fov);
}

#if MS_HAVE_GL
/* Texels per side of the builtin sky's faces: about half the image's
 * longer side (a face spans 90 degrees, the clouds are soft), a power of
 * two in [32, 512]. */
static int sky_size_for(int w, int h)
{
    int want = MS_MAX(w, h) / 2, n = 32;
    while (n < want && n < 512)
        n *= 2;
    return n;
}
#endif

ms_status ms_renderer_desc_check(const ms_renderer_desc *user)
{
    ms_renderer_desc d = ms_renderer_desc_default();
    ms_status st;
    if ((st = ms_struct_in(user, &d, MS_SIZES_RENDERER_DESC, PART)) != MS_OK ||
        (st = ms_renderer_desc_check_fields(&d)) != MS_OK)
        return st;
    return strcmp(d.cubemap, "builtin") == 0 ? MS_OK : ms_cubemap_probe(d.cubemap);
}

ms_status ms_renderer_create_desc(const ms_renderer_desc *d, ms_renderer **out)
{
    ms_status st;
    if ((st = ms_check_not_null(PART, "out", out)) != MS_OK)
        return st;
    *out = NULL;
    ms_renderer_desc desc = ms_renderer_desc_default();
    if ((st = ms_struct_in(d, &desc, MS_SIZES_RENDERER_DESC, PART)) != MS_OK ||
        (st = ms_renderer_desc_check_fields(&desc)) != MS_OK)
        return st;
    d = &desc;
#if !MS_HAVE_GL
    return ms_fail(MS_ERR_UNSUPPORTED,
                   "render: this build of libmodesplit has no OpenGL context backend "
                   "(OSMesa or EGL); install libegl-dev (or libosmesa6-dev) and rebuild to "
                   "render images");
#else
    ms_renderer *r = ms_alloc(sizeof *r);
    if (!r)
        return ms_fail(MS_ERR_OUT_OF_MEMORY, "render: out of memory for the renderer");
    r->desc = *d;
    r->shader_name = ms_strdup(d->shader);
    r->shader_params = ms_strdup(d->shader_params);
    r->cubemap_path = ms_strdup(d->cubemap);
    r->backend_name = ms_strdup(d->backend ? d->backend : "auto");
    r->pixels = ms_alloc_array((size_t)d->width * (size_t)d->height, 4);
    if (!r->shader_name || (d->shader_params && !r->shader_params) || !r->cubemap_path ||
        !r->backend_name || !r->pixels) {
        ms_renderer_destroy(r);
        return ms_fail(MS_ERR_OUT_OF_MEMORY, "render: out of memory for a %d x %d image", d->width,
                       d->height);
    }
    r->desc.shader = r->shader_name;
    r->desc.shader_params = r->shader_params;
    r->desc.cubemap = r->cubemap_path;
    r->desc.backend = r->backend_name;
    double ln = norm3(d->light_dir);
    for (int k = 0; k < 3; ++k) {
        r->desc.light_dir[k] = (float)(d->light_dir[k] / ln);
        r->light_to[k] = -r->desc.light_dir[k];
    }
    r->rim_z = d->pool_max[2];
    float side = MS_MIN(d->pool_max[0] - d->pool_min[0], d->pool_max[1] - d->pool_min[1]);
    r->tile_size = d->tile_size > 0 ? d->tile_size : side / 12.0f;

    if ((st = ms_shader_instance_create(d->shader, d->shader_params, &r->shader)) != MS_OK) {
        ms_renderer_destroy(r);
        return st;
    }
    r->passes = r->shader.vt->passes & (MS_SHADER_NEEDS_REFLECTION | MS_SHADER_NEEDS_REFRACTION |
                                        MS_SHADER_NEEDS_CAUSTICS);
    r->trace_caustics = (r->passes & MS_SHADER_NEEDS_CAUSTICS) && d->caustics;
    if (!r->trace_caustics)
        r->passes &= ~(unsigned)MS_SHADER_NEEDS_CAUSTICS;
    r->stats.passes = r->passes;

    ms_cubemap sky = {0, {NULL}};
    if (strcmp(d->cubemap, "builtin") == 0)
        st = ms_sky_builtin(sky_size_for(d->width, d->height), r->desc.light_dir, &sky);
    else
        st = ms_cubemap_load(d->cubemap, &sky);
    if (st == MS_OK)
        st = ms_gl_create(r, &sky);
    ms_cubemap_free(&sky);
    if (st != MS_OK) {
        ms_renderer_destroy(r);
        return st;
    }
    *out = r;
    return MS_OK;
#endif
}

ms_status ms_renderer_create(const ms_scene *sc, ms_renderer **out)
{
    return ms_renderer_create_from_scene(sc, out);
}

ms_status ms_renderer_create_from_scene(const ms_scene *sc, ms_renderer **out)
{
    ms_status st;
    if ((st = ms_check_not_null(PART, "out", out)) != MS_OK)
        return st;
    *out = NULL;
    if ((st = ms_check_not_null(PART, "scene", sc)) != MS_OK)
        return st;
    if (!sc->has_render)
        return ms_fail(MS_ERR_INVALID_ARGUMENT,
                       "render: scene \"%s\" has no \"render\" section, so it asks for no "
                       "image; add one or use ms_renderer_create_desc",
                       sc->name ? sc->name : "");
    ms_renderer_desc d = ms_renderer_desc_default();
    if ((st = ms_renderer_desc_from_scene(sc, &d)) != MS_OK)
        return st;
    return ms_renderer_create_desc(&d, out);
}

void ms_renderer_destroy(ms_renderer *r)
{
    if (!r)
        return;
#if MS_HAVE_GL
    ms_gl_destroy(r->gl);
#endif
    ms_shader_instance_destroy(&r->shader);
    ms_caustics_free(&r->caustics);
    ms_render_objects_free(r);
    ms_free(r->discs);
    ms_free(r->spray);
    ms_free(r->foam);
    ms_free(r->display);
    ms_render_cavity_free(r);
    ms_free(r->pixels);
    ms_free(r->shader_name);
    ms_free(r->shader_params);
    ms_free(r->cubemap_path);
    ms_free(r->backend_name);
    ms_free(r);
}

ms_status ms_renderer_draw_field(ms_renderer *r, const float *h, const ms_grid *g, double time)
{
    ms_status st;
    if ((st = ms_check_not_null(PART, "renderer", r)) != MS_OK ||
        (st = ms_check_not_null(PART, "height field", h)) != MS_OK ||
        (st = ms_check_not_null(PART, "grid", g)) != MS_OK ||
        (st = ms_check_int_range(PART, "grid nx", g->nx, 2, 16384)) != MS_OK ||
        (st = ms_check_int_range(PART, "grid ny", g->ny, 2, 16384)) != MS_OK ||
        (st = ms_check_positive(PART, "grid dx", g->dx, "m")) != MS_OK ||
        (st = ms_check_positive(PART, "grid dy", g->dy, "m")) != MS_OK ||
        (st = ms_check_finite(PART, "grid origin[0]", g->origin[0])) != MS_OK ||
        (st = ms_check_finite(PART, "grid origin[1]", g->origin[1])) != MS_OK ||
        (st = ms_check_finite(PART, "time", time)) != MS_OK)
        return st;
    if ((long)g->nx * g->ny > MAX_FIELD_CELLS)
        return ms_fail(MS_ERR_INVALID_ARGUMENT,
                       "render: grid %d x %d cells is over the %ld cells a mesh may have", g->nx,
                       g->ny, MAX_FIELD_CELLS);
    long bad = ms_field_nonfinite(h, (size_t)g->nx * (size_t)g->ny);
    if (bad >= 0)
        return ms_fail(MS_ERR_INVALID_ARGUMENT,
                       "render: height %g m at cell (%ld, %ld) is not finite; every height "
                       "must be a finite number",
                       (double)h[bad], bad % g->nx, bad / g->nx);
#if MS_HAVE_GL
    double t0 = ms_now();
    st = ms_gl_draw(r, h, g, time);
    if (st != MS_OK)
        return st;
    r->have_frame = 1;
    r->stats.frames++;
    r->stats.total_ms = 1e3 * (ms_now() - t0);
    return MS_OK;
#else
    return ms_fail(MS_ERR_UNSUPPORTED, "render: this build has no OpenGL (OSMesa or EGL)");
#endif
}

ms_status ms_renderer_set_discs(ms_renderer *r, const ms_render_disc *discs, int n)
{
    ms_status st;
    if ((st = ms_check_not_null(PART, "renderer", r)) != MS_OK ||
        (st = ms_check_int_range(PART, "discs n", n, 0, MS_RENDER_MAX_DISCS)) != MS_OK ||
        (n > 0 && (st = ms_check_not_null(PART, "discs", discs)) != MS_OK))
        return st;
    for (int i = 0; i < n; ++i) {
        const ms_render_disc *c = &discs[i];
        char key[64];
        for (int k = 0; k < 3; ++k) {
            snprintf(key, sizeof key, "disc %d pos[%d]", i, k);
            if ((st = ms_check_range(PART, key, c->pos[k], -1e6, 1e6, "m")) != MS_OK)
                return st;
            snprintf(key, sizeof key, "disc %d color[%d]", i, k);
            if ((st = ms_check_range(PART, key, c->color[k], 0, 1, "")) != MS_OK)
                return st;
        }
        snprintf(key, sizeof key, "disc %d radius", i);
        if ((st = ms_check_positive(PART, key, c->radius, "m")) != MS_OK)
            return st;
    }
    if (n > r->discs_cap) {
        ms_render_disc *p = ms_alloc_array((size_t)n, sizeof *p);
        if (!p)
            return ms_fail(MS_ERR_OUT_OF_MEMORY, "render: out of memory for %d discs", n);
        ms_free(r->discs);
        r->discs = p;
        r->discs_cap = n;
    }
    if (n > 0)
        memcpy(r->discs, discs, (size_t)n * sizeof *discs);
    r->ndiscs = n;
    r->nleaves = 0;
    r->discs_changed = 1;
    return MS_OK;
}

ms_status ms_renderer_set_spray(ms_renderer *r, const float *xyz, int n, float radius)
{
    ms_status st;
    if ((st = ms_check_not_null(PART, "renderer", r)) != MS_OK ||
        (st = ms_check_int_range(PART, "spray n", n, 0, MS_RENDER_MAX_SPRAY)) != MS_OK ||
        (n > 0 && (st = ms_check_not_null(PART, "spray", xyz)) != MS_OK) ||
        (n > 0 && (st = ms_check_range(PART, "spray radius", radius, 1e-6, 1.0, "m")) != MS_OK))
        return st;
    for (int i = 0; i < 3 * n; ++i)
        if (!isfinite(xyz[i]) || fabsf(xyz[i]) > 1e6f)
            return ms_fail(MS_ERR_INVALID_ARGUMENT,
                           "render: spray droplet %d coordinate %d is %g, outside [-1e6, 1e6] m",
                           i / 3, i % 3, (double)xyz[i]);
    if (n > r->spray_cap) {
        float *p = ms_alloc_array((size_t)n * 3, sizeof *p);
        if (!p)
            return ms_fail(MS_ERR_OUT_OF_MEMORY, "render: out of memory for %d droplets", n);
        ms_free(r->spray);
        r->spray = p;
        r->spray_cap = n;
    }
    if (n > 0)
        memcpy(r->spray, xyz, (size_t)n * 3 * sizeof *xyz);
    r->nspray = n;
    r->spray_radius = radius;
    return MS_OK;
}

ms_status ms_renderer_set_foam(ms_renderer *r, const float *foam, const ms_grid *g)
{
    ms_status st;
    if ((st = ms_check_not_null(PART, "renderer", r)) != MS_OK)
        return st;
    if (!foam) {
        r->foam_changed |= r->has_foam;
        r->has_foam = 0;
        return MS_OK;
    }
    if ((st = ms_check_not_null(PART, "foam grid", g)) != MS_OK ||
        (st = ms_check_int_range(PART, "foam grid nx", g->nx, 1, 16384)) != MS_OK ||
        (st = ms_check_int_range(PART, "foam grid ny", g->ny, 1, 16384)) != MS_OK ||
        (st = ms_check_positive(PART, "foam grid dx", g->dx, "m")) != MS_OK ||
        (st = ms_check_positive(PART, "foam grid dy", g->dy, "m")) != MS_OK)
        return st;
    const size_t cells = (size_t)g->nx * (size_t)g->ny;
    for (size_t c = 0; c < cells; ++c)
        if (!(foam[c] >= 0.0f && foam[c] <= 1.0f))
            return ms_fail(MS_ERR_INVALID_ARGUMENT, "render: foam cell %zu is %g, outside [0, 1]",
                           c, (double)foam[c]);
    if (r->foam_cap < cells) {
        float *p = ms_alloc_array(cells, sizeof *p);
        if (!p)
            return ms_fail(MS_ERR_OUT_OF_MEMORY, "render: out of memory for %zu foam cells", cells);
        ms_free(r->foam);
        r->foam = p;
        r->foam_cap = cells;
    }
    memcpy(r->foam, foam, cells * sizeof *foam);
    r->foam_grid = *g;
    r->has_foam = 1;
    r->foam_changed = 1;
    return MS_OK;
}

ms_status ms_renderer_set_camera(ms_renderer *r, const float eye[3], const float target[3],
                                 const float up[3], float fov)
{
    ms_status st;
    if ((st = ms_check_not_null(PART, "renderer", r)) != MS_OK ||
        (st = ms_check_not_null(PART, "eye", eye)) != MS_OK ||
        (st = ms_check_not_null(PART, "target", target)) != MS_OK ||
        (st = ms_check_not_null(PART, "up", up)) != MS_OK ||
        (st = check_camera(eye, target, up, fov)) != MS_OK)
        return st;
    ms_renderer_desc old = r->desc;
    memcpy(r->desc.eye, eye, sizeof r->desc.eye);
    memcpy(r->desc.target, target, sizeof r->desc.target);
    memcpy(r->desc.up, up, sizeof r->desc.up);
    r->desc.fov = fov;
#if MS_HAVE_GL
    if ((st = ms_gl_camera_moved(r)) != MS_OK) {
        r->desc = old;
        return st;
    }
#else
    (void)old;
#endif
    return MS_OK;
}

const unsigned char *ms_renderer_pixels(const ms_renderer *r, int *w, int *h)
{
    if (w)
        *w = r ? r->desc.width : 0;
    if (h)
        *h = r ? r->desc.height : 0;
    return r && !r->in_context ? r->pixels : NULL; /* in a context: the caller's framebuffer */
}

ms_status ms_renderer_write_png(const ms_renderer *r, const char *path)
{
    ms_status st;
    if ((st = ms_check_not_null(PART, "renderer", r)) != MS_OK ||
        (st = ms_check_not_null(PART, "path", path)) != MS_OK)
        return st;
    if (!r->have_frame)
        return ms_fail(MS_ERR_STATE,
                       "render: nothing drawn yet; call ms_renderer_draw before "
                       "writing \"%s\"",
                       path);
    if (r->in_context)
        return ms_fail(MS_ERR_STATE,
                       "render: this renderer draws into the caller's OpenGL "
                       "framebuffer and reads no pixels back; read them there to "
                       "write \"%s\"",
                       path);
    return ms_png_write_rgba(path, r->pixels, r->desc.width, r->desc.height);
}

void ms_renderer_stats(const ms_renderer *r, ms_render_stats *out)
{
    ms_renderer_get_stats(r, out);
}

void ms_renderer_get_stats(const ms_renderer *r, ms_render_stats *out)
{
    size_t size = ms_struct_out(out, MS_SIZES_RENDER_STATS, PART);
    if (!size)
        return;
    ms_render_stats full = ms_render_stats_init();
    if (r)
        full = r->stats;
    ms_struct_write(out, &full, size);
}

const float *ms_renderer_caustics(const ms_renderer *r, int *n)
{
    int ok = r && r->trace_caustics && r->have_frame && r->caustics.map;
    if (n)
        *n = ok ? r->caustics.n : 0;
    return ok ? r->caustics.map : NULL;
}

ms_status ms_render_reserve(float **buf, size_t *cap, size_t need, const char *what)
{
    if (*cap >= need)
        return MS_OK;
    ms_free(*buf);
    *buf = ms_alloc_array(need, sizeof(float));
    *cap = *buf ? need : 0;
    return *buf ? MS_OK : ms_fail(MS_ERR_OUT_OF_MEMORY, "render: out of memory for %s", what);
}
