/* The liquid inside the scene's container (a glass), for display only.
 * The simulated fields stay as eqs. 19-20 make them; what is
 * drawn changes:
 *
 * - The fill. The 1 cm SPH field (eqs. 16-18) ends a few mm short of the
 *   glass's inner wall and eq. 20's up-sampling slopes it to the floor
 *   over about a cell, and the wave field has a dip next to the moving
 *   wall; drawn as they are, the water in a glass was a crumpled blob. So
 *   inside the cavity, within `band` of the inner wall, the surface is
 *   carried to the wall: a plane fitted to the liquid's core (the slosh's
 *   tilt) plus the core's ripple at the band's inner edge, fading to the
 *   plane at the wall; blended in over the band's inner half. The same
 *   carried surface continues over the wall, so normals and the mesh's
 *   heights near the wall see no cliff.
 * - The cut. Mesh vertices just outside the inner wall are moved onto it
 *   (at the filled height there) and those over the wall and a little
 *   beyond sink under the floor, where the dry clip (MS_RENDER_DRY_DEPTH)
 *   removes them: the surface ends at the wall, no liquid outside it.
 * - The side. A vertical wall of liquid on the inner wall, from the
 *   cavity's floor up to the filled surface, drawn by the liquid's shader
 *   with its own (horizontal) normal, so the glass is seen filled.
 *
 * The cavity comes from the container's signed distance alone (any shape
 * with a hollow about its local z axis: a glass, a tank): per angle the
 * distance at which the inner wall starts and the outer wall ends. */
#include <math.h>
#include <string.h>

#include "core/core_internal.h"
#include "render/render_internal.h"
#include "scene/scene_internal.h"
#include "shape/shape_internal.h"

#define TWO_PI 6.28318530717958647692f
#define MARCH_STEPS 512 /* steps of the radial search over the shape's extent */
#define BISECT 24
/* The cut: the triangles from a vertex moved onto the inner wall down to
 * one sunk SINK under the floor stand nearly vertical; the dry clip keeps
 * the top MS_RENDER_DRY_DEPTH.. of them, which reach out from the moved
 * vertex by (surface height / SINK) of an edge. Moved SNAP_INSIDE of a
 * vertex spacing inside the wall, that sliver stays inside the column's
 * side, which hides it (it showed as vertical streaks outside the glass). */
#define SINK 10.0f        /* m */
#define SNAP_INSIDE 0.05f /* of the vertex spacing */
#define MAX_TILT_COS 0.9f /* the axis within 26 degrees of vertical */

/* The container's object, or NULL. */
static const ms_render_object *container(const ms_renderer *r)
{
    const ms_scene *sc = r->object_scene;
    if (!sc || !sc->has_container || r->nobjects == 0)
        return NULL;
    const ms_render_object *ob = &r->objects[r->nobjects - 1];
    return ob->spec == &sc->container && ob->nverts > 0 ? ob : NULL;
}

static float dist(const ms_shape *s, float x, float y, float z)
{
    const float q[3] = {x, y, z};
    return ms_shape_distance_local(s, q, NULL);
}

/* The first radius along angle a at local height z where the distance
 * changes sign from `from_outside` (d > 0) to inside (or back), between
 * r0 and rmax; -1 if none. */
static float crossing(const ms_shape *s, float a, float z, float r0, float rmax, int want_inside)
{
    const float ca = cosf(a), sa = sinf(a), step = rmax / MARCH_STEPS;
    float prev = r0;
    for (float rr = r0 + step; rr <= rmax + 0.5f * step; rr += step) {
        const int in = dist(s, rr * ca, rr * sa, z) <= 0;
        if (in == want_inside) {
            float lo = prev, hi = rr;
            for (int k = 0; k < BISECT; ++k) {
                const float mid = 0.5f * (lo + hi);
                if ((dist(s, mid * ca, mid * sa, z) <= 0) == want_inside)
                    hi = mid;
                else
                    lo = mid;
            }
            return 0.5f * (lo + hi);
        }
        prev = rr;
    }
    return -1;
}

/* The cavity's tables for object ob (once per object). */
static void probe(ms_render_cavity *c, const ms_render_object *ob)
{
    c->probed = ob;
    c->found = 0;
    float lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
    for (int v = 0; v < ob->nverts; ++v)
        for (int k = 0; k < 3; ++k) {
            lo[k] = MS_MIN(lo[k], ob->local[6 * (size_t)v + k]);
            hi[k] = MS_MAX(hi[k], ob->local[6 * (size_t)v + k]);
        }
    const ms_shape *s = ob->shape;
    const float z = 0.5f * (lo[2] + hi[2]);
    if (!(hi[2] > lo[2]) || dist(s, 0, 0, z) <= 0)
        return; /* solid on its axis: no cavity */
    const float rmax =
        1.25f * MS_MAX(MS_MAX(fabsf(lo[0]), fabsf(hi[0])), MS_MAX(fabsf(lo[1]), fabsf(hi[1])));
    for (int k = 0; k < MS_CAVITY_ANGLES; ++k) {
        const float a = TWO_PI * (float)k / MS_CAVITY_ANGLES;
        const float rin = crossing(s, a, z, 0, rmax, 1);
        if (rin <= 0)
            return; /* open to one side: not a cavity */
        const float rout = crossing(s, a, z, rin, rmax, 0);
        c->r_in[k] = rin;
        c->r_out[k] = rout > 0 ? rout : rmax;
    }
    /* the floor: down the axis to the first solid */
    const float step = (z - lo[2]) / MARCH_STEPS;
    c->z_floor = lo[2];
    for (float zz = z - step; zz >= lo[2] - step; zz -= step)
        if (dist(s, 0, 0, zz) <= 0) {
            float a = zz, b = zz + step;
            for (int k = 0; k < BISECT; ++k) {
                const float mid = 0.5f * (a + b);
                if (dist(s, 0, 0, mid) <= 0)
                    a = mid;
                else
                    b = mid;
            }
            c->z_floor = 0.5f * (a + b);
            break;
        }
    c->z_probe = z;
    c->found = 1;
}

/* The table t at local angle a (radians), linear between its angles. */
static float table_at(const float *t, float a)
{
    float u = a * (MS_CAVITY_ANGLES / TWO_PI);
    if (u < 0)
        u += MS_CAVITY_ANGLES;
    int i = (int)u;
    const float f = u - (float)i;
    i = MS_CLAMP(i, 0, MS_CAVITY_ANGLES - 1);
    const int j = (i + 1) % MS_CAVITY_ANGLES;
    return t[i] + f * (t[j] - t[i]);
}

/* World (x, y) in the container's frame, at the probe's height: the
 * radius from the axis and the angle. */
static void polar(const ms_render_cavity *c, float x, float y, float *rho, float *a)
{
    const float p[3] = {x, y, c->plane_z};
    float q[3];
    ms_rigid_to_local(c->rot, c->pos, p, q);
    *rho = sqrtf(q[0] * q[0] + q[1] * q[1]);
    *a = atan2f(q[1], q[0]);
}

/* Cell (i, j) of grid g: its centre (x, y) and polar() of it. */
static void cell_polar(const ms_render_cavity *c, const ms_grid *g, int i, int j, float *x,
                       float *y, float *rho, float *a)
{
    *x = g->origin[0] + ((float)i + 0.5f) * g->dx;
    *y = g->origin[1] + ((float)j + 0.5f) * g->dy;
    polar(c, *x, *y, rho, a);
}

/* The determinant of a 3x3 matrix, by its first row. */
static double det3(double a[3][3])
{
    return a[0][0] * (a[1][1] * a[2][2] - a[1][2] * a[2][1]) -
           a[0][1] * (a[1][0] * a[2][2] - a[1][2] * a[2][0]) +
           a[0][2] * (a[1][0] * a[2][1] - a[1][1] * a[2][0]);
}

/* The world point at local radius rr along local angle a, on the plane
 * z = plane_z (world). */
static void at_radius(const ms_render_cavity *c, float rr, float a, float w[3])
{
    const float x = rr * cosf(a), y = rr * sinf(a);
    const float *R = c->rot;
    const float l[3] = {x, y, (c->plane_z - c->pos[2] - R[6] * x - R[7] * y) / R[8]};
    ms_rigid_to_world(c->rot, l, w);
    for (int k = 0; k < 3; ++k)
        w[k] += c->pos[k];
}

/* Field h over g (heights above the floor) at world (x, y), bilinear,
 * clamped to the grid. */
static float sample(const float *h, const ms_grid *g, float x, float y)
{
    float u = (x - g->origin[0]) / g->dx - 0.5f, v = (y - g->origin[1]) / g->dy - 0.5f;
    u = MS_CLAMP(u, 0.0f, (float)(g->nx - 1));
    v = MS_CLAMP(v, 0.0f, (float)(g->ny - 1));
    const int i = MS_MIN((int)u, g->nx - 2), j = MS_MIN((int)v, g->ny - 2);
    const float fu = u - (float)i, fv = v - (float)j;
    const float *a = h + (size_t)j * (size_t)g->nx + (size_t)i, *b = a + g->nx;
    return (1 - fv) * ((1 - fu) * a[0] + fu * a[1]) + fv * ((1 - fu) * b[0] + fu * b[1]);
}

/* The cell range of g within radius rr of world (x, y). */
static void cell_box(const ms_grid *g, float x, float y, float rr, int box[4])
{
    box[0] = MS_CLAMP((int)floorf((x - rr - g->origin[0]) / g->dx), 0, g->nx - 1);
    box[1] = MS_CLAMP((int)ceilf((x + rr - g->origin[0]) / g->dx), 0, g->nx - 1);
    box[2] = MS_CLAMP((int)floorf((y - rr - g->origin[1]) / g->dy), 0, g->ny - 1);
    box[3] = MS_CLAMP((int)ceilf((y + rr - g->origin[1]) / g->dy), 0, g->ny - 1);
}

static float largest(const float *t)
{
    float m = 0;
    for (int k = 0; k < MS_CAVITY_ANGLES; ++k)
        m = MS_MAX(m, t[k]);
    return m;
}

static float smallest(const float *t)
{
    float m = INFINITY;
    for (int k = 0; k < MS_CAVITY_ANGLES; ++k)
        m = MS_MIN(m, t[k]);
    return m;
}

/* The side of the liquid column: a quad per segment on the inner wall
 * from the cavity's floor to the filled surface, its normal outward. */
static void build_side(ms_render_cavity *c, const float *h, const ms_grid *g, float floor_z)
{
    /* per segment edge: the top (x, y, z), the angle, the bottom (x, y, z) on
     * the cavity's floor (the glass may lean) */
    float top[MS_CAVITY_SEGMENTS + 1][7];
    for (int s = 0; s <= MS_CAVITY_SEGMENTS; ++s) {
        const float a = TWO_PI * (float)s / MS_CAVITY_SEGMENTS;
        const float rin = table_at(c->r_in, a);
        float w[3], inner[3];
        at_radius(c, rin, a, w);
        at_radius(c, MS_MAX(rin - 0.5f * g->dx, 0.0f), a, inner);
        top[s][0] = w[0], top[s][1] = w[1];
        top[s][2] = floor_z + sample(h, g, inner[0], inner[1]);
        top[s][3] = a;
        const float l[3] = {rin * cosf(a), rin * sinf(a), c->z_floor};
        ms_rigid_to_world(c->rot, l, top[s] + 4);
        for (int k = 0; k < 3; ++k)
            top[s][4 + k] += c->pos[k];
    }
    int n = 0;
    for (int s = 0; s < MS_CAVITY_SEGMENTS; ++s) {
        const float *t0 = top[s], *t1 = top[s + 1];
        if (t0[2] <= t0[6] + MS_RENDER_DRY_DEPTH && t1[2] <= t1[6] + MS_RENDER_DRY_DEPTH)
            continue; /* no liquid against the wall here */
        /* MS_CAVITY_SIDE_ROWS quads up, each with corners b0 b1 t1 t0
         * counter-clockwise seen from outside (rows, so the shading
         * normals, which change with height, are interpolated finely) */
        const float *corner[4] = {t0, t1, t1, t0};
        const int up[4] = {0, 0, 1, 1};
        static const int order[6] = {0, 1, 2, 0, 2, 3};
        for (int row = 0; row < MS_CAVITY_SIDE_ROWS; ++row)
            for (int m = 0; m < 6; ++m) {
                const int k = order[m];
                float *o = c->side + 6 * (size_t)n++;
                const float l[3] = {cosf(corner[k][3]), sinf(corner[k][3]), 0};
                const float *b = corner[k] + 4;
                const float zt = MS_MAX(corner[k][2], b[2]);
                const float f = (float)(row + up[k]) / MS_CAVITY_SIDE_ROWS;
                o[0] = b[0] + f * (corner[k][0] - b[0]);
                o[1] = b[1] + f * (corner[k][1] - b[1]);
                o[2] = b[2] + f * (zt - b[2]);
                ms_rigid_to_world(c->rot, l, o + 3);
            }
    }
    c->side_verts = n;
}

ms_status ms_render_cavity_fill(ms_renderer *r, const float *h, const ms_grid *g, float coarse_dx,
                                const float **out)
{
    ms_render_cavity *c = &r->cavity;
    *out = h;
    c->active = 0;
    c->side_verts = 0;
    const ms_render_object *ob = container(r);
    if (!ob)
        return MS_OK;
    if (c->probed != ob)
        probe(c, ob);
    if (!c->found)
        return MS_OK;
    memcpy(c->pos, ob->shape->pos, sizeof c->pos);
    memcpy(c->rot, ob->shape->rot, sizeof c->rot);
    /* a glass tilted far (poured, `modesplit view`'s Q / E) is drawn as
     * the fields are: its cavity's cross-section at the water is no longer
     * the one probed, and the cut would hide the liquid pouring over the rim */
    if (c->rot[8] < MAX_TILT_COS)
        return MS_OK;
    const size_t cells = (size_t)g->nx * (size_t)g->ny;
    ms_status st = ms_render_reserve(&r->fill, &r->fill_cap, cells, "the glass's fill");
    if (st != MS_OK)
        return st;
    float *f = r->fill;
    memcpy(f, h, cells * sizeof *f);
    const float cell = MS_MAX(g->dx, g->dy);
    const float reach = largest(c->r_in) + 2 * cell;          /* the fill's outer edge */
    const float floor_w = c->pos[2] + c->rot[8] * c->z_floor; /* m, world, on the axis */
    const float wet_above =
        floor_w - r->desc.pool_min[2] + MS_RENDER_DRY_DEPTH; /* m over the floor */
    /* the cavity is taken on the plane of the liquid's level near the axis
     * (a leaning glass's cross-section moves with height); first guess: the
     * probe's height */
    c->plane_z = c->pos[2] + c->rot[8] * c->z_probe;
    int box[4];
    for (int pass = 0; pass < 2; ++pass) {
        float axis[3];
        at_radius(c, 0, 0, axis);
        cell_box(g, axis[0], axis[1], reach, box);
        if (pass == 1)
            break;
        double sum = 0;
        long wet = 0;
        for (int j = box[2]; j <= box[3]; ++j)
            for (int i = box[0]; i <= box[1]; ++i) {
                float rho, a;
                polar(c, g->origin[0] + ((float)i + 0.5f) * g->dx,
                      g->origin[1] + ((float)j + 0.5f) * g->dy, &rho, &a);
                const float hv = h[(size_t)j * g->nx + i];
                if (rho < 0.5f * table_at(c->r_in, a) && hv > wet_above)
                    sum += hv, ++wet;
            }
        if (wet > 0)
            c->plane_z = r->desc.pool_min[2] + (float)(sum / (double)wet);
    }
    /* the band along the inner wall that is carried: two SPH cells (the
     * up-sampling's slope and the display's cubic), at least 4 wave cells,
     * at most 40 % of the radius */
    const float rmin = smallest(c->r_in);
    float band = coarse_dx > 0 ? 2 * coarse_dx : 0.25f * rmin;
    band = MS_MIN(MS_MAX(band, 4 * cell), 0.4f * rmin);
    /* the core's plane h = p0 + p1 x + p2 y (x, y from the axis), least
     * squares over its wet cells: those over the cavity's floor (a glass
     * standing in shallow water has the pool's water under its floor) */
    double m[3][3] = {{0}}, b[3] = {0};
    long n = 0;
    for (int j = box[2]; j <= box[3]; ++j)
        for (int i = box[0]; i <= box[1]; ++i) {
            float x, y, rho, a;
            cell_polar(c, g, i, j, &x, &y, &rho, &a);
            const float hv = h[(size_t)j * g->nx + i];
            if (table_at(c->r_in, a) - rho <= band || !(hv > wet_above))
                continue;
            const double e[3] = {1, x - c->pos[0], y - c->pos[1]};
            for (int p = 0; p < 3; ++p) {
                for (int q = 0; q < 3; ++q)
                    m[p][q] += e[p] * e[q];
                b[p] += e[p] * hv;
            }
            ++n;
        }
    if (n == 0)
        return MS_OK; /* no liquid in it: drawn as it is */
    c->active = 1;
    /* what the cut sinks beyond the outer wall: eq. 20's bilinear tail of
     * the SPH field reaches up to ~1.5 of its cells past the last wet one */
    c->tail = 1.5f * coarse_dx + 2 * cell;
    c->field = f;
    c->grid = *g;
    *out = f;
    double pl[3] = {b[0] / (double)n, 0, 0};
    const double det = det3(m);
    if (n >= 3 && fabs(det) > 1e-12 * fabs(m[0][0] * m[1][1] * m[2][2])) {
        for (int k = 0; k < 3; ++k) { /* Cramer */
            double a[3][3];
            memcpy(a, m, sizeof a);
            for (int p = 0; p < 3; ++p)
                a[p][k] = b[p];
            pl[k] = det3(a) / det;
        }
    }
    for (int j = box[2]; j <= box[3]; ++j)
        for (int i = box[0]; i <= box[1]; ++i) {
            float x, y, rho, a;
            cell_polar(c, g, i, j, &x, &y, &rho, &a);
            const float rin = table_at(c->r_in, a), phi = rin - rho; /* > 0 inside */
            if (phi >= band || phi < -2 * cell)
                continue;
            float pc[3];
            at_radius(c, rin - band, a, pc);
            const float hc = sample(h, g, pc[0], pc[1]);
            const float plane_c =
                (float)(pl[0] + pl[1] * (pc[0] - c->pos[0]) + pl[2] * (pc[1] - c->pos[1]));
            const float plane = (float)(pl[0] + pl[1] * (x - c->pos[0]) + pl[2] * (y - c->pos[1]));
            /* the core's ripple at the band's edge fades to the plane at the wall */
            const float fade = MS_CLAMP(phi / band, 0.0f, 1.0f);
            const float target = plane + (hc - plane_c) * fade;
            /* blended in over the band's inner two thirds: the outer
             * third, where the SPH field falls to the floor, is all fill */
            const float t = MS_CLAMP(1.5f * (band - phi) / band, 0.0f, 1.0f);
            const float w = t * t * (3 - 2 * t);
            float *hv = f + (size_t)j * g->nx + i;
            *hv += w * (target - *hv);
        }
    build_side(c, f, g, r->desc.pool_min[2]);
    return MS_OK;
}

ms_status ms_render_cavity_cut(ms_renderer *r, float *v, int nx, int ny)
{
    ms_render_cavity *c = &r->cavity;
    if (!c->active)
        return MS_OK;
    const size_t nv = (size_t)nx * (size_t)ny;
    if (c->flags_cap < nv) {
        ms_free(c->flags);
        c->flags = ms_alloc(nv);
        c->flags_cap = c->flags ? nv : 0;
        if (!c->flags)
            return ms_fail(MS_ERR_OUT_OF_MEMORY, "render: out of memory for the glass's cut");
    }
    /* the vertices' spacing (the mesh may be coarser than the field) */
    const float sx = nx > 2 ? v[6 * 2] - v[6 * 1] : v[6] - v[0];
    const float sy =
        ny > 2 ? v[6 * 2 * (size_t)nx + 1] - v[6 * (size_t)nx + 1] : v[6 * (size_t)nx + 1] - v[1];
    const float spacing = MS_MAX(sx, sy);
    const float floor_z = r->desc.pool_min[2];
    /* 1: inside, 2: over the wall or within a vertex of it, 0: elsewhere */
    unsigned char *fl = c->flags;
    for (size_t k = 0; k < nv; ++k) {
        float rho, a;
        polar(c, v[6 * k], v[6 * k + 1], &rho, &a);
        const float rin = table_at(c->r_in, a);
        const float ring = MS_MAX(table_at(c->r_out, a), rin + c->tail) + 1.5f * spacing;
        fl[k] = rho <= rin ? 1 : rho <= ring ? 2 : 0;
    }
    for (int j = 0; j < ny; ++j)
        for (int i = 0; i < nx; ++i) {
            const size_t k = (size_t)j * nx + i;
            float *o = v + 6 * k;
            if (fl[k] == 0)
                continue;
            int next_to_inside = 0;
            for (int dj = -1; dj <= 1; ++dj)
                for (int di = -1; di <= 1; ++di) {
                    const int ii = i + di, jj = j + dj;
                    if (ii >= 0 && ii < nx && jj >= 0 && jj < ny && fl[(size_t)jj * nx + ii] == 1)
                        next_to_inside = 1;
                }
            if (fl[k] == 2 && next_to_inside) { /* onto the inner wall, just inside it */
                float rho, a, w[3];
                polar(c, o[0], o[1], &rho, &a);
                at_radius(c, table_at(c->r_in, a) - SNAP_INSIDE * spacing, a, w);
                o[0] = w[0], o[1] = w[1];
            } else if (fl[k] == 2) {
                o[2] = floor_z - SINK; /* under the dry clip */
                o[3] = 0, o[4] = 0, o[5] = 1;
                continue;
            }
            /* the filled field's own height there (the mesh's block
             * averages near the wall mix in the dry floor outside) */
            float in[3], rho, a;
            polar(c, o[0], o[1], &rho, &a);
            at_radius(c, MS_MIN(rho, table_at(c->r_in, a) - 0.5f * c->grid.dx), a, in);
            if (fl[k] == 2 || table_at(c->r_in, a) - rho < 2 * spacing) {
                o[2] = floor_z + sample(c->field, &c->grid, in[0], in[1]);
                o[3] = 0, o[4] = 0, o[5] = 1;
            }
        }
    return MS_OK;
}

void ms_render_cavity_free(ms_renderer *r)
{
    ms_free(r->cavity.flags);
    r->cavity.flags = NULL;
    r->cavity.flags_cap = 0;
    ms_free(r->fill);
    r->fill = NULL;
    r->fill_cap = 0;
}
