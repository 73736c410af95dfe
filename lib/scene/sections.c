/* The scene schema: every key of the top level and of the domain, volume,
 * surface, coupling and obstacles sections, its type, unit, default and
 * range (the same table as data/scenes/README.md; keep both in step); the
 * effects, render and output sections are read by effects.c,
 * section_render.c and section_output.c.
 * A section that is absent leaves its has_* flag 0: the effect is not
 * simulated and costs nothing.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/core_internal.h"
#include "modesplit/plugin.h"
#include "modesplit/shape.h"
#include "plugin/plugin_internal.h"
#include "scene/reader.h"
#include "scene/scene_internal.h"
#include "scene/sections.h"

#define BIG MS_SCENE_BIG
#define MAX_SPEED MS_SCENE_MAX_SPEED
#define MAX_PARTICLES 10000000L

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
    char *text = params ? json_dumps(params, JSON_COMPACT) : NULL; /* malloc'ed by jansson */
    s->params_json = ms_strdup(text ? text : "{}");
    free(text);
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

/* DFSPH's stop rule and iteration caps, in the desc's ranges
 * (volume/desc.c). Under the weakly compressible laws they would do
 * nothing, so a scene that sets one there is refused rather than run as if
 * it had been heard. */
static ms_status read_dfsph_limits(ms_scene_ctx *c, json_t *o, ms_scene *sc)
{
    static const char *const limits[] = {"max_density_error", "max_divergence_error",
                                         "max_density_iterations", "max_divergence_iterations"};
    long dens_it, div_it;
    MS_TRY(ms_scene_get_float(c, o, "max_density_error", NAN, 0, 0.1, 1, "",
                              &sc->volume.max_density_error));
    MS_TRY(ms_scene_get_float(c, o, "max_divergence_error", NAN, 0, 0.1, 1, "",
                              &sc->volume.max_divergence_error));
    MS_TRY(ms_scene_get_int(c, o, "max_density_iterations", -1, 1, 10000, &dens_it));
    MS_TRY(ms_scene_get_int(c, o, "max_divergence_iterations", -1, 0, 10000, &div_it));
    sc->volume.max_density_iterations = (int)dens_it;
    sc->volume.max_divergence_iterations = (int)div_it;
    if (sc->volume.pressure == MS_PRESSURE_DFSPH)
        return MS_OK;
    for (size_t k = 0; k < sizeof limits / sizeof limits[0]; ++k)
        if (json_object_get(o, limits[k])) {
            ms_scene_push_key(c, limits[k]);
            ms_status st = ms_scene_fail(c, MS_ERR_INVALID_ARGUMENT,
                                         "is a limit of the \"dfsph\" pressure solver; "
                                         "allowed only with volume.pressure \"dfsph\"");
            ms_scene_pop(c);
            return st;
        }
    return MS_OK;
}

static ms_status read_volume(ms_scene_ctx *c, json_t *root, ms_scene *sc)
{
    static const char *const keys[] = {"spacing",
                                       "smoothing_length",
                                       "rest_density",
                                       "gas_constant",
                                       "viscosity",
                                       "gravity",
                                       "pressure",
                                       "max_particles",
                                       "fill",
                                       "field",
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
    static const char *const pressures[] = {"ideal_gas", "tait", "dfsph", NULL};
    static const float g[3] = {0, 0, -9.81f};
    json_t *o;
    long maxp;
    int pressure, field[2] = {0, 0};
    MS_TRY(ms_scene_get_object(c, root, "volume", &o));
    if (!o)
        return MS_OK;
    sc->has_volume = 1;
    float ext = MS_MIN(
        sc->domain_max[0] - sc->domain_min[0],
        MS_MIN(sc->domain_max[1] - sc->domain_min[1], sc->domain_max[2] - sc->domain_min[2]));
    ms_scene_push_key(c, "volume");
    MS_TRY(ms_scene_check_keys(c, o, keys));
    MS_TRY(ms_scene_get_float(c, o, "spacing", 0.04, 0, ext, 1, "m", &sc->volume.spacing));
    /* NAN: the volume solver's default ratio h / spacing (see sim/create.c) */
    MS_TRY(ms_scene_get_float(c, o, "smoothing_length", NAN, sc->volume.spacing,
                              4 * sc->volume.spacing, 0, "m", &sc->volume.smoothing_length));
    MS_TRY(ms_scene_get_float(c, o, "rest_density", 1000, 0, 1e5, 1, "kg/m^3",
                              &sc->volume.rest_density));
    MS_TRY(ms_scene_get_float(c, o, "gas_constant", NAN, 0, 1e7, 1, "m^2/s^2",
                              &sc->volume.gas_constant));
    MS_TRY(ms_scene_get_float(c, o, "viscosity", NAN, 0, 1e4, 0, "Pa s", &sc->volume.viscosity));
    MS_TRY(ms_scene_get_vec(c, o, "gravity", 3, g, -1e3, 1e3, "m/s^2", sc->volume.gravity));
    MS_TRY(ms_scene_get_enum(c, o, "pressure", pressures, 0, &pressure));
    sc->volume.pressure = (ms_pressure)pressure;
    MS_TRY(ms_scene_get_int(c, o, "max_particles", 0, 0, MAX_PARTICLES, &maxp));
    sc->volume.max_particles = (int)maxp;
    /* NAN / 0 / -1: the volume solver's default (see sim/create.c) */
    long maxsub, vthreads, smooth;
    MS_TRY(ms_scene_get_float(c, o, "sound_speed", NAN, 0, 1e4, 1, "m/s", &sc->volume.sound_speed));
    MS_TRY(ms_scene_get_float(c, o, "courant", NAN, 0, 0.5, 1, "", &sc->volume.courant));
    MS_TRY(ms_scene_get_int(c, o, "max_substeps", 0, 1, 10000000, &maxsub));
    MS_TRY(ms_scene_get_int(c, o, "threads", 0, 1, 64, &vthreads));
    MS_TRY(ms_scene_get_int(c, o, "smooth_steps", -1, 0, 64, &smooth));
    MS_TRY(ms_scene_get_float(c, o, "smooth_energy", NAN, 0, 1e6, 1, "J/kg",
                              &sc->volume.smooth_energy));
    sc->volume.max_substeps = (int)maxsub;
    sc->volume.threads = (int)vthreads;
    sc->volume.smooth_steps = (int)smooth;
    MS_TRY(read_dfsph_limits(c, o, sc));
    MS_TRY(ms_scene_get_ivec(c, o, "field", 2, field, 2, 4096, field));
    sc->field_nx = field[0];
    sc->field_ny = field[1];
    double count = 0;
    MS_TRY(read_fill(c, o, sc, &count));
    if (sc->volume.max_particles != 0 && count > sc->volume.max_particles) {
        ms_scene_push_key(c, "max_particles");
        ms_status st = ms_scene_fail(c, MS_ERR_INVALID_ARGUMENT,
                                     "%d is below the %.0f particles volume.fill makes; allowed: "
                                     "0 (as many as the fill makes) or at least %.0f",
                                     sc->volume.max_particles, count, count);
        ms_scene_pop(c);
        return st;
    }
    ms_scene_pop(c);
    return MS_OK;
}

static ms_status read_surface(ms_scene_ctx *c, json_t *root, ms_scene *sc)
{
    static const char *const keys[] = {"cells",        "wave_speed", "damping", "boundary",
                                       "max_substeps", "level",      "model",   NULL};
    static const char *const boundaries[] = {"reflect", "absorb", "periodic", NULL};
    /* in the order of ms_surface_model; the default is the desc's */
    static const char *const models[] = {"wave", "dispersive", NULL};
    static const int cells_def[2] = {256, 256};
    json_t *o;
    int cells[2], boundary, model;
    long maxsub;
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
    MS_TRY(ms_scene_get_ivec(c, o, "cells", 2, cells_def, 2, 16384, cells));
    MS_TRY(ms_scene_get_float(c, o, "wave_speed", 0.5, 0, MAX_SPEED, 1, "m/s",
                              &sc->surface.wave_speed));
    MS_TRY(ms_scene_get_float(c, o, "damping", 0.9, 0, 1, 1, "", &sc->surface.damping));
    MS_TRY(ms_scene_get_enum(c, o, "boundary", boundaries, 0, &boundary));
    MS_TRY(ms_scene_get_int(c, o, "max_substeps", 100000, 1, 10000000, &maxsub));
    MS_TRY(ms_scene_get_float(c, o, "level", level, 0, height, 0, "m", &sc->level));
    MS_TRY(ms_scene_get_enum(c, o, "model", models, (int)ms_surface_desc_default().model, &model));
    sc->surface.model = (ms_surface_model)model;
    sc->surface.nx = cells[0];
    sc->surface.ny = cells[1];
    sc->surface.boundary = (ms_boundary)boundary;
    sc->surface.max_substeps = (int)maxsub;
    double dx = (double)(sc->domain_max[0] - sc->domain_min[0]) / cells[0];
    double dy = (double)(sc->domain_max[1] - sc->domain_min[1]) / cells[1];
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
    sc->surface.dx = (float)dx;
    ms_scene_pop(c);
    return MS_OK;
}

static ms_status read_coupling(ms_scene_ctx *c, json_t *root, ms_scene *sc)
{
    static const char *const keys[] = {"n_time", "surface_from_volume", "volume_from_surface",
                                       NULL};
    json_t *o;
    long n_time;
    MS_TRY(ms_scene_get_object(c, root, "coupling", &o));
    if (!o)
        return MS_OK;
    ms_scene_push_key(c, "coupling");
    MS_TRY(ms_scene_check_keys(c, o, keys));
    MS_TRY(ms_scene_get_int(c, o, "n_time", 0, 0, 100000, &n_time));
    sc->n_time = (int)n_time;
    MS_TRY(ms_scene_get_float(c, o, "surface_from_volume", 0, 0, 0.25f, 0, "",
                              &sc->couple_surface_from_volume));
    MS_TRY(ms_scene_get_float(c, o, "volume_from_surface", 0, 0, 1, 0, "",
                              &sc->couple_volume_from_surface));
    ms_scene_pop(c);
    return MS_OK;
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
    long seed, threads;
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
    sc->name = ms_strdup(name);
    if (!sc->name)
        return ms_fail(MS_ERR_OUT_OF_MEMORY, "scene: out of memory");
    MS_TRY(ms_scene_get_number(c, root, "duration", 5, 0, 1e6, 1, "s", &sc->duration));
    MS_TRY(ms_scene_get_float(c, root, "frame_dt", 1.0 / 60, 0, 1, 1, "s", &sc->frame_dt));
    MS_TRY(ms_scene_get_int(c, root, "seed", 1, 0, 9007199254740992L, &seed));
    sc->seed = (uint64_t)seed;
    MS_TRY(ms_scene_get_int(c, root, "threads", 2, 1, 2, &threads));
    sc->threads = (int)threads;
    MS_TRY(read_domain(c, root, sc));
    MS_TRY(read_volume(c, root, sc));
    MS_TRY(read_surface(c, root, sc));
    if (!sc->has_volume && !sc->has_surface)
        return ms_scene_fail(c, MS_ERR_INVALID_ARGUMENT,
                             "has neither a \"volume\" nor a \"surface\" section; allowed: a "
                             "scene with at least one of them");
    MS_TRY(read_coupling(c, root, sc));
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
