/* ms_renderer_draw: the sim's combined field (ms_sim_height over
 * ms_sim_field_grid's MS_FIELD_COMBINED grid) at the fields' time, with
 * the sim's floaters (the paper's leaves) and the scene's boat as discs,
 * its spray as droplets and its foam on the liquid.
 *
 * For display only, the SPH part of the combined field is reconstructed
 * more smoothly than eq. 20's bilinear up-sampling: the field drawn is
 * combined + (catmull_rom(h_SPH) - bilinear(h_SPH)), both evaluated at the
 * wave cells' centres. Bilinear interpolation has kinks at every SPH cell
 * edge, and the normals' jumps there showed as saw-tooth seams in the
 * refracted floor; Catmull-Rom passes through the same SPH values with a
 * continuous slope. The simulated field is not changed. */
#include <math.h>
#include <string.h>

#include "core/core_internal.h"
#include "modesplit/sim.h"
#include "render/render_internal.h"
#include "scene/scene_internal.h"

#define PART "render"

/* Linear RGB of the floating things. */
static const float leaf_color[3] = {0.45f, 0.30f, 0.08f};

/* Taps of 1D interpolation of a cell-centred coarse row of n values at
 * fine cell centres: for fine index i, coarse coordinate u (clamped to
 * [0, n-1]), i0 = floor(u), t = u - i0. Catmull-Rom minus linear weights
 * for the taps i0-1 .. i0+2 (indices clamped). */
static void smooth_taps(float u, int n, int idx[4], float w[4])
{
    u = MS_CLAMP(u, 0.0f, (float)(n - 1));
    int i0 = MS_MIN((int)u, n - 2);
    float t = u - (float)i0, t2 = t * t, t3 = t2 * t;
    /* Catmull-Rom */
    w[0] = 0.5f * (-t3 + 2 * t2 - t);
    w[1] = 0.5f * (3 * t3 - 5 * t2 + 2) - (1 - t);
    w[2] = 0.5f * (-3 * t3 + 4 * t2 + t) - t;
    w[3] = 0.5f * (t3 - t2);
    for (int k = 0; k < 4; ++k)
        idx[k] = MS_CLAMP(i0 - 1 + k, 0, n - 1);
}

/* Linear taps (for the second axis of the difference). */
static void linear_taps(float u, int n, int idx[2], float w[2])
{
    u = MS_CLAMP(u, 0.0f, (float)(n - 1));
    int i0 = MS_MIN((int)u, n - 2);
    float t = u - (float)i0;
    idx[0] = i0, idx[1] = i0 + 1;
    w[0] = 1 - t, w[1] = t;
}

static float cubic_weight(float t, int k)
{
    float t2 = t * t, t3 = t2 * t;
    switch (k) {
    case 0:
        return 0.5f * (-t3 + 2 * t2 - t);
    case 1:
        return 0.5f * (3 * t3 - 5 * t2 + 2);
    case 2:
        return 0.5f * (-3 * t3 + 4 * t2 + t);
    default:
        return 0.5f * (t3 - t2);
    }
}

/* out = h (combined, grid g) + cubic(v) - bilinear(v), v the SPH field on
 * grid vg. The 2D difference is separable: C(x)C(y) - L(x)L(y) =
 * (C(x) - L(x))C(y) + L(x)(C(y) - L(y)). */
static ms_status smooth_sph_part(ms_renderer *r, const float *h, const ms_grid *g, const float *v,
                                 const ms_grid *vg, const float **out)
{
    const size_t cells = (size_t)g->nx * (size_t)g->ny;
    const size_t need = cells + 4 * (size_t)vg->ny * (size_t)g->nx;
    ms_status st = ms_render_reserve(&r->display, &r->display_cap, need, "the display field");
    if (st != MS_OK)
        return st;
    float *o = r->display;
    /* per coarse row, along x: cubic (cx), cubic - linear (dx), linear (lx) */
    float *cx = o + cells, *dxr = cx + (size_t)vg->ny * g->nx, *lx = dxr + (size_t)vg->ny * g->nx;
    for (int i = 0; i < g->nx; ++i) {
        const float x = g->origin[0] + ((float)i + 0.5f) * g->dx;
        const float u = (x - vg->origin[0]) / vg->dx - 0.5f;
        int ci[4], li[2];
        float dw[4], lw[2];
        smooth_taps(u, vg->nx, ci, dw);
        linear_taps(u, vg->nx, li, lw);
        float uc = MS_CLAMP(u, 0.0f, (float)(vg->nx - 1));
        float t = uc - (float)MS_MIN((int)uc, vg->nx - 2);
        for (int J = 0; J < vg->ny; ++J) {
            const float *row = v + (size_t)J * vg->nx;
            float c = 0, d = 0;
            for (int k = 0; k < 4; ++k) {
                c += cubic_weight(t, k) * row[ci[k]];
                d += dw[k] * row[ci[k]];
            }
            cx[(size_t)J * g->nx + i] = c;
            dxr[(size_t)J * g->nx + i] = d;
            lx[(size_t)J * g->nx + i] = lw[0] * row[li[0]] + lw[1] * row[li[1]];
        }
    }
    for (int j = 0; j < g->ny; ++j) {
        const float y = g->origin[1] + ((float)j + 0.5f) * g->dy;
        const float u = (y - vg->origin[1]) / vg->dy - 0.5f;
        int ci[4];
        float dw[4];
        smooth_taps(u, vg->ny, ci, dw);
        float uc = MS_CLAMP(u, 0.0f, (float)(vg->ny - 1));
        float t = uc - (float)MS_MIN((int)uc, vg->ny - 2);
        float cw[4];
        for (int k = 0; k < 4; ++k)
            cw[k] = cubic_weight(t, k);
        const float *hr = h + (size_t)j * g->nx;
        float *orow = o + (size_t)j * g->nx;
        for (int i = 0; i < g->nx; ++i) {
            float corr = 0;
            for (int k = 0; k < 4; ++k) {
                const size_t at = (size_t)ci[k] * g->nx + (size_t)i;
                corr += cw[k] * dxr[at] + dw[k] * lx[at];
            }
            orow[i] = hr[i] + corr;
        }
    }
    (void)cx;
    *out = o;
    return MS_OK;
}

/* out = h blurred by a separable Gaussian of sigma `sigma` cells (edges
 * replicated), for display only. Without a surface section the extracted
 * SPH field is the whole surface (Fig. 4c), and its cells are finer than
 * the particles' spacing: each column's height jumps with the few
 * particles in it, and those jumps showed as crumpled contour bands in
 * the refracted floor. The paper's SPH surface is "smooth but low in
 * detail": blurring over the particles' spacing draws it so. */
static ms_status blur_field(ms_renderer *r, const float *h, const ms_grid *g, float sigma,
                            const float **out)
{
    const int nx = g->nx, ny = g->ny, rad = MS_MIN((int)ceilf(2.5f * sigma), 32);
    const size_t cells = (size_t)nx * (size_t)ny, need = 2 * cells;
    ms_status st = ms_render_reserve(&r->display, &r->display_cap, need, "the display field");
    if (st != MS_OK)
        return st;
    float w[65], sum = 0;
    for (int k = -rad; k <= rad; ++k)
        sum += w[k + rad] = expf(-0.5f * (float)(k * k) / (sigma * sigma));
    for (int k = 0; k <= 2 * rad; ++k)
        w[k] /= sum;
    float *o = r->display, *tmp = o + cells;
    for (int j = 0; j < ny; ++j)
        for (int i = 0; i < nx; ++i) {
            float a = 0;
            for (int k = -rad; k <= rad; ++k)
                a += w[k + rad] * h[(size_t)j * nx + (size_t)MS_CLAMP(i + k, 0, nx - 1)];
            tmp[(size_t)j * nx + (size_t)i] = a;
        }
    for (int j = 0; j < ny; ++j)
        for (int i = 0; i < nx; ++i) {
            float a = 0;
            for (int k = -rad; k <= rad; ++k)
                a += w[k + rad] * tmp[(size_t)MS_CLAMP(j + k, 0, ny - 1) * nx + (size_t)i];
            o[(size_t)j * nx + (size_t)i] = a;
        }
    *out = o;
    return MS_OK;
}

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
 * time t: at boat_xy when the sim knows where the boat is (steered by
 * hand, ms_sim_steer_boat), else on its path; the bow along its motion. */
static ms_status scene_discs(ms_renderer *r, const ms_scene *sc, const float *xyz, int nf, double t,
                             const float *h, const ms_grid *g, const float *boat_xy)
{
    const ms_renderer_desc *d = &r->desc;
    const float side = MS_MIN(d->pool_max[0] - d->pool_min[0], d->pool_max[1] - d->pool_min[1]);
    const int boat = sc && sc->has_boat && sc->boat_path.npoints > 0;
    if (boat) {
        /* the boat: a hull on its path, its bow along its velocity */
        float pos[3] = {0, 0, 0}, vel[3] = {0, 0, 0};
        ms_scene_motion_eval(&sc->boat_path, t, pos, vel);
        if (boat_xy) {
            if (r->has_boat) { /* heading from where it was drawn last */
                vel[0] = boat_xy[0] - r->boat_pos[0];
                vel[1] = boat_xy[1] - r->boat_pos[1];
            }
            pos[0] = boat_xy[0];
            pos[1] = boat_xy[1];
        }
        float sp = sqrtf(vel[0] * vel[0] + vel[1] * vel[1]);
        if (sp > 1e-6f) {
            r->boat_heading[0] = vel[0] / sp;
            r->boat_heading[1] = vel[1] / sp;
        } else if (!r->has_boat) {
            r->boat_heading[0] = 1, r->boat_heading[1] = 0;
        }
        r->boat_pos[0] = pos[0];
        r->boat_pos[1] = pos[1];
        r->boat_pos[2] = d->pool_min[2] + height_at(h, g, pos[0], pos[1]);
        r->boat_radius = sc->boat_radius;
    }
    if (boat || r->has_boat)
        r->discs_changed = 1;
    r->has_boat = boat;
    if (!xyz)
        return MS_OK; /* no floaters known: the discs set by hand stay */
    int n = MS_MIN(nf, MS_RENDER_MAX_DISCS);
    if (n == 0)
        return r->ndiscs ? ms_renderer_set_discs(r, NULL, 0) : MS_OK;
    ms_render_disc *discs = ms_alloc_array((size_t)n, sizeof *discs);
    if (!discs)
        return ms_fail(MS_ERR_OUT_OF_MEMORY, "render: out of memory for %d floaters", n);
    for (int k = 0; k < n; ++k) {
        memcpy(discs[k].pos, xyz + 3 * k, sizeof discs[k].pos);
        discs[k].radius = 0.015f * side; /* a leaf: 3 cm across in a 1 m pool */
        memcpy(discs[k].color, leaf_color, sizeof leaf_color);
    }
    ms_status st = ms_renderer_set_discs(r, discs, n);
    ms_free(discs);
    if (st == MS_OK)
        r->nleaves = n; /* after set_discs, which counts its discs as plain */
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
        return ms_fail(MS_ERR_STATE, "render: the sim's field is %d x %d but its grid %d x %d", nx,
                       ny, g.nx, g.ny);
    int nf = 0;
    const float *xyz = ms_sim_floaters(sim, &nf);
    float boat_xy[2];
    const ms_scene *sc = ms_sim_scene(sim);
    const int steered = sc && sc->has_boat && ms_sim_boat(sim, boat_xy) == MS_OK;
    if ((st = scene_discs(r, sc, xyz, nf, ms_sim_time(sim), h, &g, steered ? boat_xy : NULL)) !=
            MS_OK ||
        (st = ms_render_objects_update(r, sc, sim, ms_sim_time(sim))) != MS_OK)
        return st;
    /* spray and foam, when the sim throws them (else those set by hand stay) */
    int nspray = 0;
    const float *spray = ms_sim_spray(sim, &nspray);
    ms_grid fg;
    if (spray) {
        ms_sim_info si = ms_sim_info_init();
        ms_sim_get_info(sim, &si);
        if ((st = ms_renderer_set_spray(r, spray, nspray, 0.15f * si.spacing)) != MS_OK ||
            (st = ms_sim_foam_grid(sim, &fg)) != MS_OK ||
            (st = ms_renderer_set_foam(r, ms_sim_foam(sim, NULL, NULL), &fg)) != MS_OK)
            return st;
    }
    /* the SPH part smoothed for display, when it was up-sampled (eq. 20) */
    int vnx = 0, vny = 0;
    const float *v = ms_sim_volume_height(sim, &vnx, &vny);
    ms_grid vg;
    if (v && ms_sim_surface_height(sim, NULL, NULL) && vnx >= 2 && vny >= 2 &&
        (vnx < g.nx || vny < g.ny) && ms_sim_field_grid(sim, MS_FIELD_VOLUME, &vg) == MS_OK &&
        vg.nx == vnx && vg.ny == vny && (st = smooth_sph_part(r, h, &g, v, &vg, &h)) != MS_OK)
        return st;
    /* the SPH field alone: blurred over the particles' spacing */
    ms_sim_info info = ms_sim_info_init();
    ms_sim_get_info(sim, &info);
    if (!ms_sim_surface_height(sim, NULL, NULL) && info.spacing > 0) {
        const float sigma = info.spacing / MS_MIN(g.dx, g.dy);
        if (sigma > 0.5f && (st = blur_field(r, h, &g, sigma, &h)) != MS_OK)
            return st;
    }
    /* the liquid in a glass carried to its inner wall (glass_fill.c) */
    ms_grid sph;
    const float sph_dx = v && ms_sim_field_grid(sim, MS_FIELD_VOLUME, &sph) == MS_OK ? sph.dx : 0;
    if ((st = ms_render_cavity_fill(r, h, &g, sph_dx, &h)) != MS_OK)
        return st;
    st = ms_renderer_draw_field(r, h, &g, ms_sim_time(sim));
    r->cavity.active = 0;
    return st;
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
    if ((st = scene_discs(r, sc, NULL, 0, time, h, g, NULL)) != MS_OK ||
        (st = ms_render_objects_update(r, sc, NULL, time)) != MS_OK)
        return st;
    if ((st = ms_render_cavity_fill(r, h, g, 0.0f, &h)) != MS_OK) /* glass_fill.c */
        return st;
    st = ms_renderer_draw_field(r, h, g, time);
    r->cavity.active = 0;
    return st;
}
