/* ms_renderer_draw: the sim's combined field (ms_sim_height over
 * ms_sim_field_grid's MS_FIELD_COMBINED grid) at the fields' time, with
 * the sim's floaters (the paper's leaves) and the scene's boat as discs. */
#include <string.h>

#include "core/internal.h"
#include "modesplit/sim.h"
#include "render/render_internal.h"
#include "scene/scene_internal.h"

#define PART "render"

/* Linear RGB of the floating things. */
static const float leaf_color[3] = {0.45f, 0.30f, 0.08f}, boat_color[3] = {0.80f, 0.78f, 0.72f};

/* The field's height (m above the floor) at world (x, y), bilinear,
 * clamped to the grid. */
static float height_at(const float *h, const ms_grid *g, float x, float y)
{
    float u = (x - g->origin[0]) / g->dx - 0.5f, v = (y - g->origin[1]) / g->dy - 0.5f;
    u = MS_CLAMP(u, 0.0f, (float)(g->nx - 1));
    v = MS_CLAMP(v, 0.0f, (float)(g->ny - 1));
    int i = MS_MIN((int)u, g->nx - 2), j = MS_MIN((int)v, g->ny - 2);
    float fu = u - (float)i, fv = v - (float)j;
    const float *a = h + (size_t)j * (size_t)g->nx + (size_t)i, *b = a + g->nx;
    return (1 - fv) * ((1 - fu) * a[0] + fu * a[1]) + fv * ((1 - fu) * b[0] + fu * b[1]);
}

/* The discs of nf floaters at xyz and of the scene's boat (if any) at
 * time t. */
static ms_status scene_discs(ms_renderer *r, const ms_scene *sc, const float *xyz, int nf,
                             double t, const float *h, const ms_grid *g)
{
    const ms_renderer_desc *d = &r->desc;
    const float side = MS_MIN(d->pool_max[0] - d->pool_min[0], d->pool_max[1] - d->pool_min[1]);
    const int boat = sc && sc->has_boat && sc->boat_path.npoints > 0;
    int n = MS_MIN(nf, MS_RENDER_MAX_DISCS - boat) + boat;
    if (n == 0)
        return r->ndiscs ? ms_renderer_set_discs(r, NULL, 0) : MS_OK;
    ms_render_disc *discs = ms_alloc_array((size_t)n, sizeof *discs);
    if (!discs)
        return ms_fail(MS_ERR_OUT_OF_MEMORY, "render: out of memory for %d floaters", n);
    int k = 0;
    for (; k < n - boat; ++k) {
        memcpy(discs[k].pos, xyz + 3 * k, sizeof discs[k].pos);
        discs[k].radius = 0.015f * side; /* a leaf: 3 cm across in a 1 m pool */
        memcpy(discs[k].color, leaf_color, sizeof leaf_color);
    }
    if (boat) {
        float pos[3] = {0, 0, 0}, vel[3];
        ms_scene_motion_eval(&sc->boat_path, t, pos, vel);
        discs[k].pos[0] = pos[0];
        discs[k].pos[1] = pos[1];
        discs[k].pos[2] = d->pool_min[2] + height_at(h, g, pos[0], pos[1]);
        discs[k].radius = sc->boat_radius;
        memcpy(discs[k].color, boat_color, sizeof boat_color);
    }
    ms_status st = ms_renderer_set_discs(r, discs, n);
    ms_free(discs);
    return st;
}

ms_status ms_renderer_draw(ms_renderer *r, const ms_sim *sim)
{
    ms_status st;
    if ((st = ms_check_not_null(PART, "renderer", r)) != MS_OK ||
        (st = ms_check_not_null(PART, "sim", sim)) != MS_OK)
        return st;
    int nx = 0, ny = 0;
    const float *h = ms_sim_height(sim, &nx, &ny);
    if (!h)
        return ms_fail(MS_ERR_STATE, "render: the sim has no field to draw yet; step it first");
    ms_grid g;
    if ((st = ms_sim_field_grid(sim, MS_FIELD_COMBINED, &g)) != MS_OK)
        return st;
    if (g.nx != nx || g.ny != ny)
        return ms_fail(MS_ERR_STATE, "render: the sim's field is %d x %d but its grid %d x %d",
                       nx, ny, g.nx, g.ny);
    int nf = 0;
    const float *xyz = ms_sim_floaters(sim, &nf);
    if ((st = scene_discs(r, ms_sim_scene(sim), xyz, nf, ms_sim_time(sim), h, &g)) != MS_OK)
        return st;
    return ms_renderer_draw_field(r, h, &g, ms_sim_time(sim));
}

ms_status ms_renderer_draw_scene_field(ms_renderer *r, const ms_scene *sc, const float *h,
                                       const ms_grid *g, double time)
{
    ms_status st;
    if ((st = ms_check_not_null(PART, "renderer", r)) != MS_OK ||
        (st = ms_check_not_null(PART, "scene", sc)) != MS_OK ||
        (st = ms_check_not_null(PART, "height field", h)) != MS_OK ||
        (st = ms_check_not_null(PART, "grid", g)) != MS_OK ||
        (st = ms_check_finite(PART, "time", time)) != MS_OK ||
        (st = ms_check_int_range(PART, "grid nx", g->nx, 2, 16384)) != MS_OK ||
        (st = ms_check_int_range(PART, "grid ny", g->ny, 2, 16384)) != MS_OK)
        return st;
    if ((st = scene_discs(r, sc, NULL, 0, time, h, g)) != MS_OK)
        return st;
    return ms_renderer_draw_field(r, h, g, time);
}
