/* lib/io: a shaded-relief preview of a height field, as RGB pixels or a
 * PNG (libpng). This is not the renderer (lib/render: cubemaps, Fresnel,
 * caustics); it is the quick look the tool writes with --png when no
 * renderer is available.
 *
 * Colour: the height, scaled to [0, 1] over the desc's range, picks a
 * colour on a water ramp (deep navy troughs, blue, turquoise, pale
 * crests). Light: a hillshade, Lambert's cosine law n.L with the normal of
 * the exaggerated surface z = relief * h(x, y) from central differences
 * (one-sided at the edges), scaled so flat water keeps its ramp colour.
 * The image has north up: its top row is the grid's largest y. With
 * scale > 1 the cell colours are interpolated bilinearly between cell
 * centres (a cell with a non-finite height stays a magenta block).
 * The PNG is written to "<path>.tmp" and renamed, so no half-written
 * preview is ever seen under the final name.
 */
#include <errno.h>
#include <png.h>
#include <setjmp.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "io/io_internal.h"
#include "io/io_sizes.h"

#define DEG_TO_RAD 0.017453292519943295
#define AMBIENT 0.35f /* share of the light that does not depend on the slope */
#define MAX_PIXELS (1L << 28)

ms_preview_desc ms_preview_desc_default(void)
{
    ms_preview_desc d = {
        .size = (uint32_t)sizeof(ms_preview_desc),
        .dx = 0.01f,
        .dy = 0.01f,
        .height_min = 0.0f,
        .height_max = 0.0f,
        .relief = 1.0f,
        .sun_azimuth = 315.0f,
        .sun_elevation = 45.0f,
        .scale = 1,
    };
    return d;
}

/* The caller's desc read at its size (core.h: struct sizes) into *d, then
 * checked. */
static ms_status check_desc(const float *h, int nx, int ny, const ms_preview_desc *user,
                            ms_preview_desc *d)
{
    ms_status st;
    *d = ms_preview_desc_default();
    if ((st = ms_check_not_null("preview", "height field", h)) != MS_OK ||
        (st = ms_struct_in(user, d, MS_SIZES_PREVIEW_DESC, "preview")) != MS_OK ||
        (st = ms_check_int_range("preview", "nx", nx, 1, MS_IO_MAX_SIDE)) != MS_OK ||
        (st = ms_check_int_range("preview", "ny", ny, 1, MS_IO_MAX_SIDE)) != MS_OK ||
        (st = ms_check_positive("preview", "dx", d->dx, "m")) != MS_OK ||
        (st = ms_check_positive("preview", "dy", d->dy, "m")) != MS_OK ||
        (st = ms_check_finite("preview", "height_min", d->height_min)) != MS_OK ||
        (st = ms_check_finite("preview", "height_max", d->height_max)) != MS_OK ||
        (st = ms_check_range("preview", "relief", d->relief, 0, 1e6, "")) != MS_OK ||
        (st = ms_check_finite("preview", "sun_azimuth", d->sun_azimuth)) != MS_OK ||
        (st = ms_check_range("preview", "sun_elevation", d->sun_elevation, 1e-3, 90, "degrees")) !=
            MS_OK ||
        (st = ms_check_int_range("preview", "scale", d->scale, 1, 16)) != MS_OK)
        return st;
    if (d->height_min > d->height_max)
        return ms_fail(MS_ERR_INVALID_ARGUMENT, "preview: height_min %g m is above height_max %g m",
                       (double)d->height_min, (double)d->height_max);
    long w = (long)nx * d->scale, hgt = (long)ny * d->scale;
    if (w * hgt > MAX_PIXELS)
        return ms_fail(MS_ERR_INVALID_ARGUMENT,
                       "preview: image %ld x %ld pixels is over %ld pixels", w, hgt, MAX_PIXELS);
    return MS_OK;
}

/* The water ramp: s in [0, 1] to RGB in [0, 1]. */
static void ramp(float s, float rgb[3])
{
    static const float stops[5][4] = {
        {0.00f, 0.02f, 0.09f, 0.28f}, /* deep trough: navy */
        {0.35f, 0.04f, 0.32f, 0.58f}, /* blue */
        {0.60f, 0.10f, 0.58f, 0.68f}, /* turquoise */
        {0.85f, 0.52f, 0.84f, 0.86f}, /* light crest */
        {1.00f, 0.95f, 0.98f, 1.00f}, /* foam */
    };
    s = MS_CLAMP(s, 0.0f, 1.0f);
    int i = 0;
    while (i < 3 && s > stops[i + 1][0])
        ++i;
    float t = (s - stops[i][0]) / (stops[i + 1][0] - stops[i][0]);
    for (int c = 0; c < 3; ++c)
        rgb[c] = stops[i][c + 1] + t * (stops[i + 1][c + 1] - stops[i][c + 1]);
}

static float at(const float *h, int nx, int x, int y)
{
    return h[(size_t)y * (size_t)nx + (size_t)x];
}

/* d/dx by central differences, one-sided at the edges, 0 for one cell or
 * a non-finite neighbour. */
static float slope(const float *h, int nx, int ny, int x, int y, int ax, float step)
{
    int n = ax ? ny : nx, i = ax ? y : x;
    if (n < 2)
        return 0.0f;
    int lo = i > 0 ? i - 1 : i, hi = i < n - 1 ? i + 1 : i;
    float a = ax ? at(h, nx, x, lo) : at(h, nx, lo, y);
    float b = ax ? at(h, nx, x, hi) : at(h, nx, hi, y);
    float g = (b - a) / ((float)(hi - lo) * step);
    return isfinite(g) ? g : 0.0f;
}

ms_status ms_field_shade(const float *h, int nx, int ny, const ms_preview_desc *user,
                         unsigned char *rgb, size_t rgb_bytes)
{
    ms_preview_desc desc, *d = &desc;
    ms_status st = check_desc(h, nx, ny, user, &desc);
    if (st != MS_OK || (st = ms_check_not_null("preview", "rgb", rgb)) != MS_OK)
        return st;
    size_t w = (size_t)nx * (size_t)d->scale;
    if (rgb_bytes < w * (size_t)ny * (size_t)d->scale * 3)
        return ms_fail(MS_ERR_INVALID_ARGUMENT,
                       "preview: rgb holds %zu bytes but %zu x %zu pixels need %zu", rgb_bytes, w,
                       (size_t)ny * (size_t)d->scale, w * (size_t)ny * (size_t)d->scale * 3);
    float lo = d->height_min, hi = d->height_max;
    if (lo == hi) {
        double mn = INFINITY, mx = -INFINITY;
        for (size_t i = 0; i < (size_t)nx * (size_t)ny; ++i)
            if (isfinite(h[i])) {
                mn = h[i] < mn ? h[i] : mn;
                mx = h[i] > mx ? h[i] : mx;
            }
        lo = isfinite(mn) ? (float)mn : 0.0f;
        hi = isfinite(mx) ? (float)mx : 0.0f;
    }
    float inv_range = hi > lo ? 1.0f / (hi - lo) : 0.0f;
    double az = d->sun_azimuth * DEG_TO_RAD, el = d->sun_elevation * DEG_TO_RAD;
    float lx = (float)(sin(az) * cos(el)), ly = (float)(cos(az) * cos(el));
    float lz = (float)sin(el);
    /* Cell colours first (NaN red marks a non-finite height)... */
    float *cell = ms_malloc((size_t)nx * (size_t)ny * 3 * sizeof *cell);
    if (!cell)
        return ms_fail(MS_ERR_OUT_OF_MEMORY, "preview: out of memory for %d x %d cells", nx, ny);
    for (int y = 0; y < ny; ++y) {
        for (int x = 0; x < nx; ++x) {
            float v = at(h, nx, x, y);
            float *c = cell + ((size_t)y * (size_t)nx + (size_t)x) * 3;
            if (!isfinite(v)) {
                c[0] = NAN;
                continue;
            }
            ramp(hi > lo ? (v - lo) * inv_range : 0.5f, c);
            float gx = d->relief * slope(h, nx, ny, x, y, 0, d->dx);
            float gy = d->relief * slope(h, nx, ny, x, y, 1, d->dy);
            float ndotl = (-gx * lx - gy * ly + lz) / sqrtf(gx * gx + gy * gy + 1.0f);
            float light = AMBIENT + (1.0f - AMBIENT) * MS_MAX(ndotl, 0.0f) / lz;
            for (int k = 0; k < 3; ++k)
                c[k] = MS_CLAMP(c[k] * light, 0.0f, 1.0f);
        }
    }
    /* ...then pixels: bilinear between cell centres (nearest next to a
     * non-finite cell, which stays magenta), top row = largest y. */
    size_t hgt = (size_t)ny * (size_t)d->scale;
    float inv_scale = 1.0f / (float)d->scale;
    for (size_t j = 0; j < hgt; ++j) {
        float v = ((float)(hgt - 1 - j) + 0.5f) * inv_scale - 0.5f;
        v = MS_CLAMP(v, 0.0f, (float)(ny - 1));
        int y0 = (int)v, y1 = y0 + 1 < ny ? y0 + 1 : y0;
        float fy = v - (float)y0;
        for (size_t i = 0; i < w; ++i) {
            float u = ((float)i + 0.5f) * inv_scale - 0.5f;
            u = MS_CLAMP(u, 0.0f, (float)(nx - 1));
            int x0 = (int)u, x1 = x0 + 1 < nx ? x0 + 1 : x0;
            float fx = u - (float)x0;
            const float *c00 = cell + ((size_t)y0 * (size_t)nx + (size_t)x0) * 3;
            const float *c10 = cell + ((size_t)y0 * (size_t)nx + (size_t)x1) * 3;
            const float *c01 = cell + ((size_t)y1 * (size_t)nx + (size_t)x0) * 3;
            const float *c11 = cell + ((size_t)y1 * (size_t)nx + (size_t)x1) * 3;
            unsigned char *px = rgb + (j * w + i) * 3;
            if (isnan(c00[0]) || isnan(c10[0]) || isnan(c01[0]) || isnan(c11[0])) {
                const float *c = fx < 0.5f ? (fy < 0.5f ? c00 : c01) : (fy < 0.5f ? c10 : c11);
                if (isnan(c[0])) {
                    px[0] = 255, px[1] = 0, px[2] = 255;
                } else {
                    for (int k = 0; k < 3; ++k)
                        px[k] = (unsigned char)lrintf(255.0f * c[k]);
                }
                continue;
            }
            for (int k = 0; k < 3; ++k) {
                float a = c00[k] + fx * (c10[k] - c00[k]);
                float b = c01[k] + fx * (c11[k] - c01[k]);
                px[k] = (unsigned char)lrintf(255.0f * (a + fy * (b - a)));
            }
        }
    }
    ms_free(cell);
    return MS_OK;
}

typedef struct png_err {
    char msg[200];
} png_err;

static void on_png_error(png_structp png, png_const_charp msg)
{
    png_err *e = png_get_error_ptr(png);
    snprintf(e->msg, sizeof e->msg, "%s", msg);
    png_longjmp(png, 1);
}

static void on_png_warning(png_structp png, png_const_charp msg)
{
    (void)png;
    (void)msg; /* the library never prints */
}

/* Everything volatile that setjmp's return may need. */
static ms_status write_rgb_png(FILE *fp, const unsigned char *rgb, size_t w, size_t hgt,
                               png_err *err)
{
    png_structp png =
        png_create_write_struct(PNG_LIBPNG_VER_STRING, err, on_png_error, on_png_warning);
    if (!png)
        return MS_ERR_OUT_OF_MEMORY;
    png_infop info = png_create_info_struct(png);
    if (!info) {
        png_destroy_write_struct(&png, NULL);
        return MS_ERR_OUT_OF_MEMORY;
    }
    if (setjmp(png_jmpbuf(png))) {
        png_destroy_write_struct(&png, &info);
        return MS_ERR_IO;
    }
    png_init_io(png, fp);
    png_set_IHDR(png, info, (png_uint_32)w, (png_uint_32)hgt, 8, PNG_COLOR_TYPE_RGB,
                 PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
    png_set_compression_level(png, 3);
    png_write_info(png, info);
    for (size_t y = 0; y < hgt; ++y)
        png_write_row(png, rgb + y * w * 3);
    png_write_end(png, NULL);
    png_destroy_write_struct(&png, &info);
    return MS_OK;
}

ms_status ms_field_write_png(const float *h, int nx, int ny, const char *path,
                             const ms_preview_desc *user)
{
    ms_preview_desc desc, *d = &desc;
    ms_status st = check_desc(h, nx, ny, user, &desc);
    if (st != MS_OK || (st = ms_check_not_null("preview", "path", path)) != MS_OK)
        return st;
    size_t w = (size_t)nx * (size_t)d->scale, hgt = (size_t)ny * (size_t)d->scale;
    unsigned char *rgb = ms_malloc(w * hgt * 3);
    if (!rgb)
        return ms_fail(MS_ERR_OUT_OF_MEMORY, "preview: out of memory for %zu x %zu pixels", w, hgt);
    st = ms_field_shade(h, nx, ny, d, rgb, w * hgt * 3);
    if (st != MS_OK) {
        ms_free(rgb);
        return st;
    }
    size_t n = strlen(path);
    char *tmp = ms_malloc(n + 5);
    if (!tmp) {
        ms_free(rgb);
        return ms_fail(MS_ERR_OUT_OF_MEMORY, "preview: out of memory");
    }
    memcpy(tmp, path, n);
    memcpy(tmp + n, ".tmp", 5);
    FILE *fp = fopen(tmp, "wb");
    if (!fp) {
        st = ms_fail(MS_ERR_IO, "preview: cannot create %s: %s", path, strerror(errno));
    } else {
        png_err err = {""};
        errno = 0;
        st = write_rgb_png(fp, rgb, w, hgt, &err);
        int e = errno;
        int closed = fclose(fp);
        if (closed != 0 && !e)
            e = errno;
        if (st == MS_ERR_OUT_OF_MEMORY)
            st = ms_fail(st, "preview: out of memory in libpng");
        else if (st != MS_OK || closed != 0)
            st = ms_fail(MS_ERR_IO, "preview: writing %s failed: %s", path,
                         e            ? strerror(e)
                         : err.msg[0] ? err.msg
                                      : "unknown libpng error");
        else if (rename(tmp, path) != 0)
            st = ms_fail(MS_ERR_IO, "preview: cannot rename %s to %s: %s", tmp, path,
                         strerror(errno));
        if (st != MS_OK)
            remove(tmp);
    }
    ms_free(tmp);
    ms_free(rgb);
    return st;
}
