/* Shape plugin "glass": an open container (a cup, a glass, a tank): a
 * cylindrical wall of some thickness on a floor, open at the top, that the
 * user moves around (ms_shape_set_pose). With wall == radius it is a solid
 * cylinder.
 *
 * Parameters (m): {"radius": 0.05, "height": 0.12, "wall": 0.004,
 *                  "floor": 0.006, "smooth": min(wall, floor)/2}
 *   radius  outer radius; height  outer height, the rim is at z = height;
 *   wall    wall thickness, 0 < wall <= radius;
 *   floor   floor thickness, 0 <= floor <= height (0: an open tube);
 *   smooth  width over which the normal turns between faces (Fig. 5).
 * The local origin is the centre of the bottom; z is the axis.
 *
 * The glass is a solid of revolution: its closest point lies in the
 * meridian half-plane of p, so the exact distance is the 2D distance, in
 * (rho, z), to the U-shaped profile: bottom, outer wall, rim, inner wall,
 * inner floor. The normal blends the outward normals of the profile's
 * edges whose distance is within `smooth` of the nearest one, weighted
 * 1 - (d_e - d_min)/smooth: continuous across the rim, the outer bottom
 * edge and the concave inner corner; with smooth = 0 it is the exact
 * gradient. Inside the wall and the floor it flips on their middle
 * surface, where the two sides' normals are opposite (a thin wall pushes a
 * particle out through the nearer side).
 */
#include <math.h>
#include <stdlib.h>

#include "../common/host.h"
#include "../common/params.h"
#include "modesplit/plugin.h"

#define MAX_EDGES 5

typedef struct edge {
    float a[2], b[2]; /* (rho, z), m */
    float n[2];       /* outward unit normal */
} edge;

typedef struct glass {
    float R, H, w, f; /* m */
    float smooth;     /* m */
    edge e[MAX_EDGES];
    int ne;
} glass;

static void add_edge(glass *g, float a0, float a1, float b0, float b1, float n0, float n1)
{
    if ((a0 == b0 && a1 == b1) || (a0 == 0 && b0 == 0))
        return; /* empty, or on the axis (not a surface) */
    edge *e = &g->e[g->ne++];
    e->a[0] = a0;
    e->a[1] = a1;
    e->b[0] = b0;
    e->b[1] = b1;
    e->n[0] = n0;
    e->n[1] = n1;
}

static int glass_create(const char *json, void **out, char *err, size_t err_size)
{
    static const char *const keys[] = {"radius", "height", "wall", "floor", "smooth", NULL};
    params pm;
    float R = 0.05f, H = 0.12f, w = 0.004f, f = 0.006f, s = 0;
    if (params_open(&pm, json, keys, err, err_size) == MS_PLUGIN_OK) {
        R = params_number(&pm, "radius", R, 1e-6, 1e6, "m");
        H = params_number(&pm, "height", H, 1e-6, 1e6, "m");
        w = params_number(&pm, "wall", fminf(w, R), 1e-7, R, "m");
        f = params_number(&pm, "floor", fminf(f, H), 0.0, H, "m");
        float sd = 0.5f * (f > 0 ? fminf(w, f) : w);
        s = params_number(&pm, "smooth", sd, 0.0, 0.5 * R, "m");
    }
    int rc = params_close(&pm);
    if (rc != MS_PLUGIN_OK)
        return rc;
    glass *g = plugin_calloc(1, sizeof *g);
    if (!g) {
        snprintf(err, err_size, "out of memory");
        return MS_PLUGIN_ERR_OUT_OF_MEMORY;
    }
    g->R = R;
    g->H = H;
    g->w = w;
    g->f = f;
    g->smooth = s;
    float ri = R - w; /* inner radius */
    if (f > 0)
        add_edge(g, 0, 0, R, 0, 0, -1); /* bottom */
    else
        add_edge(g, ri, 0, R, 0, 0, -1); /* a tube: the wall's foot */
    add_edge(g, R, 0, R, H, 1, 0);       /* outer wall */
    add_edge(g, R, H, ri, H, 0, 1);      /* rim */
    add_edge(g, ri, H, ri, f, -1, 0);    /* inner wall */
    if (f > 0)
        add_edge(g, ri, f, 0, f, 0, 1); /* inner floor */
    *out = g;
    return MS_PLUGIN_OK;
}

static void glass_destroy(void *self)
{
    plugin_free(self);
}

static int inside(const glass *g, float rho, float z)
{
    return (rho <= g->R && z >= 0 && z <= g->f) ||
           (rho >= g->R - g->w && rho <= g->R && z >= 0 && z <= g->H);
}

/* Distance from q to edge e, and the outward unit normal it implies. */
static float edge_distance(const edge *e, const float q[2], int in, float n[2])
{
    float ab[2] = {e->b[0] - e->a[0], e->b[1] - e->a[1]};
    float aq[2] = {q[0] - e->a[0], q[1] - e->a[1]};
    float t = (aq[0] * ab[0] + aq[1] * ab[1]) / (ab[0] * ab[0] + ab[1] * ab[1]);
    t = fminf(fmaxf(t, 0.0f), 1.0f);
    float v[2] = {aq[0] - t * ab[0], aq[1] - t * ab[1]};
    float l = sqrtf(v[0] * v[0] + v[1] * v[1]);
    if (t > 0.0f && t < 1.0f) {
        n[0] = e->n[0]; /* the edge's own normal, on either side */
        n[1] = e->n[1];
    } else if (l > 1e-12f) {
        float s = in ? -1.0f : 1.0f; /* from the vertex outwards */
        n[0] = s * v[0] / l;
        n[1] = s * v[1] / l;
    } else {
        n[0] = e->n[0];
        n[1] = e->n[1];
    }
    return l;
}

static float glass_distance(const void *self, const float p[3], float n[3])
{
    const glass *g = self;
    float rho = sqrtf(p[0] * p[0] + p[1] * p[1]);
    float q[2] = {rho, p[2]};
    int in = inside(g, rho, p[2]);
    float de[MAX_EDGES], ne[MAX_EDGES][2], dmin = 1e30f;
    int imin = 0;
    for (int i = 0; i < g->ne; ++i) {
        de[i] = edge_distance(&g->e[i], q, in, ne[i]);
        if (de[i] < dmin) {
            dmin = de[i];
            imin = i;
        }
    }
    if (n) {
        float m[2] = {0, 0};
        if (g->smooth > 0) {
            for (int i = 0; i < g->ne; ++i) {
                float w = fmaxf(0.0f, 1.0f - (de[i] - dmin) / g->smooth);
                m[0] += w * ne[i][0];
                m[1] += w * ne[i][1];
            }
        }
        float l = sqrtf(m[0] * m[0] + m[1] * m[1]);
        if (!(l > 1e-6f)) { /* smooth 0, or opposite normals cancelled */
            m[0] = ne[imin][0];
            m[1] = ne[imin][1];
            l = 1;
        }
        float ux = rho > 0 ? p[0] / rho : 1.0f, uy = rho > 0 ? p[1] / rho : 0.0f;
        n[0] = m[0] / l * ux;
        n[1] = m[0] / l * uy;
        n[2] = m[1] / l;
    }
    return in ? -dmin : dmin;
}

static void glass_bounds(const void *self, float lo[3], float hi[3])
{
    const glass *g = self;
    lo[0] = lo[1] = -g->R;
    hi[0] = hi[1] = g->R;
    lo[2] = 0;
    hi[2] = g->H;
}

static int glass_height_at(const void *self, float x, float y, float *top)
{
    const glass *g = self;
    float rho = sqrtf(x * x + y * y);
    if (rho > g->R)
        return 0;
    if (rho >= g->R - g->w) {
        *top = g->H;
        return 1;
    }
    if (g->f <= 0)
        return 0;
    *top = g->f;
    return 1;
}

static const ms_shape_vtable glass_vtable = {
    .size = sizeof(ms_shape_vtable),
    .create = glass_create,
    .destroy = glass_destroy,
    .distance = glass_distance,
    .bounds = glass_bounds,
    .height_at = glass_height_at,
};

static const ms_plugin_info glass_info = {
    .abi = MS_PLUGIN_ABI,
    .size = sizeof(ms_plugin_info),
    .name = "glass",
    .version = "1.0",
    .kind = MS_PLUGIN_SHAPE,
    .description = "open cylindrical container: wall and floor of a thickness, open top",
    .vtable = &glass_vtable,
    .set_host = plugin_set_host,
};

const ms_plugin_info *ms_plugin_entry(void)
{
    return &glass_info;
}
