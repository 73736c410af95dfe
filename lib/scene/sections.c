/* The scene schema: every key of the top level and of the domain, volume,
 * surface, coupling and obstacles sections, its type, unit, default and
 * range (the same table as data/scenes/README.md; keep both in step); the
 * effects, render and output sections are read by effects.c,
 * section_render.c and section_output.c.
 * A section that is absent leaves its has_* flag 0: the effect is not
 * simulated and costs nothing.
 */
#include <float.h>
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/core_internal.h"
#include "modesplit/plugin.h"
#include "modesplit/shape.h"
#include "modesplit/sim.h"
#include "plugin/plugin_internal.h"
#include "scene/reader.h"
#include "scene/scene_internal.h"
#include "scene/sections.h"

#define BIG MS_SCENE_BIG
#define MAX_SPEED MS_SCENE_MAX_SPEED
#define MAX_PARTICLES MS_VOLUME_MAX_PARTICLES

/* {"points": [[x, y(, z)], ...], "speed", "loop", "start"} */
ms_status ms_scene_read_path(ms_scene_ctx *c, json_t *obj, const char *key, int dim,
                             ms_scene_motion *p)
{
    static const char *const keys[] = {"points", "speed", "loop", "start", NULL};
    json_t *o, *pts;
    MS_TRY(ms_scene_get_object(c, obj, key, &o));
    if (!o)
        return MS_OK;
    ms_scene_push_key(c, key);
    ms_status st = ms_scene_check_keys(c, o, keys);
    if (st == MS_OK)
        st = ms_scene_require(c, o, "points",
                              dim == 2 ? "an array of [x, y] in m" : "an array of [x, y, z] in m");
    if (st == MS_OK)
        st = ms_scene_get_array(c, o, "points", 1, MS_SCENE_MAX_PATH_POINTS, &pts);
    if (st == MS_OK)
        st = ms_scene_get_float(c, o, "speed", 1.0, 0, MAX_SPEED, 1, "m/s", &p->speed);
    if (st == MS_OK)
        st = ms_scene_get_bool(c, o, "loop", 0, &p->loop);
    if (st == MS_OK)
        st = ms_scene_get_float(c, o, "start", 0.0, 0, 1e6, 0, "s", &p->start);
    if (st == MS_OK) {
        size_t n = json_array_size(pts);
        p->points = ms_alloc_array(n * (size_t)dim, sizeof *p->points);
        if (!p->points)
            st = ms_fail(MS_ERR_OUT_OF_MEMORY, "scene: out of memory for a path of %zu points", n);
        else {
            p->dim = dim;
            ms_scene_push_key(c, "points");
            for (size_t i = 0; st == MS_OK && i < n; ++i) {
                ms_scene_push_index(c, (long)i);
                st = ms_scene_read_vec(c, json_array_get(pts, i), dim, -BIG, BIG, "m",
                                       p->points + i * (size_t)dim);
                ms_scene_pop(c);
            }
            ms_scene_pop(c);
            if (st == MS_OK)
                p->npoints = (int)n;
        }
    }
    ms_scene_pop(c);
    return st;
}

/* An obstacle or the container: a shape of a plugin, posed and maybe moving. */
ms_status ms_scene_read_shape(ms_scene_ctx *c, json_t *o, ms_scene_shape *s)
{
    static const char *const keys[] = {"shape", "params", "position",     "velocity", "orientation",
                                       "spin",  "path",   "surface_mask", NULL};
    static const float zero[3] = {0, 0, 0}, unturned[4] = {1, 0, 0, 0};
    const char *kind;
    json_t *params;
    MS_TRY(ms_scene_check_keys(c, o, keys));
    MS_TRY(ms_scene_require(c, o, "shape", "a shape plugin name such as \"sphere\""));
    MS_TRY(ms_scene_get_string(c, o, "shape", NULL, &kind));
    if (!kind[0] || strlen(kind) > 64) {
        ms_scene_push_key(c, "shape");
        ms_status st =
            ms_scene_fail(c, MS_ERR_INVALID_ARGUMENT,
                          "\"%.64s\" is not a shape name; allowed: 1 to 64 characters", kind);
        ms_scene_pop(c);
        return st;
    }
    MS_TRY(ms_scene_get_object(c, o, "params", &params));
    MS_TRY(ms_scene_get_vec(c, o, "position", 3, zero, -BIG, BIG, "m", s->position));
    MS_TRY(ms_scene_get_vec(c, o, "velocity", 3, zero, -MAX_SPEED, MAX_SPEED, "m/s", s->velocity));
    MS_TRY(ms_scene_get_vec(c, o, "orientation", 4, unturned, -1e3, 1e3, "", s->orientation));
    double q2 = 0.0;
    for (int k = 0; k < 4; ++k)
        q2 += (double)s->orientation[k] * s->orientation[k];
    if (!(q2 > 1e-12)) {
        ms_scene_push_key(c, "orientation");
        ms_status st = ms_scene_fail(c, MS_ERR_INVALID_ARGUMENT,
                                     "[0, 0, 0, 0] is no rotation; allowed: a quaternion "
                                     "[w, x, y, z] of any length but 0 (it is normalised)");
        ms_scene_pop(c);
        return st;
    }
    MS_TRY(ms_scene_get_vec(c, o, "spin", 3, zero, -1e3, 1e3, "rad/s", s->spin));
    MS_TRY(ms_scene_read_path(c, o, "path", 3, &s->path));
    MS_TRY(ms_scene_get_bool(c, o, "surface_mask", 1, &s->surface_mask));
    s->kind = ms_strdup(kind);
    /* a file a shape reads (the terrain's "png") is relative to the scene
     * file's folder, as the cubemap is, not to the working directory */
    json_t *png = params ? json_object_get(params, "png") : NULL;
    if (json_is_string(png) && json_string_value(png)[0] != '/' && c->dir && c->dir[0]) {
        size_t n = strlen(c->dir) + strlen(json_string_value(png)) + 1;
        char *full = ms_malloc(n);
        if (!full)
            return ms_fail(MS_ERR_OUT_OF_MEMORY, "scene: out of memory for a shape");
        snprintf(full, n, "%s%s", c->dir, json_string_value(png));
        json_object_set_new(params, "png", json_string(full));
        ms_free(full);
    }
    char *text = params ? ms_json_text(params, JSON_COMPACT) : NULL;
    s->params_json = text ? text : ms_strdup("{}");
    if (!s->kind || !s->params_json)
        return ms_fail(MS_ERR_OUT_OF_MEMORY, "scene: out of memory for a shape");
    /* the kind must name a shape plugin (the registry's sentence lists the
     * available ones), and the plugin must accept the parameters */
    const ms_plugin_rec *rec;
    ms_status st = MS_OK;
    if (ms_plugin_find("scene", kind, MS_PLUGIN_SHAPE, &rec) != MS_OK) {
        ms_scene_push_key(c, "shape");
        st = ms_scene_fail(c, MS_ERR_INVALID_ARGUMENT, "\"%.64s\" is not a shape plugin (%s)", kind,
                           ms_last_error());
    } else {
        ms_shape *probe = NULL;
        ms_status cst = ms_shape_create(kind, s->params_json, &probe);
        ms_shape_destroy(probe);
        if (cst != MS_OK) {
            ms_scene_push_key(c, params ? "params" : "shape");
            st = ms_scene_fail(c, cst == MS_ERR_OUT_OF_MEMORY ? cst : MS_ERR_INVALID_ARGUMENT,
                               "is refused by the %.64s plugin (%s)", kind, ms_last_error());
        }
    }
    if (st != MS_OK)
        return st;
    if (s->path.npoints > 0)
        memcpy(s->position, s->path.points, sizeof s->position);
    return MS_OK;
}

static ms_status read_domain(ms_scene_ctx *c, json_t *root, ms_scene *sc)
{
    static const char *const keys[] = {"min", "max", NULL};
    static const float dmin[3] = {0, 0, 0}, dmax[3] = {1, 1, 0.5f};
    json_t *o;
    MS_TRY(ms_scene_get_object(c, root, "domain", &o));
    memcpy(sc->domain_min, dmin, sizeof dmin);
    memcpy(sc->domain_max, dmax, sizeof dmax);
    if (!o)
        return MS_OK;
    ms_scene_push_key(c, "domain");
    ms_status st = ms_scene_check_keys(c, o, keys);
    if (st == MS_OK)
        st = ms_scene_get_vec(c, o, "min", 3, dmin, -BIG, BIG, "m", sc->domain_min);
    if (st == MS_OK)
        st = ms_scene_get_vec(c, o, "max", 3, dmax, -BIG, BIG, "m", sc->domain_max);
    for (int k = 0; st == MS_OK && k < 3; ++k) {
        if (!(sc->domain_max[k] > sc->domain_min[k])) {
            ms_scene_push_key(c, "max");
            st = ms_scene_fail(c, MS_ERR_INVALID_ARGUMENT,
                               "[%d] = %g m is not above min[%d] = %g m; allowed: max > min on "
                               "every axis",
                               k, sc->domain_max[k], k, sc->domain_min[k]);
            ms_scene_pop(c);
        }
    }
    ms_scene_pop(c);
    return st;
}

/* Particles fill_box makes along one axis of [lo, hi] at spacing h. */
static double fill_count(float lo, float hi, float h)
{
    return floor((double)(hi - lo) / h + 1e-6);
}

/* volume.fill[i]: a box {"min", "max"} inside the domain, max > min. */
static ms_status read_fill_box(ms_scene_ctx *c, json_t *b, float lo[3], float hi[3],
                               const ms_scene *sc)
{
    static const char *const box_keys[] = {"min", "max", NULL};
    if (!json_is_object(b))
        return ms_scene_fail(c, MS_ERR_PARSE,
                             "is not an object; allowed: {\"min\": [x, y, z], "
                             "\"max\": [x, y, z]} in m");
    MS_TRY(ms_scene_check_keys(c, b, box_keys));
    MS_TRY(ms_scene_require(c, b, "min", "[x, y, z] in m"));
    MS_TRY(ms_scene_require(c, b, "max", "[x, y, z] in m"));
    for (int k = 0; k < 2; ++k) {
        const char *key = k ? "max" : "min";
        ms_scene_push_key(c, key);
        ms_status st =
            ms_scene_read_vec(c, json_object_get(b, key), 3, -BIG, BIG, "m", k ? hi : lo);
        for (int a = 0; st == MS_OK && a < 3; ++a) {
            float v = (k ? hi : lo)[a];
            if (v < sc->domain_min[a] || v > sc->domain_max[a])
                st = ms_scene_fail(c, MS_ERR_INVALID_ARGUMENT,
                                   "[%d] = %g m lies outside the domain; allowed: [%g, "
                                   "%g] m",
                                   a, v, sc->domain_min[a], sc->domain_max[a]);
        }
        if (st == MS_OK && k == 1)
            for (int a = 0; a < 3; ++a)
                if (!(hi[a] > lo[a]))
                    st = ms_scene_fail(c, MS_ERR_INVALID_ARGUMENT,
                                       "[%d] = %g m is not above min[%d] = %g m; allowed: "
                                       "max > min on every axis",
                                       a, hi[a], a, lo[a]);
        ms_scene_pop(c);
        MS_TRY(st);
    }
    return MS_OK;
}

/* volume.fill: the boxes the volume starts filled with; *count is the
 * number of particles they make at volume.spacing (bounded here so a
 * scene cannot ask for more memory than MAX_PARTICLES). */
static ms_status read_fill(ms_scene_ctx *c, json_t *o, ms_scene *sc, double *count)
{
    json_t *fill;
    MS_TRY(ms_scene_get_array(c, o, "fill", 1, MS_SCENE_MAX_FILLS, &fill));
    if (!fill)
        return MS_OK;
    ms_scene_push_key(c, "fill");
    for (size_t i = 0; i < json_array_size(fill); ++i) {
        float *lo = sc->fill_lo[i], *hi = sc->fill_hi[i];
        ms_scene_push_index(c, (long)i);
        MS_TRY(read_fill_box(c, json_array_get(fill, i), lo, hi, sc));
        *count += fill_count(lo[0], hi[0], sc->volume.spacing) *
                  fill_count(lo[1], hi[1], sc->volume.spacing) *
                  fill_count(lo[2], hi[2], sc->volume.spacing);
        ms_scene_pop(c);
    }
    sc->nfill = (int)json_array_size(fill);
    if (*count > MAX_PARTICLES) {
        ms_status st = ms_scene_fail(c, MS_ERR_INVALID_ARGUMENT,
                                     "makes %.0f particles at spacing %g m; allowed: at most "
                                     "%ld (raise volume.spacing)",
                                     *count, sc->volume.spacing, MAX_PARTICLES);
        ms_scene_pop(c);
        return st;
    }
    ms_scene_pop(c);
    return MS_OK;
}

/* A part's refusal of the desc the scene filled (the sentence in
 * ms_last_error, the desc field in ms_last_error_key), named at the scene
 * key that set the field: section.key (key NULL: the section itself;
 * section NULL: a top-level key). The range is the part's: the scene
 * checks only that a value has the field's type. */
static ms_status refused_at(ms_scene_ctx *c, ms_status st, const char *section, const char *key)
{
    char why[640];
    snprintf(why, sizeof why, "%s", ms_last_error());
    int depth = c->depth;
    c->depth = 0;
    if (section)
        ms_scene_push_key(c, section);
    if (key)
        ms_scene_push_key(c, key);
    st = ms_scene_fail(c, st, "is refused: %s", why);
    c->depth = depth;
    return st;
}

/* The volume desc's fields that a scene key of the same name sets. */
static const char *const volume_keys[] = {"spacing",
                                          "smoothing_length",
                                          "rest_density",
                                          "gas_constant",
                                          "viscosity",
                                          "gravity",
                                          "pressure",
                                          "max_particles",
                                          "sound_speed",
                                          "courant",
                                          "max_substeps",
                                          "threads",
                                          "smooth_steps",
                                          "smooth_energy",
                                          "max_density_error",
                                          "max_divergence_error",
                                          "max_density_iterations",
                                          "max_divergence_iterations",
                                          NULL};
/* The DFSPH stop rule and caps among them (the tail of volume_keys). */
static const char *const *const dfsph_keys = volume_keys + 14;

/* ms_volume_desc_check of the scene's volume desc; a refusal named at the
 * key that set the field. h follows the spacing when the file does not
 * set it, so a refused default h is named at volume.spacing. */
static ms_status check_volume(ms_scene_ctx *c, json_t *o, const ms_volume_desc *v)
{
    ms_status st = ms_volume_desc_check(v);
    if (st == MS_OK)
        return MS_OK;
    const char *field = ms_last_error_key();
    if (strcmp(field, "domain_min") == 0 || strcmp(field, "domain_max") == 0)
        return refused_at(c, st, "domain", field + 7);
    if (strcmp(field, "smoothing_length") == 0 && !json_object_get(o, field))
        return refused_at(c, st, "volume", "spacing");
    for (const char *const *k = volume_keys; *k; ++k)
        if (strcmp(*k, field) == 0)
            return refused_at(c, st, "volume", *k);
    return refused_at(c, st, "volume", NULL);
}

/* A float key of a desc: any finite float (the part checks the range). */
static ms_status get_field(ms_scene_ctx *c, json_t *o, const char *key, const char *unit,
                           float *inout)
{
    return ms_scene_get_float(c, o, key, *inout, -FLT_MAX, FLT_MAX, 0, unit, inout);
}

static ms_status get_int_field(ms_scene_ctx *c, json_t *o, const char *key, int *inout)
{
    long v;
    MS_TRY(ms_scene_get_int(c, o, key, *inout, INT_MIN, INT_MAX, &v));
    *inout = (int)v;
    return MS_OK;
}

/* The volume section over ms_volume_desc_default(): each key sets the
 * desc field of its name. Scene rules on top of the desc: h is the
 * default's ratio h / spacing times the spacing unless set; max_particles
 * 0 (or absent) is room for what volume.fill makes; the DFSPH limits are
 * refused under the other laws (they would do nothing there). */
static ms_status read_volume(ms_scene_ctx *c, json_t *root, ms_scene *sc)
{
    static const char *const more[] = {"fill", "field", "settle", NULL};
    static const char *const pressures[] = {"ideal_gas", "tait", "dfsph", NULL};
    const char *keys[sizeof volume_keys / sizeof volume_keys[0] + 3];
    size_t nk = 0;
    for (const char *const *k = volume_keys; *k; ++k)
        keys[nk++] = *k;
    for (const char *const *k = more; *k; ++k)
        keys[nk++] = *k;
    keys[nk] = NULL;
    ms_volume_desc *v = &sc->volume;
    *v = ms_volume_desc_default();
    const float ratio = v->smoothing_length / v->spacing; /* the default h / spacing */
    json_t *o;
    int pressure, field[2] = {0, 0};
    MS_TRY(ms_scene_get_object(c, root, "volume", &o));
    if (!o)
        return MS_OK;
    sc->has_volume = 1;
    memcpy(v->domain_min, sc->domain_min, sizeof v->domain_min);
    memcpy(v->domain_max, sc->domain_max, sizeof v->domain_max);
    ms_scene_push_key(c, "volume");
    MS_TRY(ms_scene_check_keys(c, o, keys));
    MS_TRY(get_field(c, o, "spacing", "m", &v->spacing));
    v->smoothing_length = ratio * v->spacing;
    MS_TRY(get_field(c, o, "smoothing_length", "m", &v->smoothing_length));
    MS_TRY(get_field(c, o, "rest_density", "kg/m^3", &v->rest_density));
    MS_TRY(get_field(c, o, "gas_constant", "m^2/s^2", &v->gas_constant));
    MS_TRY(get_field(c, o, "viscosity", "Pa s", &v->viscosity));
    MS_TRY(
        ms_scene_get_vec(c, o, "gravity", 3, v->gravity, -FLT_MAX, FLT_MAX, "m/s^2", v->gravity));
    MS_TRY(ms_scene_get_enum(c, o, "pressure", pressures, (int)v->pressure, &pressure));
    v->pressure = (ms_pressure)pressure;
    int maxp = 0;
    MS_TRY(get_int_field(c, o, "max_particles", &maxp));
    if (maxp != 0)
        v->max_particles = maxp;
    MS_TRY(get_field(c, o, "sound_speed", "m/s", &v->sound_speed));
    MS_TRY(get_field(c, o, "courant", "", &v->courant));
    MS_TRY(get_int_field(c, o, "max_substeps", &v->max_substeps));
    MS_TRY(get_int_field(c, o, "threads", &v->threads));
    MS_TRY(get_int_field(c, o, "smooth_steps", &v->smooth_steps));
    MS_TRY(get_field(c, o, "smooth_energy", "J/kg", &v->smooth_energy));
    MS_TRY(get_field(c, o, "max_density_error", "", &v->max_density_error));
    MS_TRY(get_field(c, o, "max_divergence_error", "", &v->max_divergence_error));
    MS_TRY(get_int_field(c, o, "max_density_iterations", &v->max_density_iterations));
    MS_TRY(get_int_field(c, o, "max_divergence_iterations", &v->max_divergence_iterations));
    for (const char *const *k = dfsph_keys; v->pressure != MS_PRESSURE_DFSPH && *k; ++k)
        if (json_object_get(o, *k)) {
            ms_scene_push_key(c, *k);
            return ms_scene_fail(c, MS_ERR_INVALID_ARGUMENT,
                                 "is a limit of the \"dfsph\" pressure solver; allowed only with "
                                 "volume.pressure \"dfsph\"");
        }
    MS_TRY(ms_scene_get_ivec(c, o, "field", 2, field, INT_MIN, INT_MAX, field));
    sc->sim.field_nx = field[0];
    sc->sim.field_ny = field[1];
    MS_TRY(check_volume(c, o, v));
    /* the range is the volume's (ms_volume_settle) */
    MS_TRY(ms_scene_get_float(c, o, "settle", 0, 0, MS_VOLUME_SETTLE_MAX_S, 0, "s", &sc->settle));
    double count = 0;
    MS_TRY(read_fill(c, o, sc, &count));
    if (maxp != 0 && count > maxp) {
        ms_scene_push_key(c, "max_particles");
        ms_status st = ms_scene_fail(c, MS_ERR_INVALID_ARGUMENT,
                                     "%d is below the %.0f particles volume.fill makes; allowed: "
                                     "0 (as many as the fill makes) or at least %.0f",
                                     maxp, count, count);
        ms_scene_pop(c);
        return st;
    }
    if (maxp == 0) {
        /* room for what the fill makes, counted generously (one more per
         * axis) */
        long particles = 0;
        for (int i = 0; i < sc->nfill; ++i) {
            long n = 1;
            for (int k = 0; k < 3; ++k)
                n *= (long)floor((double)(sc->fill_hi[i][k] - sc->fill_lo[i][k]) / v->spacing +
                                 1e-6) +
                     1;
            particles += n;
        }
        v->max_particles = (int)MS_MIN(MS_MAX(particles, 64), MS_VOLUME_MAX_PARTICLES);
    }
    ms_scene_pop(c);
    return MS_OK;
}

/* ms_surface_desc_check of the scene's surface desc, named at the key that
 * set the refused field: nx, ny at surface.cells, dx (the domain's x
 * extent over cells[0]) at domain.max. */
static ms_status check_surface(ms_scene_ctx *c, const ms_surface_desc *s)
{
    ms_status st = ms_surface_desc_check(s);
    if (st == MS_OK)
        return MS_OK;
    const char *field = ms_last_error_key();
    if (strcmp(field, "nx") == 0 || strcmp(field, "ny") == 0)
        return refused_at(c, st, "surface", "cells");
    if (strcmp(field, "dx") == 0)
        return refused_at(c, st, "domain", "max");
    if (strcmp(field, "seed") == 0)
        return refused_at(c, st, NULL, "seed");
    return refused_at(c, st, "surface", field[0] ? field : NULL);
}

/* The surface section over ms_surface_desc_default(); dx is the domain's
 * x extent over cells[0] (square cells), the seed the scene's. */
static ms_status read_surface(ms_scene_ctx *c, json_t *root, ms_scene *sc)
{
    static const char *const keys[] = {
        "cells", "wave_speed", "damping", "boundary",           "max_substeps",
        "level", "model",      "advect",  "turbulence_damping", NULL};
    static const char *const boundaries[] = {"reflect", "absorb", "periodic", NULL};
    /* in the order of ms_surface_model; the default is the desc's */
    static const char *const models[] = {"wave", "dispersive", NULL};
    ms_surface_desc *s = &sc->surface;
    *s = ms_surface_desc_default();
    json_t *o;
    int cells[2] = {s->nx, s->ny}, boundary, model;
    float height = sc->domain_max[2] - sc->domain_min[2];
    /* still water: the height of the fill spread over the domain, or half the
     * domain's height without a volume */
    double level = 0.5 * height;
    if (sc->has_volume) {
        double v = 0, area = (double)(sc->domain_max[0] - sc->domain_min[0]) *
                             (sc->domain_max[1] - sc->domain_min[1]);
        for (int i = 0; i < sc->nfill; ++i)
            v += (double)(sc->fill_hi[i][0] - sc->fill_lo[i][0]) *
                 (sc->fill_hi[i][1] - sc->fill_lo[i][1]) * (sc->fill_hi[i][2] - sc->fill_lo[i][2]);
        level = MS_MIN(v / area, height);
    }
    sc->level = (float)level;
    MS_TRY(ms_scene_get_object(c, root, "surface", &o));
    if (!o)
        return MS_OK;
    sc->has_surface = 1;
    ms_scene_push_key(c, "surface");
    MS_TRY(ms_scene_check_keys(c, o, keys));
    MS_TRY(ms_scene_get_ivec(c, o, "cells", 2, cells, INT_MIN, INT_MAX, cells));
    MS_TRY(get_field(c, o, "wave_speed", "m/s", &s->wave_speed));
    MS_TRY(get_field(c, o, "damping", "", &s->damping));
    MS_TRY(ms_scene_get_enum(c, o, "boundary", boundaries, (int)s->boundary, &boundary));
    MS_TRY(get_int_field(c, o, "max_substeps", &s->max_substeps));
    MS_TRY(ms_scene_get_float(c, o, "level", level, 0, height, 0, "m", &sc->level));
    MS_TRY(ms_scene_get_enum(c, o, "model", models, (int)s->model, &model));
    s->model = (ms_surface_model)model;
    MS_TRY(ms_scene_get_bool(c, o, "advect", s->advect, &s->advect));
    MS_TRY(get_field(c, o, "turbulence_damping", "", &s->turbulence_damping));
    if (s->advect && !sc->has_volume) {
        ms_scene_push_key(c, "advect");
        return ms_scene_fail(c, MS_ERR_INVALID_ARGUMENT,
                             "true needs a volume section: its flow carries the waves");
    }
    s->nx = cells[0];
    s->ny = cells[1];
    s->boundary = (ms_boundary)boundary;
    s->seed = sc->seed;
    double dx = (double)(sc->domain_max[0] - sc->domain_min[0]) / cells[0];
    double dy = (double)(sc->domain_max[1] - sc->domain_min[1]) / cells[1];
    s->dx = (float)dx;
    MS_TRY(check_surface(c, s));
    if (fabs(dx - dy) > 1e-3 * dx) {
        ms_scene_push_key(c, "cells");
        ms_status st = ms_scene_fail(c, MS_ERR_INVALID_ARGUMENT,
                                     "[%d, %d] over the domain's %g m x %g m gives cells of %g m x "
                                     "%g m; allowed: square cells (cells[1] = %.0f)",
                                     cells[0], cells[1], sc->domain_max[0] - sc->domain_min[0],
                                     sc->domain_max[1] - sc->domain_min[1], dx, dy,
                                     (sc->domain_max[1] - sc->domain_min[1]) / dx);
        ms_scene_pop(c);
        return st;
    }
    ms_scene_pop(c);
    return MS_OK;
}

static ms_status read_coupling(ms_scene_ctx *c, json_t *root, ms_scene *sc)
{
    static const char *const keys[] = {"n_time", "surface_from_volume", "volume_from_surface",
                                       NULL};
    json_t *o;
    MS_TRY(ms_scene_get_object(c, root, "coupling", &o));
    if (!o)
        return MS_OK;
    ms_scene_push_key(c, "coupling");
    MS_TRY(ms_scene_check_keys(c, o, keys));
    MS_TRY(get_int_field(c, o, "n_time", &sc->sim.surface_substeps));
    MS_TRY(get_field(c, o, "surface_from_volume", "", &sc->sim.couple_surface_from_volume));
    MS_TRY(get_field(c, o, "volume_from_surface", "", &sc->sim.couple_volume_from_surface));
    ms_scene_pop(c);
    return MS_OK;
}

/* ms_sim_desc_check of the scene's sim desc (its volume and surface point
 * at the scene's), named at the key that set the refused field. */
static ms_status check_sim(ms_scene_ctx *c, ms_scene *sc)
{
    static const char *const map[][3] = {
        {"field_nx", "volume", "field"},
        {"field_ny", "volume", "field"},
        {"surface_substeps", "coupling", "n_time"},
        {"couple_surface_from_volume", "coupling", "surface_from_volume"},
        {"couple_volume_from_surface", "coupling", "volume_from_surface"},
        {"threads", NULL, "threads"},
    };
    sc->sim.volume = sc->has_volume ? &sc->volume : NULL;
    sc->sim.surface = sc->has_surface ? &sc->surface : NULL;
    ms_status st = ms_sim_desc_check(&sc->sim);
    if (st == MS_OK)
        return MS_OK;
    const char *field = ms_last_error_key();
    for (size_t i = 0; i < sizeof map / sizeof map[0]; ++i)
        if (strcmp(field, map[i][0]) == 0)
            return refused_at(c, st, map[i][1], map[i][2]);
    return refused_at(c, st, NULL, NULL);
}

static ms_status read_obstacles(ms_scene_ctx *c, json_t *root, ms_scene *sc)
{
    json_t *a;
    MS_TRY(ms_scene_get_array(c, root, "obstacles", 0, MS_SCENE_MAX_OBSTACLES, &a));
    if (!a || json_array_size(a) == 0)
        return MS_OK;
    size_t n = json_array_size(a);
    sc->obstacles = ms_alloc_array(n, sizeof *sc->obstacles);
    if (!sc->obstacles)
        return ms_fail(MS_ERR_OUT_OF_MEMORY, "scene: out of memory for %zu obstacles", n);
    ms_scene_push_key(c, "obstacles");
    for (size_t i = 0; i < n; ++i) {
        json_t *o = json_array_get(a, i);
        ms_scene_push_index(c, (long)i);
        if (!json_is_object(o))
            return ms_scene_fail(c, MS_ERR_PARSE,
                                 "is not an object; allowed: {\"shape\": name, \"params\": {...}, "
                                 "\"position\": [x, y, z], ...}");
        sc->nobstacles = (int)i + 1; /* so destroy frees what read_shape made */
        MS_TRY(ms_scene_read_shape(c, o, &sc->obstacles[i]));
        ms_scene_pop(c);
    }
    ms_scene_pop(c);
    return MS_OK;
}

ms_status ms_scene_read_sections(ms_scene_ctx *c, json_t *root, ms_scene *sc, const char *dir,
                                 const char *default_name)
{
    static const char *const keys[] = {"name", "duration", "frame_dt", "seed", "threads", "domain",
                                       "volume", "surface", "coupling", "obstacles", "effects",
                                       "render", "output",
                                       /* --set overrides (override.c) */
                                       "overrides", NULL};
    const char *name;
    long seed;
    if (!json_is_object(root))
        return ms_scene_fail(c, MS_ERR_PARSE,
                             "is not a JSON object; allowed: a scene {\"name\": ..., ...}");
    MS_TRY(ms_scene_check_keys(c, root, keys));
    MS_TRY(ms_scene_get_string(c, root, "name", default_name, &name));
    if (strlen(name) > 256) {
        ms_scene_push_key(c, "name");
        return ms_scene_fail(c, MS_ERR_INVALID_ARGUMENT,
                             "is %zu bytes long; allowed: at most 256 bytes", strlen(name));
    }
    /* the name is printed (check, run's progress, the viewer's title and
     * its log's header line): a control character would reach a terminal
     * raw (an escape sequence retitles or clears it) or break the log's
     * lines */
    for (const unsigned char *p = (const unsigned char *)name; *p; ++p)
        if (*p < 0x20 || *p == 0x7f) {
            ms_scene_push_key(c, "name");
            return ms_scene_fail(c, MS_ERR_INVALID_ARGUMENT,
                                 "holds the control character 0x%02x at byte %td; allowed: "
                                 "printable text",
                                 *p, (const char *)p - name);
        }
    sc->name = ms_strdup(name);
    if (!sc->name)
        return ms_fail(MS_ERR_OUT_OF_MEMORY, "scene: out of memory");
    MS_TRY(ms_scene_get_number(c, root, "duration", 5, 0, 1e6, 1, "s", &sc->duration));
    MS_TRY(ms_scene_get_float(c, root, "frame_dt", 1.0 / 60, 0, 1, 1, "s", &sc->frame_dt));
    MS_TRY(ms_scene_get_int(c, root, "seed", 1, 0, 9007199254740992L, &seed));
    sc->seed = (uint64_t)seed;
    /* the sim desc over ms_sim_desc_default(), but for threads: a scene
     * is run by the tool, which splits the frame over two cores unless the
     * scene says 1 (the desc's default 1 suits an engine that starts no
     * threads of its own); 1 and 2 give the same bytes */
    sc->sim = ms_sim_desc_default();
    sc->sim.threads = 2;
    MS_TRY(get_int_field(c, root, "threads", &sc->sim.threads));
    MS_TRY(read_domain(c, root, sc));
    MS_TRY(read_volume(c, root, sc));
    MS_TRY(read_surface(c, root, sc));
    if (!sc->has_volume && !sc->has_surface)
        return ms_scene_fail(c, MS_ERR_INVALID_ARGUMENT,
                             "has neither a \"volume\" nor a \"surface\" section; allowed: a "
                             "scene with at least one of them");
    MS_TRY(read_coupling(c, root, sc));
    MS_TRY(check_sim(c, sc));
    MS_TRY(read_obstacles(c, root, sc));
    MS_TRY(ms_scene_read_effects(c, root, sc));
    MS_TRY(ms_scene_read_render(c, root, sc, dir));
    MS_TRY(ms_scene_read_output(c, root, sc));
    /* the --set overrides a scene was made with: kept as information */
    json_t *ovr = NULL;
    MS_TRY(ms_scene_get_array(c, root, "overrides", 0, 4096, &ovr));
    for (size_t i = 0; ovr && i < json_array_size(ovr); ++i)
        if (!json_is_string(json_array_get(ovr, i))) {
            ms_scene_push_key(c, "overrides");
            ms_scene_push_index(c, (long)i);
            return ms_scene_fail(c, MS_ERR_PARSE, "is not a string; allowed: KEY=VALUE strings");
        }
    return MS_OK;
}
