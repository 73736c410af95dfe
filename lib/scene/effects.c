/* The scene's "effects" section (rain, boat, drops, floaters, drag,
 * container, spray): what the sim adds to the flow beside the two solvers. The
 * same table as data/scenes/README.md's effects; keep both in step. An
 * effect that is absent leaves its has_* flag 0 and costs nothing.
 */
#include <string.h>

#include "core/core_internal.h"
#include "scene/reader.h"
#include "scene/scene_internal.h"
#include "scene/sections.h"

#define BIG MS_SCENE_BIG

static ms_status read_rain(ms_scene_ctx *c, json_t *fx, ms_scene *sc)
{
    static const char *const keys[] = {"rate", "radius", "amplitude", NULL};
    json_t *o;
    MS_TRY(ms_scene_get_object(c, fx, "rain", &o));
    if (!o)
        return MS_OK;
    sc->has_rain = 1;
    ms_scene_push_key(c, "rain");
    MS_TRY(ms_scene_check_keys(c, o, keys));
    sc->rain = ms_rain_default();
    MS_TRY(ms_scene_get_float(c, o, "rate", 20, 0, 1e6, 0, "drops/(m^2 s)", &sc->rain.rate));
    MS_TRY(ms_scene_get_float(c, o, "radius", 0.01, 0, 100, 1, "m", &sc->rain.radius));
    MS_TRY(ms_scene_get_float(c, o, "amplitude", -0.002, -10, 10, 0, "m", &sc->rain.amplitude));
    ms_scene_pop(c);
    if (sc->rain.rate == 0)
        sc->has_rain = 0; /* rate 0: no rain, no random numbers drawn */
    return MS_OK;
}

static ms_status read_boat(ms_scene_ctx *c, json_t *fx, ms_scene *sc)
{
    static const char *const keys[] = {"path", "radius", "depth", NULL};
    json_t *o;
    MS_TRY(ms_scene_get_object(c, fx, "boat", &o));
    if (!o)
        return MS_OK;
    sc->has_boat = 1;
    ms_scene_push_key(c, "boat");
    MS_TRY(ms_scene_check_keys(c, o, keys));
    MS_TRY(ms_scene_require(c, o, "path", "{\"points\": [[x, y], ...], \"speed\": m/s}"));
    MS_TRY(ms_scene_read_path(c, o, "path", 2, &sc->boat_path));
    MS_TRY(ms_scene_get_float(c, o, "radius", 0.05, 0, 100, 1, "m", &sc->boat_radius));
    MS_TRY(ms_scene_get_float(c, o, "depth", 0.02, -10, 10, 0, "m", &sc->boat_depth));
    ms_scene_pop(c);
    return MS_OK;
}

static ms_status read_drops(ms_scene_ctx *c, json_t *fx, ms_scene *sc)
{
    static const char *const keys[] = {"at", "time", "radius", "amplitude", NULL};
    json_t *a;
    MS_TRY(ms_scene_get_array(c, fx, "drops", 0, MS_SCENE_MAX_DROPS, &a));
    if (!a || json_array_size(a) == 0)
        return MS_OK;
    size_t n = json_array_size(a);
    sc->drops = ms_alloc_array(n, sizeof *sc->drops);
    if (!sc->drops)
        return ms_fail(MS_ERR_OUT_OF_MEMORY, "scene: out of memory for %zu drops", n);
    ms_scene_push_key(c, "drops");
    for (size_t i = 0; i < n; ++i) {
        json_t *o = json_array_get(a, i);
        ms_scene_drop *d = &sc->drops[i];
        float at[2];
        ms_scene_push_index(c, (long)i);
        if (!json_is_object(o))
            return ms_scene_fail(c, MS_ERR_PARSE,
                                 "is not an object; allowed: {\"at\": [x, y], \"time\": s, "
                                 "\"radius\": m, \"amplitude\": m}");
        MS_TRY(ms_scene_check_keys(c, o, keys));
        MS_TRY(ms_scene_require(c, o, "at", "[x, y] in m"));
        MS_TRY(ms_scene_get_vec(c, o, "at", 2, NULL, -BIG, BIG, "m", at));
        MS_TRY(ms_scene_get_float(c, o, "time", 0, 0, 1e6, 0, "s", &d->time));
        MS_TRY(ms_scene_get_float(c, o, "radius", 0.03, 0, 100, 1, "m", &d->radius));
        MS_TRY(ms_scene_get_float(c, o, "amplitude", 0.01, -10, 10, 0, "m", &d->amplitude));
        d->x = at[0];
        d->y = at[1];
        ms_scene_pop(c);
    }
    sc->ndrops = (int)n;
    ms_scene_pop(c);
    return MS_OK;
}

static ms_status read_floaters(ms_scene_ctx *c, json_t *fx, ms_scene *sc)
{
    static const char *const keys[] = {"count", "region", "positions", "drag", "slope", NULL};
    json_t *o, *region, *pos;
    long count;
    MS_TRY(ms_scene_get_object(c, fx, "floaters", &o));
    if (!o)
        return MS_OK;
    sc->has_floaters = 1;
    ms_scene_push_key(c, "floaters");
    MS_TRY(ms_scene_check_keys(c, o, keys));
    MS_TRY(ms_scene_get_int(c, o, "count", 16, 1, MS_SCENE_MAX_FLOATERS, &count));
    MS_TRY(ms_scene_get_float(c, o, "drag", 4, 0, 1e3, 1, "1/s", &sc->floater_drag));
    MS_TRY(ms_scene_get_float(c, o, "slope", 1, 0, 100, 0, "", &sc->floater_slope));
    MS_TRY(ms_scene_get_array(c, o, "positions", 1, MS_SCENE_MAX_FLOATERS, &pos));
    float lo[2] = {sc->domain_min[0], sc->domain_min[1]};
    float hi[2] = {sc->domain_max[0], sc->domain_max[1]};
    MS_TRY(ms_scene_get_object(c, o, "region", &region));
    if (region) {
        static const char *const rkeys[] = {"min", "max", NULL};
        ms_scene_push_key(c, "region");
        MS_TRY(ms_scene_check_keys(c, region, rkeys));
        MS_TRY(ms_scene_get_vec(c, region, "min", 2, lo, -BIG, BIG, "m", lo));
        MS_TRY(ms_scene_get_vec(c, region, "max", 2, hi, -BIG, BIG, "m", hi));
        for (int k = 0; k < 2; ++k)
            if (lo[k] < sc->domain_min[k] || hi[k] > sc->domain_max[k] || !(hi[k] >= lo[k])) {
                ms_scene_push_key(c, "max");
                return ms_scene_fail(c, MS_ERR_INVALID_ARGUMENT,
                                     "and min give [%g, %g] m on axis %d; allowed: min <= max, "
                                     "inside the domain [%g, %g] m",
                                     lo[k], hi[k], k, sc->domain_min[k], sc->domain_max[k]);
            }
        ms_scene_pop(c);
    }
    if (pos)
        count = (long)json_array_size(pos);
    sc->floater_xy = ms_alloc_array((size_t)count * 2, sizeof *sc->floater_xy);
    if (!sc->floater_xy)
        return ms_fail(MS_ERR_OUT_OF_MEMORY, "scene: out of memory for %ld floaters", count);
    if (pos) {
        ms_scene_push_key(c, "positions");
        for (long i = 0; i < count; ++i) {
            float *xy = sc->floater_xy + 2 * i;
            ms_scene_push_index(c, i);
            MS_TRY(ms_scene_read_vec(c, json_array_get(pos, (size_t)i), 2, -BIG, BIG, "m", xy));
            for (int k = 0; k < 2; ++k)
                if (xy[k] < sc->domain_min[k] || xy[k] > sc->domain_max[k])
                    return ms_scene_fail(c, MS_ERR_INVALID_ARGUMENT,
                                         "[%d] = %g m lies outside the domain; allowed: [%g, %g] m",
                                         k, xy[k], sc->domain_min[k], sc->domain_max[k]);
            ms_scene_pop(c);
        }
        ms_scene_pop(c);
    } else {
        /* spread from the scene's seed, so the same scene gives the same start */
        ms_rng r;
        ms_rng_seed(&r, sc->seed ^ 0x666c6f6174657273ull); /* "floaters" */
        for (long i = 0; i < count; ++i) {
            sc->floater_xy[2 * i] = lo[0] + (hi[0] - lo[0]) * ms_rng_uniform(&r);
            sc->floater_xy[2 * i + 1] = lo[1] + (hi[1] - lo[1]) * ms_rng_uniform(&r);
        }
    }
    sc->nfloaters = (int)count;
    ms_scene_pop(c);
    return MS_OK;
}

static ms_status read_drag(ms_scene_ctx *c, json_t *fx, ms_scene *sc)
{
    static const char *const keys[] = {"path", "radius", "depth", "strength", NULL};
    json_t *o;
    MS_TRY(ms_scene_get_object(c, fx, "drag", &o));
    if (!o)
        return MS_OK;
    sc->has_drag = 1;
    ms_scene_push_key(c, "drag");
    MS_TRY(ms_scene_check_keys(c, o, keys));
    MS_TRY(ms_scene_require(c, o, "path", "{\"points\": [[x, y], ...], \"speed\": m/s}"));
    MS_TRY(ms_scene_read_path(c, o, "path", 2, &sc->drag_path));
    MS_TRY(ms_scene_get_float(c, o, "radius", 0.1, 0, 100, 1, "m", &sc->drag_radius));
    MS_TRY(ms_scene_get_float(c, o, "depth", 0.05, 0, 100, 0, "m", &sc->drag_depth));
    MS_TRY(ms_scene_get_float(c, o, "strength", 10, 0, 1e4, 1, "1/s", &sc->drag_strength));
    ms_scene_pop(c);
    return MS_OK;
}

static ms_status read_container(ms_scene_ctx *c, json_t *fx, ms_scene *sc)
{
    json_t *o;
    MS_TRY(ms_scene_get_object(c, fx, "container", &o));
    if (!o)
        return MS_OK;
    sc->has_container = 1;
    ms_scene_push_key(c, "container");
    MS_TRY(ms_scene_read_shape(c, o, &sc->container));
    ms_scene_pop(c);
    return MS_OK;
}

/* A ramp [lo, hi] of an emission potential: both in [0, max], lo < hi. */
static ms_status get_ramp(ms_scene_ctx *c, json_t *o, const char *key, float lo, float hi,
                          double max, const char *unit, float *out)
{
    const float def[2] = {lo, hi};
    MS_TRY(ms_scene_get_vec(c, o, key, 2, def, 0, max, unit, out));
    if (out[0] < out[1])
        return MS_OK;
    ms_scene_push_key(c, key);
    ms_status st = ms_scene_fail(c, MS_ERR_INVALID_ARGUMENT,
                                 "[%g, %g] is no ramp; allowed: [lo, hi] with lo < hi",
                                 (double)out[0], (double)out[1]);
    ms_scene_pop(c);
    return st;
}

/* Spray and foam (lib/sim/spray.c owns what they do; the defaults and
 * ranges are here, as for every effect). The defaults fit the scenes'
 * scale (decimetres, splashes of 0.5 to 2 m/s): a particle starts to emit
 * above 0.4 m/s (0.08 J/kg) and emits fully at 1.4 m/s (1 J/kg); the
 * trapped-air and wave-crest ramps start at 0.2 and 0.15 m/s. A pool at
 * rest keeps below 0.1 m/s (0.005 J/kg) and emits nothing. */
static ms_status read_spray(ms_scene_ctx *c, json_t *fx, ms_scene *sc)
{
    static const char *const keys[] = {"budget", "kinetic",  "trapped_air", "wave_crest",
                                       "rate",   "lifetime", "foam",        NULL};
    static const float rate[2] = {400, 400};
    json_t *o;
    long budget;
    MS_TRY(ms_scene_get_object(c, fx, "spray", &o));
    if (!o)
        return MS_OK;
    sc->has_spray = 1;
    ms_scene_push_key(c, "spray");
    MS_TRY(ms_scene_check_keys(c, o, keys));
    MS_TRY(ms_scene_get_int(c, o, "budget", 4096, 1, MS_SCENE_MAX_SPRAY, &budget));
    sc->spray_budget = (int)budget;
    MS_TRY(get_ramp(c, o, "kinetic", 0.08f, 1.0f, 1e6, "J/kg", sc->spray_kinetic));
    MS_TRY(get_ramp(c, o, "trapped_air", 0.2f, 1.0f, 1e3, "m/s", sc->spray_trapped_air));
    MS_TRY(get_ramp(c, o, "wave_crest", 0.15f, 0.8f, 1e3, "m/s", sc->spray_wave_crest));
    MS_TRY(ms_scene_get_vec(c, o, "rate", 2, rate, 0, 1e4, "1/s", sc->spray_rate));
    MS_TRY(ms_scene_get_float(c, o, "lifetime", 3, 0, 600, 1, "s", &sc->foam_lifetime));
    MS_TRY(ms_scene_get_float(c, o, "foam", 0.04, 0, 1, 0, "", &sc->foam_deposit));
    ms_scene_pop(c);
    return MS_OK;
}

ms_status ms_scene_read_effects(ms_scene_ctx *c, json_t *root, ms_scene *sc)
{
    static const char *const keys[] = {"rain", "boat",      "drops", "floaters",
                                       "drag", "container", "spray", NULL};
    json_t *fx;
    MS_TRY(ms_scene_get_object(c, root, "effects", &fx));
    if (!fx)
        return MS_OK;
    ms_scene_push_key(c, "effects");
    MS_TRY(ms_scene_check_keys(c, fx, keys));
    MS_TRY(read_rain(c, fx, sc));
    MS_TRY(read_boat(c, fx, sc));
    MS_TRY(read_drops(c, fx, sc));
    MS_TRY(read_floaters(c, fx, sc));
    MS_TRY(read_drag(c, fx, sc));
    MS_TRY(read_container(c, fx, sc));
    MS_TRY(read_spray(c, fx, sc));
    if (sc->has_spray && !sc->has_volume) {
        ms_scene_push_key(c, "spray");
        return ms_scene_fail(c, MS_ERR_INVALID_ARGUMENT,
                             "needs a \"volume\" section (the SPH particles emit it); allowed: "
                             "only in scenes with a volume");
    }
    /* effects that live on the wave field need one */
    static const char *const surface_fx[] = {"rain", "boat", "drops", NULL};
    for (const char *const *k = surface_fx; *k && !sc->has_surface; ++k) {
        if (json_object_get(fx, *k)) {
            ms_scene_push_key(c, *k);
            return ms_scene_fail(c, MS_ERR_INVALID_ARGUMENT,
                                 "needs a \"surface\" section (it makes waves); allowed: "
                                 "only in scenes with a surface");
        }
    }
    ms_scene_pop(c);
    return MS_OK;
}
