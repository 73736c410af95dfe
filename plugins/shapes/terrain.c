/* Shape plugin "terrain": a ground from a height map, a grey-scale PNG or
 * an array of heights, over a rectangle [0, sx] x [0, sy] of the local x-y
 * plane, solid from `base` below its lowest point up to the height surface.
 *
 * Parameters:
 *   {"png": "ground.png", "size": [sx, sy], "height_range": [zmin, zmax],
 *    "base": 0.05}
 *     png           grey-scale PNG, 8 or 16 bit; black is zmin, white zmax;
 *                   the image's top row is the y = sy edge (a map seen
 *                   from above); a relative path is taken from the current
 *                   directory (a scene file's is made relative to the
 *                   scene file's folder before it gets here);
 *   {"heights": [[h00, h10, ...], [h01, h11, ...], ...], "size": ..., "base": ...}
 *     heights       rows of heights (m), row j at y = j sy/(ny-1), sample i
 *                   at x = i sx/(nx-1); at least 2 x 2;
 *   size [1, 1] m, base 0.05 m (thickness below the lowest sample). Without
 *   "png" and "heights" the terrain is flat at z = 0.
 *
 * Height: bilinear between samples (height_at gives it exactly, so the
 * depth map z - h(x, y) that sets the wave speed is exact at cell centres).
 * Normal: the bilinear blend of the samples' normals (central differences),
 * continuous everywhere over the map. Distance: (z - h) / sqrt(1 + |grad h|^2)
 * above and below the height surface (exact for a plane, first order in the
 * curvature otherwise), combined with the sides and the bottom as for a box.
 */
#ifndef _POSIX_C_SOURCE
#define _POSIX_C_SOURCE 200809L /* open, fstat, fdopen */
#endif
#include <errno.h>
#include <fcntl.h>
#include <math.h>
#include <png.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "../common/host.h"
#include "../common/params.h"
#include "modesplit/plugin.h"

#define MAX_SAMPLES (1 << 24)

typedef struct terrain {
    int nx, ny;
    float sx, sy;   /* m */
    float dx, dy;   /* m, sample spacing */
    float zbot;     /* m */
    float zmax;     /* m */
    float *h;       /* ny * nx, m */
    float *gx, *gy; /* slopes at the samples, m/m */
} terrain;

static void terrain_destroy(void *self)
{
    terrain *t = self;
    if (!t)
        return;
    plugin_free(t->h);
    plugin_free(t->gx);
    plugin_free(t->gy);
    plugin_free(t);
}

static int alloc_maps(terrain *t, params *pm)
{
    size_t n = (size_t)t->nx * (size_t)t->ny;
    t->h = plugin_alloc(n * sizeof *t->h);
    t->gx = plugin_alloc(n * sizeof *t->gx);
    t->gy = plugin_alloc(n * sizeof *t->gy);
    if (!t->h || !t->gx || !t->gy) {
        params_fail(pm, MS_PLUGIN_ERR_OUT_OF_MEMORY, "out of memory for %d x %d heights", t->nx,
                    t->ny);
        return 0;
    }
    return 1;
}

static void read_heights(terrain *t, params *pm, json_t *rows)
{
    if (!json_is_array(rows) || json_array_size(rows) < 2) {
        params_fail(pm, MS_PLUGIN_ERR_PARSE, "heights must be an array of at least 2 rows");
        return;
    }
    json_t *row0 = json_array_get(rows, 0);
    if (!json_is_array(row0) || json_array_size(row0) < 2) {
        params_fail(pm, MS_PLUGIN_ERR_PARSE,
                    "heights[0] must be an array of at least 2 numbers (m)");
        return;
    }
    size_t ny = json_array_size(rows), nx = json_array_size(row0);
    if (nx * ny > MAX_SAMPLES) {
        params_fail(pm, MS_PLUGIN_ERR_INVALID_ARGUMENT,
                    "heights has %zu x %zu samples, more than %d", nx, ny, MAX_SAMPLES);
        return;
    }
    t->nx = (int)nx;
    t->ny = (int)ny;
    if (!alloc_maps(t, pm))
        return;
    for (size_t j = 0; j < ny; ++j) {
        json_t *row = json_array_get(rows, j);
        if (!json_is_array(row) || json_array_size(row) != nx) {
            params_fail(pm, MS_PLUGIN_ERR_PARSE,
                        "heights[%zu] must be an array of %zu numbers (m), as heights[0]", j, nx);
            return;
        }
        for (size_t i = 0; i < nx; ++i) {
            json_t *v = json_array_get(row, i);
            char key[64];
            snprintf(key, sizeof key, "heights[%zu][%zu]", j, i);
            if (!json_is_number(v)) {
                params_fail(pm, MS_PLUGIN_ERR_PARSE, "%s must be a number (m)", key);
                return;
            }
            t->h[j * nx + i] = params_check(pm, key, json_number_value(v), -1e6, 1e6, "m");
        }
    }
}

/* A grey-scale PNG through libpng's simplified API: 8-bit files are read
 * as 8-bit grey, 16-bit files as 16-bit grey, values unchanged. */
/* The PNG only when it is a regular file, opened without blocking: a FIFO
 * would hang the open (and `check`), a device such as /dev/zero or
 * /dev/stdin never ends. The same rule as the library's own inputs
 * (lib/core/file.c); a plugin cannot call the library's internals. */
static FILE *open_regular(const char *path, const char **why)
{
    int fd = open(path, O_RDONLY | O_NONBLOCK | O_NOCTTY | O_CLOEXEC);
    if (fd < 0) {
        *why = strerror(errno);
        return NULL;
    }
    struct stat sb;
    memset(&sb, 0, sizeof sb); /* a failed fstat reads as "not a regular file" */
    if (fstat(fd, &sb) != 0 || !S_ISREG(sb.st_mode)) {
        *why = S_ISDIR(sb.st_mode)    ? "a directory"
               : S_ISFIFO(sb.st_mode) ? "a FIFO (named pipe)"
               : S_ISCHR(sb.st_mode)  ? "a character device"
               : S_ISBLK(sb.st_mode)  ? "a block device"
                                      : "not a regular file";
        close(fd);
        return NULL;
    }
    int fl = fcntl(fd, F_GETFL);
    if (fl >= 0)
        (void)fcntl(fd, F_SETFL, fl & ~O_NONBLOCK);
    FILE *f = fdopen(fd, "rb");
    if (!f) {
        *why = strerror(errno);
        close(fd);
    }
    return f;
}

static void read_png_from(terrain *t, params *pm, FILE *f, const char *path, const float range[2]);

static void read_png(terrain *t, params *pm, const char *path, const float range[2])
{
    const char *why = "";
    FILE *f = open_regular(path, &why);
    if (!f) {
        params_fail(pm, MS_PLUGIN_ERR_IO, "png \"%s\" cannot be read: %s", path, why);
        return;
    }
    read_png_from(t, pm, f, path, range);
    fclose(f);
}

static void read_png_from(terrain *t, params *pm, FILE *f, const char *path, const float range[2])
{
    png_image img;
    memset(&img, 0, sizeof img);
    img.version = PNG_IMAGE_VERSION;
    if (!png_image_begin_read_from_stdio(&img, f)) {
        params_fail(pm, MS_PLUGIN_ERR_IO, "png \"%s\" cannot be read: %s", path, img.message);
        return;
    }
    if (img.format & PNG_FORMAT_FLAG_COLOR) {
        png_image_free(&img);
        params_fail(pm, MS_PLUGIN_ERR_INVALID_ARGUMENT,
                    "png \"%s\" is a colour image; a height map must be grey-scale", path);
        return;
    }
    if (img.width < 2 || img.height < 2 || (size_t)img.width * img.height > MAX_SAMPLES) {
        png_image_free(&img);
        params_fail(pm, MS_PLUGIN_ERR_INVALID_ARGUMENT,
                    "png \"%s\" is %u x %u pixels; a height map needs 2 x 2 to %d samples", path,
                    img.width, img.height, MAX_SAMPLES);
        return;
    }
    int wide = (img.format & PNG_FORMAT_FLAG_LINEAR) != 0; /* 16-bit file */
    img.format = wide ? PNG_FORMAT_LINEAR_Y : PNG_FORMAT_GRAY;
    t->nx = (int)img.width;
    t->ny = (int)img.height;
    void *pix = plugin_alloc(PNG_IMAGE_SIZE(img));
    if (!pix || !alloc_maps(t, pm)) {
        plugin_free(pix);
        png_image_free(&img);
        if (!pix)
            params_fail(pm, MS_PLUGIN_ERR_OUT_OF_MEMORY, "out of memory reading png \"%s\"", path);
        return;
    }
    if (!png_image_finish_read(&img, NULL, pix, 0, NULL)) {
        plugin_free(pix);
        params_fail(pm, MS_PLUGIN_ERR_IO, "png \"%s\" cannot be decoded: %s", path, img.message);
        return;
    }
    const float scale = (range[1] - range[0]) / (wide ? 65535.0f : 255.0f);
    for (size_t r = 0; r < (size_t)t->ny; ++r) {
        size_t j = (size_t)t->ny - 1 - r; /* top row = far edge, y = sy */
        for (size_t i = 0; i < (size_t)t->nx; ++i) {
            size_t k = r * (size_t)t->nx + i;
            float v =
                wide ? (float)((const png_uint_16 *)pix)[k] : (float)((const png_byte *)pix)[k];
            t->h[j * (size_t)t->nx + i] = range[0] + scale * v;
        }
    }
    plugin_free(pix);
}

static void slopes(terrain *t)
{
    const int nx = t->nx, ny = t->ny;
    for (int j = 0; j < ny; ++j)
        for (int i = 0; i < nx; ++i) {
            int i0 = i > 0 ? i - 1 : i, i1 = i < nx - 1 ? i + 1 : i;
            int j0 = j > 0 ? j - 1 : j, j1 = j < ny - 1 ? j + 1 : j;
            const float *h = t->h;
            t->gx[j * nx + i] = (h[j * nx + i1] - h[j * nx + i0]) / ((float)(i1 - i0) * t->dx);
            t->gy[j * nx + i] = (h[j1 * nx + i] - h[j0 * nx + i]) / ((float)(j1 - j0) * t->dy);
        }
}

static int terrain_create(const char *json, void **out, char *err, size_t err_size)
{
    static const char *const keys[] = {"png", "heights", "size", "height_range", "base", NULL};
    static const float dsize[2] = {1, 1}, drange[2] = {0, 0.1f};
    params pm;
    terrain *t = plugin_calloc(1, sizeof *t);
    if (!t) {
        snprintf(err, err_size, "out of memory");
        return MS_PLUGIN_ERR_OUT_OF_MEMORY;
    }
    float size[2] = {1, 1}, range[2] = {0, 0.1f}, base = 0.05f;
    if (params_open(&pm, json, keys, err, err_size) == MS_PLUGIN_OK) {
        params_vec(&pm, "size", 2, size, dsize, 1e-6, 1e6, "m");
        params_vec(&pm, "height_range", 2, range, drange, -1e6, 1e6, "m");
        base = params_number(&pm, "base", base, 1e-6, 1e6, "m");
        const char *png = params_string(&pm, "png", NULL);
        json_t *heights = params_get(&pm, "heights");
        if (pm.rc == MS_PLUGIN_OK && png && heights)
            params_fail(&pm, MS_PLUGIN_ERR_INVALID_ARGUMENT,
                        "png and heights are both given; a terrain takes one of them");
        else if (pm.rc == MS_PLUGIN_OK && heights && params_has(&pm, "height_range"))
            params_fail(&pm, MS_PLUGIN_ERR_INVALID_ARGUMENT,
                        "height_range applies to png only; heights are in metres");
        else if (pm.rc == MS_PLUGIN_OK && png)
            read_png(t, &pm, png, range);
        else if (pm.rc == MS_PLUGIN_OK && heights)
            read_heights(t, &pm, heights);
        else if (pm.rc == MS_PLUGIN_OK) { /* flat at z = 0 */
            t->nx = t->ny = 2;
            if (alloc_maps(t, &pm))
                memset(t->h, 0, 4 * sizeof *t->h);
        }
    }
    int rc = params_close(&pm);
    if (rc != MS_PLUGIN_OK) {
        terrain_destroy(t);
        return rc;
    }
    t->sx = size[0];
    t->sy = size[1];
    t->dx = t->sx / (float)(t->nx - 1);
    t->dy = t->sy / (float)(t->ny - 1);
    float lo = t->h[0], hi = t->h[0];
    for (size_t k = 0; k < (size_t)t->nx * (size_t)t->ny; ++k) {
        lo = fminf(lo, t->h[k]);
        hi = fmaxf(hi, t->h[k]);
    }
    t->zbot = lo - base;
    t->zmax = hi;
    slopes(t);
    *out = t;
    return MS_PLUGIN_OK;
}

/* Bilinear height and slopes at (x, y), clamped to the map. */
static void sample(const terrain *t, float x, float y, float *h, float *gx, float *gy)
{
    float u = fminf(fmaxf(x / t->dx, 0.0f), (float)(t->nx - 1));
    float v = fminf(fmaxf(y / t->dy, 0.0f), (float)(t->ny - 1));
    int i = (int)u, j = (int)v;
    i = i > t->nx - 2 ? t->nx - 2 : i;
    j = j > t->ny - 2 ? t->ny - 2 : j;
    float fu = u - (float)i, fv = v - (float)j;
    size_t k = (size_t)j * (size_t)t->nx + (size_t)i, nx = (size_t)t->nx;
    float w00 = (1 - fu) * (1 - fv), w10 = fu * (1 - fv), w01 = (1 - fu) * fv, w11 = fu * fv;
#define BILERP(a) (w00 * (a)[k] + w10 * (a)[k + 1] + w01 * (a)[k + nx] + w11 * (a)[k + nx + 1])
    *h = BILERP(t->h);
    if (gx) {
        *gx = BILERP(t->gx);
        *gy = BILERP(t->gy);
    }
#undef BILERP
}

static float terrain_distance(const void *self, const float p[3], float n[3])
{
    const terrain *t = self;
    float h, gx, gy;
    sample(t, p[0], p[1], &h, &gx, &gy);
    float k = 1.0f / sqrtf(1.0f + gx * gx + gy * gy);
    /* the four faces: excess e (m) over each, and its outward normal */
    float sxn = p[0] < 0.5f * t->sx ? -1.0f : 1.0f, syn = p[1] < 0.5f * t->sy ? -1.0f : 1.0f;
    const float e[4] = {fmaxf(-p[0], p[0] - t->sx), fmaxf(-p[1], p[1] - t->sy), (p[2] - h) * k,
                        t->zbot - p[2]};
    const float dir[4][3] = {{sxn, 0, 0}, {0, syn, 0}, {-gx * k, -gy * k, k}, {0, 0, -1}};
    double out2 = 0, m[3] = {0, 0, 0};
    float emax = e[0];
    for (int c = 0; c < 4; ++c) {
        emax = fmaxf(emax, e[c]);
        if (e[c] > 0) {
            out2 += (double)e[c] * e[c];
            for (int a = 0; a < 3; ++a)
                m[a] += (double)e[c] * dir[c][a];
        }
    }
    float d = out2 > 0 ? (float)sqrt(out2) : emax;
    if (n) {
        if (!(out2 > 0)) { /* inside: blend faces by relative depth */
            float tmin = -emax;
            for (int c = 0; c < 4; ++c) {
                float tc = -e[c];
                float w =
                    tmin > 0 ? fmaxf(0.0f, 1.0f - (tc - tmin) / tmin) : (tc <= tmin ? 1.0f : 0.0f);
                for (int a = 0; a < 3; ++a)
                    m[a] += (double)w * dir[c][a];
            }
        }
        double l = sqrt(m[0] * m[0] + m[1] * m[1] + m[2] * m[2]);
        for (int a = 0; a < 3; ++a)
            n[a] = l > 0 ? (float)(m[a] / l) : (a == 2 ? 1.0f : 0.0f);
    }
    return d;
}

static void terrain_bounds(const void *self, float lo[3], float hi[3])
{
    const terrain *t = self;
    lo[0] = 0;
    lo[1] = 0;
    lo[2] = t->zbot;
    hi[0] = t->sx;
    hi[1] = t->sy;
    hi[2] = t->zmax;
}

static int terrain_height_at(const void *self, float x, float y, float *top)
{
    const terrain *t = self;
    if (x < 0 || y < 0 || x > t->sx || y > t->sy)
        return 0;
    sample(t, x, y, top, NULL, NULL);
    return 1;
}

static const ms_shape_vtable terrain_vtable = {
    .size = sizeof(ms_shape_vtable),
    .create = terrain_create,
    .destroy = terrain_destroy,
    .distance = terrain_distance,
    .bounds = terrain_bounds,
    .height_at = terrain_height_at,
};

static const ms_plugin_info terrain_info = {
    .abi = MS_PLUGIN_ABI,
    .size = sizeof(ms_plugin_info),
    .name = "terrain",
    .version = "1.0",
    .kind = MS_PLUGIN_SHAPE,
    .description = "ground from a grey-scale PNG or an array of heights (m)",
    .vtable = &terrain_vtable,
    .set_host = plugin_set_host,
};

const ms_plugin_info *ms_plugin_entry(void)
{
    return &terrain_info;
}
