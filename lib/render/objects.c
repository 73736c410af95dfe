/* The scene's obstacles and container (the glass) as lit opaque meshes.
 *
 * The shapes give only a signed distance (ms_shape_distance), so each one
 * is meshed once, in its own frame, as two height maps over its x-y
 * bounds: the first surface a ray meets coming down (the top: a box's lid,
 * a glass's rim and its inside floor) and coming up (the bottom). Rays
 * that miss leave their vertex on the shape's silhouette: the point at
 * mid height projected onto the surface along the distance's gradient,
 * shared by both maps, so the two close there. Good for the shipped shapes
 * (box, sphere, capsule, glass, terrain); an overhang seen from the side
 * (a handle) is filled in. Each frame the mesh is moved by the shape's
 * pose: placed as the sim places it (ms_sim_shape_place: path, the
 * engine's moves and turns), so it is drawn where it blocks the water.
 * Unbounded shapes (a plane) are not drawn: the pool's floor shows them. */
#include <math.h>
#include <string.h>

#include "core/core_internal.h"
#include "render/render_internal.h"
#include "shape/shape_internal.h"
#include "sim/sim_internal.h"

/* Vertices per side of the larger extent: a glass of 14 cm gets 2.3 mm
 * cells, finer than its 1 cm wall. */
#define OBJ_CELLS 64

/* Linear RGB: obstacles a light stone, the glass a pale blue-white. */
static const float stone[3] = {0.55f, 0.53f, 0.50f};
static const float glass_tint[3] = {0.70f, 0.80f, 0.85f};

/* The first z in [z0 -> z1] where the surface is crossed on the vertical
 * through (x, y), by sphere tracing and bisection; 0 if none. */
static int trace(const ms_shape *s, float x, float y, float z0, float z1, float step, float *z)
{
    const float dir = z1 > z0 ? 1.0f : -1.0f;
    float p[3] = {x, y, z0}, prev = z0;
    float d = ms_shape_distance(s, p, NULL);
    if (d <= 0)
        return 0; /* starts inside: the bounds are loose, treat as a miss */
    for (int it = 0; it < 4096 && dir * (z1 - p[2]) >= 0; ++it) {
        prev = p[2];
        p[2] += dir * MS_MAX(0.9f * d, step);
        d = ms_shape_distance(s, p, NULL);
        if (d <= 0) {
            float a = prev, b = p[2];
            for (int k = 0; k < 20; ++k) {
                p[2] = 0.5f * (a + b);
                if (ms_shape_distance(s, p, NULL) <= 0)
                    b = p[2];
                else
                    a = p[2];
            }
            *z = 0.5f * (a + b);
            return 1;
        }
    }
    return 0;
}

/* (x, y, z) moved onto the surface along the distance's gradient. */
static void project(const ms_shape *s, float p[3])
{
    for (int k = 0; k < 8; ++k) {
        float n[3];
        float d = ms_shape_distance(s, p, n);
        p[0] -= d * n[0], p[1] -= d * n[1], p[2] -= d * n[2];
    }
}

static void put(float *o, const float *vx)
{
    memcpy(o, vx, 6 * sizeof *o);
}

/* The local mesh of s (at the origin, unturned): 6 floats a vertex. */
static ms_status mesh_shape(ms_render_object *ob)
{
    const ms_shape *s = ob->shape;
    float lo[3], hi[3];
    ms_shape_bounds(s, lo, hi);
    for (int k = 0; k < 3; ++k)
        if (!isfinite(lo[k]) || !isfinite(hi[k]) || hi[k] - lo[k] > 1e3f || hi[k] <= lo[k])
            return MS_OK; /* unbounded: not drawn */
    const float ext = MS_MAX(hi[0] - lo[0], hi[1] - lo[1]), cell = ext / OBJ_CELLS;
    const int nx = (int)ceilf((hi[0] - lo[0]) / cell) + 3, ny = (int)ceilf((hi[1] - lo[1]) / cell) + 3;
    const float x0 = lo[0] - cell, y0 = lo[1] - cell, zmid = 0.5f * (lo[2] + hi[2]);
    const float pad = 0.05f * (hi[2] - lo[2]) + cell, step = 0.1f * cell;
    const size_t nv = (size_t)nx * ny;
    /* per grid vertex, per map (0 top, 1 bottom): x, y, z, nx, ny, nz, hit */
    float *g = ms_alloc_array(2 * nv, 7 * sizeof(float));
    ob->local = ms_alloc_array(2 * 6 * (size_t)(nx - 1) * (ny - 1), 6 * sizeof(float));
    if (!g || !ob->local) {
        ms_free(g);
        return ms_fail(MS_ERR_OUT_OF_MEMORY, "render: out of memory for an obstacle's mesh");
    }
    for (int j = 0; j < ny; ++j)
        for (int i = 0; i < nx; ++i) {
            const float x = x0 + (float)i * cell, y = y0 + (float)j * cell;
            float rim[3] = {x, y, zmid};
            project(s, rim);
            for (int m = 0; m < 2; ++m) {
                float *o = g + (2 * ((size_t)j * nx + i) + m) * 7, z;
                float p[3] = {rim[0], rim[1], rim[2]};
                int hit = m == 0 ? trace(s, x, y, hi[2] + pad, lo[2] - pad, step, &z)
                                 : trace(s, x, y, lo[2] - pad, hi[2] + pad, step, &z);
                if (hit)
                    p[0] = x, p[1] = y, p[2] = z;
                ms_shape_distance(s, p, o + 3);
                o[0] = p[0], o[1] = p[1], o[2] = p[2], o[6] = (float)hit;
            }
        }
    int n = 0;
    for (int j = 0; j + 1 < ny; ++j)
        for (int i = 0; i + 1 < nx; ++i)
            for (int m = 0; m < 2; ++m) {
                const float *a = g + (2 * ((size_t)j * nx + i) + m) * 7, *b = a + 14,
                            *c = a + 14 * (size_t)nx, *e = c + 14;
                const float *tri[2][3] = {{a, b, e}, {a, e, c}};
                for (int t = 0; t < 2; ++t) {
                    if (tri[t][0][6] + tri[t][1][6] + tri[t][2][6] == 0)
                        continue; /* off the shape */
                    for (int k = 0; k < 3; ++k)
                        put(ob->local + 6 * (size_t)n++, tri[t][k]);
                }
            }
    ms_free(g);
    ob->nverts = n;
    return MS_OK;
}

void ms_render_objects_free(ms_renderer *r)
{
    for (int i = 0; i < r->nobjects; ++i) {
        ms_shape_destroy(r->objects[i].shape);
        ms_free(r->objects[i].local);
    }
    ms_free(r->objects);
    ms_free(r->object_verts);
    r->objects = NULL, r->object_verts = NULL;
    r->nobjects = 0, r->object_nverts = 0, r->object_scene = NULL;
}

/* One mesh per obstacle then the container (the sim's order). */
static ms_status make_objects(ms_renderer *r, const ms_scene *sc)
{
    ms_render_objects_free(r);
    r->object_scene = sc;
    const int n = sc->nobstacles + (sc->has_container ? 1 : 0);
    if (n == 0)
        return MS_OK;
    r->objects = ms_alloc_array((size_t)n, sizeof *r->objects);
    if (!r->objects)
        return ms_fail(MS_ERR_OUT_OF_MEMORY, "render: out of memory for %d obstacles", n);
    r->nobjects = n;
    size_t total = 0;
    for (int i = 0; i < n; ++i) {
        ms_render_object *ob = &r->objects[i];
        ob->spec = i < sc->nobstacles ? &sc->obstacles[i] : &sc->container;
        const int is_glass = i >= sc->nobstacles;
        memcpy(ob->color, is_glass ? glass_tint : stone, sizeof ob->color);
        ms_status st = ms_shape_create(ob->spec->kind, ob->spec->params_json, &ob->shape);
        if (st == MS_OK)
            st = mesh_shape(ob);
        if (st != MS_OK)
            return st;
        total += (size_t)ob->nverts;
    }
    r->object_verts = ms_alloc_array(total ? total : 1, MS_RENDER_OBJECT_STRIDE * sizeof(float));
    if (!r->object_verts)
        return ms_fail(MS_ERR_OUT_OF_MEMORY, "render: out of memory for the obstacles' meshes");
    return MS_OK;
}

ms_status ms_render_objects_update(ms_renderer *r, const ms_scene *sc, const ms_sim *sim,
                                   double t)
{
    if (!sc) {
        if (r->nobjects)
            r->discs_changed = 1;
        ms_render_objects_free(r);
        return MS_OK;
    }
    ms_status st;
    if (sc != r->object_scene && (st = make_objects(r, sc)) != MS_OK) {
        ms_render_objects_free(r);
        return st;
    }
    int n = 0;
    r->object_glass = -1;
    for (int i = 0; i < r->nobjects; ++i) {
        ms_render_object *ob = &r->objects[i];
        if (ob->spec == &sc->container && r->object_glass < 0)
            r->object_glass = n; /* last: the container */
        if (ob->nverts == 0)
            continue;
        /* where the sim has it (moved or turned by the engine), else where
         * the scene puts it at t */
        ms_sim_shape own = {.spec = ob->spec};
        const ms_sim_shape *sh = sim && i < sim->nshapes ? &sim->shapes[i] : &own;
        if ((st = ms_sim_shape_place(sh, ob->shape, t)) != MS_OK)
            return st;
        const ms_shape *s = ob->shape;
        for (int v = 0; v < ob->nverts; ++v) {
            const float *l = ob->local + 6 * (size_t)v;
            float *o = r->object_verts + MS_RENDER_OBJECT_STRIDE * (size_t)n++;
            ms_rigid_to_world(s->rot, l, o);
            ms_rigid_to_world(s->rot, l + 3, o + 3);
            for (int k = 0; k < 3; ++k)
                o[k] += s->pos[k];
            memcpy(o + 6, ob->color, sizeof ob->color);
        }
    }
    r->object_nverts = n;
    if (r->object_glass < 0)
        r->object_glass = n;
    r->discs_changed = 1;
    return MS_OK;
}
