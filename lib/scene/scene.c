/* ms_scene: loading a scene file (JSON, parsed by jansson) into the values
 * of data/scenes/README.md, and the accessors the tool and the writer use.
 * The schema itself is in sections.c, effects.c, section_render.c and
 * section_output.c; the typed readers that name
 * file:line:col in reader.c and locate.c.
 */
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <jansson.h>

#include "core/core_internal.h"
#include "sim/sim_sizes.h"
#include "surface/surface_sizes.h"
#include "volume/volume_sizes.h"
#include "scene/override.h"
#include "scene/sections.h"

#define MAX_SCENE_BYTES (16u << 20)

static void free_path(ms_scene_motion *p)
{
    ms_free(p->points);
    p->points = NULL;
    p->npoints = 0;
}

static void free_shape(ms_scene_shape *s)
{
    ms_free(s->kind);
    ms_free(s->params_json);
    free_path(&s->path);
}

void ms_scene_destroy(ms_scene *sc)
{
    if (!sc)
        return;
    ms_free(sc->text);
    ms_free(sc->path);
    ms_free(sc->name);
    for (int i = 0; i < sc->nobstacles; ++i)
        free_shape(&sc->obstacles[i]);
    ms_free(sc->obstacles);
    free_path(&sc->boat_path);
    free_path(&sc->drag_path);
    ms_free(sc->drops);
    ms_free(sc->floater_xy);
    if (sc->has_container)
        free_shape(&sc->container);
    ms_free(sc->render_shader);
    ms_free(sc->render_cubemap);
    ms_free(sc->render_shader_params);
    ms_free(sc);
}

static ms_status parse_one(const char *text, size_t len, const char *file, const char *path,
                           const char *dir, const char *default_name, int nset,
                           const char *const *set, ms_scene **out)
{
    if (len > MAX_SCENE_BYTES)
        return ms_fail(MS_ERR_INVALID_ARGUMENT, "%s: scene of %zu bytes; allowed: at most %u bytes",
                       file, len, MAX_SCENE_BYTES);
    ms_scene *sc = ms_alloc(sizeof *sc);
    if (!sc)
        return ms_fail(MS_ERR_OUT_OF_MEMORY, "scene: out of memory");
    sc->text = ms_strndup(text, len);
    sc->text_len = len;
    sc->path = ms_strndup(path, strlen(path));
    if (!sc->text || !sc->path) {
        ms_scene_destroy(sc);
        return ms_fail(MS_ERR_OUT_OF_MEMORY, "scene: out of memory for %zu bytes", len);
    }
    json_error_t err;
    json_t *root = json_loadb(text, len, JSON_REJECT_DUPLICATES, &err);
    if (!root) {
        int line = err.line, col = err.column;
        if (line < 1) {
            size_t pos = err.position > 0 ? (size_t)err.position : 0;
            ms_scene_line_col(text, len, pos, &line, &col);
        }
        ms_scene_destroy(sc);
        return ms_fail(MS_ERR_PARSE, "%s:%d:%d: JSON syntax error: %s", file, line,
                       col < 1 ? 1 : col, err.text);
    }
    ms_scene_ctx c = {.file = file,
                      .text = sc->text,
                      .len = len,
                      .depth = 0,
                      .dir = dir,
                      .set = set,
                      .nset = nset};
    ms_status st = ms_scene_read_sections(&c, root, sc, dir, default_name);
    json_decref(root);
    if (st != MS_OK) {
        ms_scene_destroy(sc);
        return st;
    }
    *out = sc;
    return MS_OK;
}

/* The scene of text with n overrides (override.c). The text alone is read
 * first, so its own errors name its own lines; then the merged scene, whose
 * errors at an overridden key name the "--set"; the rest name the merged
 * text ("FILE with --set:line:col"), the text ms_scene_text returns. */
static ms_status parse(const char *text, size_t len, const char *file, const char *path,
                       const char *dir, const char *default_name, int nset, const char *const *set,
                       ms_scene **out)
{
    if (nset == 0)
        return parse_one(text, len, file, path, dir, default_name, 0, NULL, out);
    if (nset < 0 || !set)
        return ms_fail(MS_ERR_INVALID_ARGUMENT,
                       "scene: %d overrides at %p; allowed: n >= 0 "
                       "and a list when n > 0",
                       nset, (const void *)set);
    for (int i = 0; i < nset; ++i)
        MS_TRY(ms_scene_override_check(set[i]));
    ms_scene *plain = NULL;
    MS_TRY(parse_one(text, len, file, path, dir, default_name, 0, NULL, &plain));
    ms_scene_destroy(plain);
    char *merged = NULL;
    size_t mlen = 0;
    MS_TRY(ms_scene_apply_overrides(text, len, nset, set, &merged, &mlen));
    size_t flen = strlen(file) + 16;
    char *where = ms_alloc(flen);
    ms_status st = MS_ERR_OUT_OF_MEMORY;
    if (where) {
        snprintf(where, flen, "%s with --set", file);
        st = parse_one(merged, mlen, where, path, dir, default_name, nset, set, out);
    } else {
        ms_fail(st, "scene: out of memory");
    }
    ms_free(where);
    ms_free(merged);
    return st;
}

ms_status ms_scene_parse(const char *json, size_t len, ms_scene **out)
{
    return ms_scene_parse_with_overrides(json, len, 0, NULL, out);
}

ms_status ms_scene_parse_with_overrides(const char *json, size_t len, int n,
                                        const char *const *overrides, ms_scene **out)
{
    if (!out)
        return ms_fail(MS_ERR_INVALID_ARGUMENT, "scene: out is NULL");
    *out = NULL;
    if (!json)
        return ms_fail(MS_ERR_INVALID_ARGUMENT, "scene: json text is NULL");
    return parse(json, len, "<scene>", "", "", "scene", n, overrides, out);
}

ms_status ms_scene_load(const char *path, ms_scene **out)
{
    return ms_scene_load_with_overrides(path, 0, NULL, out);
}

ms_status ms_scene_load_with_overrides(const char *path, int n, const char *const *overrides,
                                       ms_scene **out)
{
    if (!out)
        return ms_fail(MS_ERR_INVALID_ARGUMENT, "scene: out is NULL");
    *out = NULL;
    if (!path || !path[0])
        return ms_fail(MS_ERR_INVALID_ARGUMENT, "scene: path is NULL or empty");
    FILE *f = fopen(path, "rb");
    if (!f)
        return ms_fail(MS_ERR_IO, "%s: cannot open the scene file: %s", path, strerror(errno));
    char *buf = NULL;
    size_t len = 0, cap = 0;
    ms_status st = MS_OK;
    for (;;) {
        if (len == cap) {
            if (cap > MAX_SCENE_BYTES) {
                st = ms_fail(MS_ERR_INVALID_ARGUMENT,
                             "%s: scene file is larger than %u bytes; allowed: at most %u bytes",
                             path, MAX_SCENE_BYTES, MAX_SCENE_BYTES);
                break;
            }
            size_t ncap = cap ? 2 * cap : 65536;
            char *nb = ms_realloc(buf, ncap);
            if (!nb) {
                st = ms_fail(MS_ERR_OUT_OF_MEMORY, "%s: out of memory reading the scene", path);
                break;
            }
            buf = nb;
            cap = ncap;
        }
        size_t got = fread(buf + len, 1, cap - len, f);
        len += got;
        if (got == 0) {
            if (ferror(f))
                st =
                    ms_fail(MS_ERR_IO, "%s: cannot read the scene file: %s", path, strerror(errno));
            break;
        }
    }
    fclose(f);
    if (st == MS_OK) {
        /* directory with a trailing '/', for paths inside the scene */
        const char *slash = strrchr(path, '/');
        size_t dlen = slash ? (size_t)(slash - path) + 1 : 0;
        char *dir = ms_strndup(path, dlen);
        const char *base = slash ? slash + 1 : path;
        size_t blen = strlen(base);
        if (blen > 5 && strcmp(base + blen - 5, ".json") == 0)
            blen -= 5;
        char *name = ms_strndup(base, blen);
        if (!dir || !name)
            st = ms_fail(MS_ERR_OUT_OF_MEMORY, "%s: out of memory", path);
        else
            st = parse(buf, len, path, path, dir, name[0] ? name : "scene", n, overrides, out);
        ms_free(dir);
        ms_free(name);
    }
    ms_free(buf);
    return st;
}

const char *ms_scene_name(const ms_scene *sc)
{
    return sc ? sc->name : "";
}

const char *ms_scene_text(const ms_scene *sc)
{
    return sc ? sc->text : "";
}

const char *ms_scene_path(const ms_scene *sc)
{
    return sc ? sc->path : "";
}

double ms_scene_duration(const ms_scene *sc)
{
    return sc ? sc->duration : 0;
}

float ms_scene_frame_dt(const ms_scene *sc)
{
    return sc ? sc->frame_dt : 0;
}

unsigned ms_scene_output_fields(const ms_scene *sc)
{
    return sc ? sc->output_fields : 0;
}

int ms_scene_output_every(const ms_scene *sc)
{
    return sc ? sc->output_every : 1;
}

int ms_scene_output_checkpoint_every(const ms_scene *sc)
{
    return sc ? sc->output_checkpoint_every : 1;
}

int ms_scene_output_deflate(const ms_scene *sc)
{
    return sc ? sc->output_deflate : 1;
}

int ms_scene_has_render(const ms_scene *sc)
{
    return sc ? sc->has_render : 0;
}

/* A desc of the scene written up to the caller's .size. */
static ms_status desc_out(const ms_scene *sc, int has, const char *section, void *user,
                          const void *full, ms_struct_sizes k)
{
    MS_TRY(ms_check_not_null("scene", "scene", sc));
    MS_TRY(ms_check_not_null("scene", "out", user));
    if (!has)
        return ms_fail(MS_ERR_STATE, "scene: \"%s\" has no \"%s\" section", sc->name, section);
    size_t size = ms_struct_out(user, k, "scene");
    if (!size)
        return MS_ERR_INVALID_ARGUMENT;
    ms_struct_write(user, full, size);
    return MS_OK;
}

ms_status ms_scene_volume_desc(const ms_scene *sc, ms_volume_desc *out)
{
    return desc_out(sc, sc && sc->has_volume, "volume", out, sc ? &sc->volume : NULL,
                    MS_SIZES_VOLUME_DESC);
}

ms_status ms_scene_surface_desc(const ms_scene *sc, ms_surface_desc *out)
{
    return desc_out(sc, sc && sc->has_surface, "surface", out, sc ? &sc->surface : NULL,
                    MS_SIZES_SURFACE_DESC);
}

ms_status ms_scene_sim_desc(const ms_scene *sc, ms_sim_desc *out)
{
    return desc_out(sc, 1, "sim", out, sc ? &sc->sim : NULL, MS_SIZES_SIM_DESC);
}
