/* The caustics light map (paper section 3.6: "a planar light map is
 * generated via light raytracing using Snell's law"), on the CPU.
 *
 * Parallel sunlight (direction L, |L| = 1, L_z < 0) crosses the liquid
 * surface z = floor + h(x, y). A patch of the surface whose horizontal
 * projection has area A takes the flux E0 |L_z| A whatever its tilt (the
 * surface is a graph over the floor); the Fresnel transmission T (Schlick:
 * R = R0 + (1 - R0)(1 - cos i)^5, R0 = ((n - 1)/(n + 1))^2) lets 1 - R of it
 * in, along the refracted direction (Snell's law, vector form, eta = 1/n:
 *     t = eta L + (eta cos i - sqrt(1 - eta^2 (1 - cos i^2))) N ),
 * to the floor. Where neighbouring rays converge the floor is brighter.
 * Rays start on a lattice over the pool, m per texel and axis (m as small
 * as makes them at least as fine as the field's cells), each at its
 * patch's centre with height and gradient interpolated bilinearly, and are
 * splat bilinearly where they meet the floor; flat water gives 1 in every
 * texel exactly (the map is scaled by flat water's flux E0 |L_z| T0), so
 * the map's mean over the pool is the share of light that reaches the
 * floor, relative to flat water: conserved up to the slopes' extra
 * reflection and the rays that meet the walls. A [1 2 1]/4 blur each way
 * hides the ray lattice where rays diverge.
 */
#include <math.h>
#include <string.h>

#include "core/core_internal.h"
#include "render/render_internal.h"

#define MAX_RAYS_PER_TEXEL 8 /* per axis */

void ms_caustics_free(ms_caustics *c)
{
    if (!c)
        return;
    ms_free(c->walls);
    ms_free(c->walls_tmp);
    ms_free(c->map);
    ms_free(c->tmp);
    ms_free(c->gx);
    ms_free(c->gy);
    ms_free(c->row);
    ms_free(c->col0);
    ms_free(c->colf);
    ms_free(c->lit);
    ms_free(c->open);
    ms_free(c->layers);
    memset(c, 0, sizeof *c);
}

static ms_status reserve(ms_caustics *c, int n, size_t cells, size_t row)
{
    if (c->row_cap < row) {
        ms_free(c->row);
        ms_free(c->col0);
        ms_free(c->colf);
        c->row = ms_alloc_array(row, 6 * sizeof(float));
        c->col0 = ms_alloc_array(row, sizeof(int));
        c->colf = ms_alloc_array(row, sizeof(float));
        c->row_cap = c->row && c->col0 && c->colf ? row : 0;
        if (!c->row_cap)
            return ms_fail(MS_ERR_OUT_OF_MEMORY,
                           "render: out of memory for the caustics tracer's rows");
    }
    if (c->n != n) {
        ms_free(c->map);
        ms_free(c->tmp);
        ms_free(c->lit);
        ms_free(c->open);
        ms_free(c->layers);
        c->lit = c->open = c->layers = NULL;
        c->nlayers = 0;
        c->map = ms_alloc_array((size_t)n * (size_t)n, sizeof(float));
        c->tmp = ms_alloc_array((size_t)n * (size_t)n, sizeof(float));
        c->n = c->map && c->tmp ? n : 0;
        if (!c->n)
            return ms_fail(MS_ERR_OUT_OF_MEMORY,
                           "render: out of memory for a %d x %d caustics "
                           "light map",
                           n, n);
    }
    if (c->field_cap < cells) {
        ms_free(c->gx);
        ms_free(c->gy);
        c->gx = ms_alloc_array(cells, sizeof(float));
        c->gy = ms_alloc_array(cells, sizeof(float));
        c->field_cap = c->gx && c->gy ? cells : 0;
        if (!c->field_cap)
            return ms_fail(MS_ERR_OUT_OF_MEMORY,
                           "render: out of memory for the caustics tracer's gradients");
    }
    return MS_OK;
}

static float schlick_transmission(float cosi, float r0)
{
    float m = 1.0f - cosi;
    float m2 = m * m;
    return 1.0f - (r0 + (1.0f - r0) * m2 * m2 * m);
}

/* Gradients at the cell centres by central differences, one-sided at the
 * edges. */
static void gradients(const float *h, int nx, int ny, float dx, float dy, float *restrict gx,
                      float *restrict gy)
{
    for (int j = 0; j < ny; ++j) {
        const float *row = h + (size_t)j * (size_t)nx;
        const float *lo = h + (size_t)(j > 0 ? j - 1 : j) * (size_t)nx;
        const float *hi = h + (size_t)(j < ny - 1 ? j + 1 : j) * (size_t)nx;
        const float iy = (j > 0 && j < ny - 1 ? 0.5f : 1.0f) / dy;
        float *ox = gx + (size_t)j * (size_t)nx, *oy = gy + (size_t)j * (size_t)nx;
        for (int i = 0; i < nx; ++i)
            oy[i] = (hi[i] - lo[i]) * iy;
        ox[0] = (row[1] - row[0]) / dx;
        for (int i = 1; i < nx - 1; ++i)
            ox[i] = (row[i + 1] - row[i - 1]) * (0.5f / dx);
        ox[nx - 1] = (row[nx - 1] - row[nx - 2]) / dx;
    }
}

/* Where world coordinate x (m) samples the nodes (cell centres) of an axis
 * of `cells` cells from x0 with spacing dx: the node below and the
 * fraction towards the next, clamped to the grid. */
static void sample_axis(float x, float x0, float dx, int cells, int *i0, float *f)
{
    float u = (x - x0) / dx - 0.5f;
    int i = (int)floorf(u);
    float t = u - (float)i;
    if (i < 0)
        i = 0, t = 0;
    if (i > cells - 2)
        i = cells - 2, t = 1;
    *i0 = i;
    *f = t;
}

/* [1 2 1] / 4 along rows of src into dst (stride 1) with clamped edges;
 * called on rows, then on the transpose's rows. */
static void blur_rows(const float *src, float *dst, int n)
{
    for (int j = 0; j < n; ++j) {
        const float *s = src + (size_t)j * (size_t)n;
        float *d = dst + (size_t)j * (size_t)n;
        d[0] = 0.25f * (3.0f * s[0] + s[1]);
        for (int i = 1; i < n - 1; ++i)
            d[i] = 0.25f * (s[i - 1] + 2.0f * s[i] + s[i + 1]);
        d[n - 1] = 0.25f * (s[n - 2] + 3.0f * s[n - 1]);
    }
}

static void blur_cols(const float *src, float *dst, int n)
{
    for (int j = 0; j < n; ++j) {
        const float *up = src + (size_t)(j > 0 ? j - 1 : j) * (size_t)n;
        const float *s = src + (size_t)j * (size_t)n;
        const float *dn = src + (size_t)(j < n - 1 ? j + 1 : j) * (size_t)n;
        float *d = dst + (size_t)j * (size_t)n;
        for (int i = 0; i < n; ++i)
            d[i] = 0.25f * (up[i] + 2.0f * s[i] + dn[i]);
    }
}

/* One row of rays, from the field rows interpolated to the rays' y
 * (rh, rgx, rgy over the field's nx nodes) to where each meets the floor
 * (hx, hy, m) and the light it carries (w; 0 for none). No branches: the
 * compiler may vectorise it. */
static void trace_row(int rx, float y, const int *restrict col0, const float *restrict colf,
                      const float *restrict rh, const float *restrict rgx,
                      const float *restrict rgy, float x0, float step, const float L[3], float eta,
                      float r0, float w_flat, float *restrict hx, float *restrict hy,
                      float *restrict w)
{
    const float Lx = L[0], Ly = L[1], Lz = L[2];
    for (int k = 0; k < rx; ++k) {
        const int i = col0[k];
        const float f = colf[k];
        const float hh = rh[i] + f * (rh[i + 1] - rh[i]);
        const float gx = rgx[i] + f * (rgx[i + 1] - rgx[i]);
        const float gy = rgy[i] + f * (rgy[i + 1] - rgy[i]);
        const float x = x0 + ((float)k + 0.5f) * step;
        const float inv = 1.0f / sqrtf(gx * gx + gy * gy + 1.0f);
        const float Nx = -gx * inv, Ny = -gy * inv, Nz = inv;
        const float cosi = MS_MAX(-(Lx * Nx + Ly * Ny + Lz * Nz), 0.0f);
        const float kk = MS_MAX(1.0f - eta * eta * (1.0f - cosi * cosi), 0.0f);
        const float m = eta * cosi - sqrtf(kk);
        const float tX = eta * Lx + m * Nx, tY = eta * Ly + m * Ny;
        const float tZ = MS_MIN(eta * Lz + m * Nz, -1e-6f);
        const float depth = MS_MAX(hh, 0.0f); /* dry: the sun straight onto the floor, */
        const float s = depth / -tZ;          /* path length to the floor, m */
        const float wet = hh > 0 ? 1.0f : 0.0f;
        const float om = 1.0f - cosi, om2 = om * om;
        const float t = 1.0f - (r0 + (1.0f - r0) * om2 * om2 * om); /* Schlick */
        hx[k] = x + s * tX;
        hy[k] = y + s * tY;
        /* with no surface to reflect any (1 / T0 of flat water's light); a
         * slope facing away from the sun takes none (cosi = 0: t = 0) */
        w[k] = w_flat * (wet * t + (1.0f - wet));
    }
}

int ms_caustics_wall_rows(const ms_caustics_desc *d)
{
    if (!(d->depth > 0))
        return 0;
    /* rays start a texel apart; under flat water they meet a wall
     * |t_z| / |t_h| texels apart in height (t the refracted sun, Snell):
     * a row as tall as two of those keeps the strips free of ray lines */
    const float *L = d->light_dir, eta = 1.0f / d->ior;
    const float lh = sqrtf(L[0] * L[0] + L[1] * L[1]), th = eta * lh;
    const float tz = sqrtf(MS_MAX(1.0f - th * th, 0.0f));
    const float texel = MS_MAX(d->pool[2], d->pool[3]) / (float)d->resolution;
    const float row = 2.0f * texel * tz / MS_MAX(MS_MAX(fabsf(L[0]), fabsf(L[1])) * eta, 1e-3f);
    return MS_CLAMP((int)ceilf(d->depth / row), 4, d->resolution);
}

/* The walls' strips (section 3.6 lights only the floor): a ray
 * whose floor point (hx, hy) lies outside the floor's square crossed a
 * wall first, at the fraction f of its way down from its start (x, y,
 * z0 over the floor) where it reaches the wall's plane. Splat there in the
 * floor map's unit: the ray's light per floor texel area over the wall
 * texel's area. Nothing if it meets no wall under the still water. */
static void splat_wall(ms_caustics *c, const ms_caustics_desc *d, float x, float y, float z0,
                       float hx, float hy, float w)
{
    const int n = c->n, rows = c->wall_rows;
    const float x0 = d->pool[0], y0 = d->pool[1], x1 = x0 + d->pool[2], y1 = y0 + d->pool[3];
    /* the first wall plane the ray's way down crosses */
    float f = 2, along = 0, span = 1, origin = 0;
    int strip = -1;
    if (hx < x0 || hx > x1) {
        const float fx = ((hx < x0 ? x0 : x1) - x) / (hx - x);
        if (fx < f)
            f = fx, strip = hx < x0 ? 0 : 1, along = y + fx * (hy - y), origin = y0,
            span = d->pool[3];
    }
    if (hy < y0 || hy > y1) {
        const float fy = ((hy < y0 ? y0 : y1) - y) / (hy - y);
        if (fy < f)
            f = fy, strip = hy < y0 ? 2 : 3, along = x + fy * (hx - x), origin = x0,
            span = d->pool[2];
    }
    if (strip < 0 || !(f >= 0 && f <= 1) || !(w > 0))
        return;
    const float z = z0 * (1 - f); /* height over the floor where it meets the wall */
    const float u = (along - origin) / span * (float)n - 0.5f;
    const float v = z / d->depth * (float)rows - 0.5f;
    if (!(u >= -0.5f && u <= (float)n - 0.5f && v >= -0.5f && v <= (float)rows - 0.5f))
        return; /* above the still water or past a corner */
    const float texel_along = span / (float)n;
    const float texel_floor = (d->pool[2] / (float)n) * (d->pool[3] / (float)n);
    const float wk = w * texel_floor / (texel_along * (d->depth / (float)rows));
    int iu = (int)floorf(u), iv = (int)floorf(v);
    const float au = u - (float)iu, av = v - (float)iv;
    const int iu1 = MS_MIN(iu + 1, n - 1), iv1 = MS_MIN(iv + 1, rows - 1);
    iu = MS_MAX(iu, 0);
    iv = MS_MAX(iv, 0);
    float *m = c->walls + (size_t)strip * (size_t)rows * (size_t)n;
    m[(size_t)iv * n + iu] += wk * (1 - au) * (1 - av);
    m[(size_t)iv * n + iu1] += wk * au * (1 - av);
    m[(size_t)iv1 * n + iu] += wk * (1 - au) * av;
    m[(size_t)iv1 * n + iu1] += wk * au * av;
}

/* [1 2 1] / 4 along u of each wall strip row, and along v within each
 * strip (edges clamped), as the floor's blur. */
static void blur_walls(ms_caustics *c)
{
    const int n = c->n, rows = c->wall_rows;
    float *a = c->walls, *b = c->walls_tmp;
    for (int r = 0; r < 4 * rows; ++r) {
        const float *s = a + (size_t)r * n;
        float *o = b + (size_t)r * n;
        o[0] = 0.25f * (3.0f * s[0] + s[1]);
        for (int i = 1; i < n - 1; ++i)
            o[i] = 0.25f * (s[i - 1] + 2.0f * s[i] + s[i + 1]);
        o[n - 1] = 0.25f * (s[n - 2] + 3.0f * s[n - 1]);
    }
    for (int st = 0; st < 4; ++st)
        for (int r = 0; r < rows; ++r) {
            const size_t base = (size_t)st * rows;
            const float *dn = b + (base + (size_t)(r > 0 ? r - 1 : r)) * n;
            const float *s = b + (base + (size_t)r) * n;
            const float *up = b + (base + (size_t)(r < rows - 1 ? r + 1 : r)) * n;
            float *o = a + (base + (size_t)r) * n;
            for (int i = 0; i < n; ++i)
                o[i] = 0.25f * (dn[i] + 2.0f * s[i] + up[i]);
        }
}

/* Light w splat bilinearly at texel coordinates (u, v) of the n x n map m;
 * nothing outside it. */
static void splat(float *m, int n, float u, float v, float w)
{
    if (!(u >= -0.5f && u <= (float)n - 0.5f && v >= -0.5f && v <= (float)n - 0.5f))
        return;
    int iu = (int)floorf(u), iv = (int)floorf(v);
    const float au = u - (float)iu, av = v - (float)iv;
    const int iu1 = MS_MIN(iu + 1, n - 1), iv1 = MS_MIN(iv + 1, n - 1);
    iu = MS_MAX(iu, 0);
    iv = MS_MAX(iv, 0);
    m[(size_t)iv * n + iu] += w * (1 - au) * (1 - av);
    m[(size_t)iv * n + iu1] += w * au * (1 - av);
    m[(size_t)iv1 * n + iu] += w * (1 - au) * av;
    m[(size_t)iv1 * n + iu1] += w * au * av;
}

/* The floor's texels in the shadow of the occluders (section 3.6 has no
 * objects under the water): each triangle projected onto the
 * floor along flat water's refracted sun t (Snell's law), its parts above
 * the still water from the water plane (there the light is not yet
 * bent), and the texels whose centres it covers set to 0 in c->lit, then
 * [1 2 1]/4 each way for a soft edge as the light map's. */
static ms_status shade_floor(ms_caustics *c, const ms_caustics_desc *d)
{
    const int n = c->n;
    if (!c->lit)
        c->lit = ms_alloc_array((size_t)n * (size_t)n, sizeof(float));
    if (!c->open)
        c->open = ms_alloc_array((size_t)n * (size_t)n, sizeof(float));
    if (!c->lit || !c->open)
        return ms_fail(MS_ERR_OUT_OF_MEMORY, "render: out of memory for the objects' shadow");
    for (size_t i = 0; i < (size_t)n * (size_t)n; ++i)
        c->lit[i] = 1.0f;
    const float *L = d->light_dir, eta = 1.0f / d->ior;
    const float cosi = MS_MAX(-L[2], 0.0f);
    const float tz = -sqrtf(MS_MAX(1.0f - eta * eta * (1.0f - cosi * cosi), 1e-6f));
    const float sx = eta * L[0] / -tz, sy = eta * L[1] / -tz; /* m across per m down */
    const float top = d->floor_z + d->depth;
    const float ux = (float)n / d->pool[2], uy = (float)n / d->pool[3];
    for (int v = 0; v + 2 < d->occluder_verts; v += 3) {
        float P[3][2];
        for (int k = 0; k < 3; ++k) {
            const float *p = d->occluders + (size_t)(v + k) * (size_t)d->occluder_stride;
            const float down = MS_MAX(MS_MIN(p[2], top) - d->floor_z, 0.0f); /* m to the floor */
            P[k][0] = (p[0] + down * sx - d->pool[0]) * ux - 0.5f;           /* texel coordinates */
            P[k][1] = (p[1] + down * sy - d->pool[1]) * uy - 0.5f;
        }
        const float area =
            (P[1][0] - P[0][0]) * (P[2][1] - P[0][1]) - (P[2][0] - P[0][0]) * (P[1][1] - P[0][1]);
        if (!(fabsf(area) > 1e-12f))
            continue; /* edge-on: the neighbours cover it */
        const int i0 = MS_MAX((int)floorf(MS_MIN(P[0][0], MS_MIN(P[1][0], P[2][0]))), 0);
        const int i1 = MS_MIN((int)ceilf(MS_MAX(P[0][0], MS_MAX(P[1][0], P[2][0]))), n - 1);
        const int j0 = MS_MAX((int)floorf(MS_MIN(P[0][1], MS_MIN(P[1][1], P[2][1]))), 0);
        const int j1 = MS_MIN((int)ceilf(MS_MAX(P[0][1], MS_MAX(P[1][1], P[2][1]))), n - 1);
        for (int j = j0; j <= j1; ++j)
            for (int i = i0; i <= i1; ++i) {
                /* inside: the three edge functions share the area's sign */
                int inside = 1;
                for (int e = 0; e < 3 && inside; ++e) {
                    const float *a = P[e], *b = P[(e + 1) % 3];
                    const float w =
                        (b[0] - a[0]) * ((float)j - a[1]) - (b[1] - a[1]) * ((float)i - a[0]);
                    inside = area > 0 ? w >= 0 : w <= 0;
                }
                if (inside)
                    c->lit[(size_t)j * n + i] = 0.0f;
            }
    }
    blur_rows(c->lit, c->tmp, n);
    blur_cols(c->tmp, c->lit, n);
    memcpy(c->open, c->map, (size_t)n * (size_t)n * sizeof *c->map);
    for (size_t i = 0; i < (size_t)n * (size_t)n; ++i)
        c->map[i] *= c->lit[i];
    c->shaded = 1;
    return MS_OK;
}

ms_status ms_caustics_trace(ms_caustics *c, const ms_caustics_desc *d, const float *h,
                            const ms_grid *g)
{
    const int n = d->resolution, nx = g->nx, ny = g->ny;
    /* m rays per texel and axis: as fine as the field's cells, and an
     * integer fraction of a texel, so flat water splats exactly 1 in each */
    const float tx = d->pool[2] / (float)n, ty = d->pool[3] / (float)n; /* m per texel */
    const int mx = MS_CLAMP((int)ceilf(tx / g->dx - 1e-3f), 1, MAX_RAYS_PER_TEXEL);
    const int my = MS_CLAMP((int)ceilf(ty / g->dy - 1e-3f), 1, MAX_RAYS_PER_TEXEL);
    const int rx = n * mx, ry = n * my;
    ms_status st = reserve(c, n, (size_t)nx * (size_t)ny, (size_t)MS_MAX(rx, nx));
    if (st != MS_OK)
        return st;
    const int rows = ms_caustics_wall_rows(d);
    if (rows != c->wall_rows) {
        ms_free(c->walls);
        ms_free(c->walls_tmp);
        c->walls = c->walls_tmp = NULL;
        c->wall_rows = 0;
        if (rows > 0) {
            c->walls = ms_alloc_array(4 * (size_t)rows * (size_t)n, sizeof(float));
            c->walls_tmp = ms_alloc_array(4 * (size_t)rows * (size_t)n, sizeof(float));
            if (!c->walls || !c->walls_tmp)
                return ms_fail(MS_ERR_OUT_OF_MEMORY,
                               "render: out of memory for the caustics on the pool's walls");
            c->wall_rows = rows;
        }
    }
    if (rows > 0)
        memset(c->walls, 0, 4 * (size_t)rows * (size_t)n * sizeof *c->walls);
    /* the light in the water at half the floor's resolution: objects are
     * small in the picture, and the layers' splats are most of their cost */
    const int nl = d->depth > 0 ? MS_CLAMP(d->layers, 0, 16) : 0, ln = MS_MAX(n / 2, 8);
    const size_t slice = (size_t)ln * (size_t)ln;
    if (nl != c->nlayers || (nl && ln != c->layer_n)) {
        ms_free(c->layers);
        c->layers = nl ? ms_alloc_array((size_t)(nl + 1) * slice, sizeof(float)) : NULL;
        c->nlayers = c->layers ? nl : 0;
        c->layer_n = ln;
        if (nl && !c->layers)
            return ms_fail(MS_ERR_OUT_OF_MEMORY,
                           "render: out of memory for %d layers of the caustics", nl);
    }
    if (nl)
        memset(c->layers, 0, (size_t)(nl + 1) * slice * sizeof *c->layers);
    /* a ray's light per floor texel, per layer texel */
    const float lw = (float)ln * (float)ln / ((float)n * (float)n);
    const float ilx = (float)ln / d->pool[2], ily = (float)ln / d->pool[3];
    float *map = c->map;
    memset(map, 0, (size_t)n * (size_t)n * sizeof *map);
    c->shaded = 0;
    if (!(d->light_dir[2] < -1e-3f)) {
        /* the sun at or below the horizon: no direct light on the floor */
        return MS_OK;
    }
    gradients(h, nx, ny, g->dx, g->dy, c->gx, c->gy);

    const float eta = 1.0f / d->ior;
    const float r0 = ((d->ior - 1.0f) / (d->ior + 1.0f)) * ((d->ior - 1.0f) / (d->ior + 1.0f));
    const float t0 = schlick_transmission(-d->light_dir[2], r0);
    /* light per ray over light per texel, both through flat water */
    const float w_ray = 1.0f / ((float)(mx * my) * t0);
    const float px0 = d->pool[0], py0 = d->pool[1];
    const float itx = 1.0f / tx, ity = 1.0f / ty, stepx = tx / (float)mx;
    for (int k = 0; k < rx; ++k)
        sample_axis(px0 + ((float)k + 0.5f) * stepx, g->origin[0], g->dx, nx, &c->col0[k],
                    &c->colf[k]);
    float *rh = c->row, *rgx = rh + c->row_cap, *rgy = rgx + c->row_cap;
    float *hx = rgy + c->row_cap, *hy = hx + c->row_cap, *w = hy + c->row_cap;

    for (int kj = 0; kj < ry; ++kj) {
        const float y = py0 + ((float)kj + 0.5f) * ty / (float)my;
        int j0;
        float fv;
        sample_axis(y, g->origin[1], g->dy, ny, &j0, &fv);
        /* the field's rows at the rays' y */
        const size_t a0 = (size_t)j0 * (size_t)nx, a1 = a0 + (size_t)nx;
        for (int i = 0; i < nx; ++i) {
            rh[i] = h[a0 + i] + fv * (h[a1 + i] - h[a0 + i]);
            rgx[i] = c->gx[a0 + i] + fv * (c->gx[a1 + i] - c->gx[a0 + i]);
            rgy[i] = c->gy[a0 + i] + fv * (c->gy[a1 + i] - c->gy[a0 + i]);
        }
        trace_row(rx, y, c->col0, c->colf, rh, rgx, rgy, px0, stepx, d->light_dir, eta, r0, w_ray,
                  hx, hy, w);
        /* splat each ray's light bilinearly where it meets the floor */
        for (int k = 0; k < rx; ++k) {
            if (nl && w[k] > 0) {
                /* and where it crosses each layer on its way: the ray runs
                 * from its start (x, y, z0) to (hx, hy, 0) straight */
                const int i = c->col0[k];
                const float z0 = rh[i] + c->colf[k] * (rh[i + 1] - rh[i]);
                const float x = px0 + ((float)k + 0.5f) * stepx;
                for (int l = 0; l < nl && z0 > 0; ++l) {
                    const float zl = d->depth * (float)(l + 1) / (float)(nl + 1);
                    const float f = MS_MAX(z0 - zl, 0.0f) / z0; /* of the way down */
                    splat(c->layers + (size_t)(l + 1) * slice, ln,
                          (x + f * (hx[k] - x) - px0) * ilx - 0.5f,
                          (y + f * (hy[k] - y) - py0) * ily - 0.5f, w[k] * lw);
                }
            }
            float u = (hx[k] - px0) * itx - 0.5f, v = (hy[k] - py0) * ity - 0.5f;
            if (!(w[k] > 0 && u >= -0.5f && u <= (float)n - 0.5f && v >= -0.5f &&
                  v <= (float)n - 0.5f)) {
                if (rows > 0 && w[k] > 0) { /* into a wall: its start, again */
                    const int i = c->col0[k];
                    const float z0 = rh[i] + c->colf[k] * (rh[i + 1] - rh[i]);
                    splat_wall(c, d, px0 + ((float)k + 0.5f) * stepx, y, MS_MAX(z0, 0.0f), hx[k],
                               hy[k], w[k]);
                }
                continue;
            }
            int iu = (int)floorf(u), iv = (int)floorf(v);
            float au = u - (float)iu, av = v - (float)iv, wk = w[k];
            int iu1 = MS_MIN(iu + 1, n - 1), iv1 = MS_MIN(iv + 1, n - 1);
            iu = MS_MAX(iu, 0);
            iv = MS_MAX(iv, 0);
            float *r_lo = map + (size_t)iv * (size_t)n, *r_hi = map + (size_t)iv1 * (size_t)n;
            r_lo[iu] += wk * (1 - au) * (1 - av);
            r_lo[iu1] += wk * au * (1 - av);
            r_hi[iu] += wk * (1 - au) * av;
            r_hi[iu1] += wk * au * av;
        }
    }
    blur_rows(map, c->tmp, n);
    blur_cols(c->tmp, map, n);
    const float k = d->intensity;
    for (size_t i = 0; i < (size_t)n * (size_t)n; ++i)
        map[i] = MS_MAX(1.0f + k * (map[i] - 1.0f), 0.0f);
    for (int l = 1; l <= nl; ++l) {
        float *m = c->layers + (size_t)l * slice;
        blur_rows(m, c->tmp, ln);
        blur_cols(c->tmp, m, ln);
        for (size_t i = 0; i < slice; ++i)
            m[i] = MS_MAX(1.0f + k * (m[i] - 1.0f), 0.0f);
    }
    if (nl) {
        /* slice 0: the floor before any shadow, sampled bilinearly at the
         * layer texels' centres (for ln = n / 2 the mean of 2 x 2) */
        for (int j = 0; j < ln; ++j)
            for (int i = 0; i < ln; ++i) {
                int i0, j0;
                float fi, fj;
                sample_axis(((float)i + 0.5f) / (float)ln, 0, 1.0f / (float)n, n, &i0, &fi);
                sample_axis(((float)j + 0.5f) / (float)ln, 0, 1.0f / (float)n, n, &j0, &fj);
                const float *a = map + (size_t)j0 * n + i0, *b = a + n;
                c->layers[(size_t)j * ln + i] =
                    (1 - fj) * ((1 - fi) * a[0] + fi * a[1]) + fj * ((1 - fi) * b[0] + fi * b[1]);
            }
    }
    if (d->occluders && d->occluder_verts >= 3 && (st = shade_floor(c, d)) != MS_OK)
        return st;
    if (rows > 0) {
        blur_walls(c);
        /* intensity scales each wall's contrast about its mean */
        for (int wall = 0; wall < 4; ++wall) {
            float *m = c->walls + (size_t)wall * rows * n;
            double mean = 0;
            for (size_t i = 0; i < (size_t)rows * n; ++i)
                mean += m[i];
            mean /= (double)rows * n;
            for (size_t i = 0; i < (size_t)rows * n; ++i)
                m[i] = MS_MAX((float)mean + k * (m[i] - (float)mean), 0.0f);
        }
    }
    return MS_OK;
}
