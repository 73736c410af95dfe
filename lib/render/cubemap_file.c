/* Cubemaps from files (libpng's simplified API): a directory of six square
 * PNG faces named by world axes (px nx py ny pz nz, or posx ... negz), or
 * one PNG of the six faces stacked top to bottom in that order. Faces are
 * taken as they are (sRGB, OpenGL's cube map layout); grey or paletted
 * PNGs are converted to RGBA by libpng. */
#include <errno.h>
#include <math.h>
#include <png.h>
#include <setjmp.h>
#include <stdio.h>
#include <string.h>
#include <sys/stat.h>

#include "core/core_internal.h"
#include "render/render_internal.h"

#define MAX_FACE 4096 /* texels per side */

static const char *const short_names[6] = {"px", "nx", "py", "ny", "pz", "nz"};
static const char *const long_names[6] = {"posx", "negx", "posy", "negy", "posz", "negz"};

/* Opens a PNG (a regular file only: ms_fopen_regular) and checks the size
 * in its header against max_w x max_h before anything is decoded (a small
 * PNG can declare faces of gigabytes); on failure *img is freed and *fp
 * closed, on success the caller closes *fp after the read. */
static ms_status open_png(const char *path, int max_w, int max_h, png_image *img, FILE **fp)
{
    memset(img, 0, sizeof *img);
    img->version = PNG_IMAGE_VERSION;
    const char *why;
    FILE *f = ms_fopen_regular(path, &why);
    *fp = NULL;
    if (!f)
        return ms_fail(MS_ERR_IO, "render: cubemap \"%s\" cannot be read: %s", path, why);
    if (!png_image_begin_read_from_stdio(img, f)) {
        fclose(f);
        ms_status st = ms_fail(MS_ERR_PARSE, "render: cubemap \"%s\" is not a readable PNG (%s)",
                               path, img->message);
        png_image_free(img);
        return st;
    }
    if (img->width < 1 || img->height < 1 || img->width > (unsigned)max_w ||
        img->height > (unsigned)max_h) {
        png_image_free(img);
        fclose(f);
        return ms_fail(MS_ERR_INVALID_ARGUMENT,
                       "render: cubemap \"%s\" is %u x %u pixels (at most %d x %d here); faces "
                       "may be at most %d texels a side",
                       path, (unsigned)img->width, (unsigned)img->height, max_w, max_h, MAX_FACE);
    }
    *fp = f;
    return MS_OK;
}

/* Reads a PNG as RGBA8; *w, *h its size (open_png checks it first). */
static ms_status read_png(const char *path, int max_w, int max_h, unsigned char **out, int *w,
                          int *h)
{
    png_image img;
    FILE *f;
    *out = NULL;
    MS_TRY(open_png(path, max_w, max_h, &img, &f));
    img.format = PNG_FORMAT_RGBA;
    unsigned char *px = ms_alloc(PNG_IMAGE_SIZE(img));
    if (!px) {
        png_image_free(&img);
        fclose(f);
        return ms_fail(MS_ERR_OUT_OF_MEMORY, "render: out of memory for cubemap \"%s\"", path);
    }
    int done = png_image_finish_read(&img, NULL, px, 0, NULL);
    fclose(f);
    if (!done) {
        ms_status st = ms_fail(MS_ERR_PARSE, "render: cubemap \"%s\" cannot be decoded (%s)", path,
                               img.message);
        png_image_free(&img);
        ms_free(px);
        return st;
    }
    *w = (int)img.width;
    *h = (int)img.height;
    *out = px;
    return MS_OK;
}

/* libpng's errors as a sentence (longjmp back to decode_rows); its
 * warnings are not the caller's business. */
typedef struct png_err {
    jmp_buf jump;
    char message[160];
} png_err;

static void on_png_error(png_structp png, png_const_charp message)
{
    png_err *e = png_get_error_ptr(png);
    snprintf(e->message, sizeof e->message, "%s", message);
    longjmp(e->jump, 1);
}

static void on_png_warning(png_structp png, png_const_charp message)
{
    (void)png;
    (void)message;
}

/* Every row of a PNG decoded, one row of memory at a time, the pixels
 * dropped: what ms_cubemap_load meets past the header (a face cut short,
 * corrupt data) found without the face's memory, so that the check
 * refuses what loading refuses. The header was checked by open_png. */
static ms_status decode_rows(const char *path)
{
    const char *why;
    FILE *f = ms_fopen_regular(path, &why);
    if (!f)
        return ms_fail(MS_ERR_IO, "render: cubemap \"%s\" cannot be read: %s", path, why);
    png_err e;
    e.message[0] = '\0';
    png_structp png =
        png_create_read_struct(PNG_LIBPNG_VER_STRING, &e, on_png_error, on_png_warning);
    png_infop info = png ? png_create_info_struct(png) : NULL;
    unsigned char *volatile row = NULL;
    ms_status st = MS_OK;
    if (!info) {
        st = ms_fail(MS_ERR_OUT_OF_MEMORY, "render: out of memory for cubemap \"%s\"", path);
    } else if (setjmp(e.jump)) {
        st =
            ms_fail(MS_ERR_PARSE, "render: cubemap \"%s\" cannot be decoded (%s)", path, e.message);
    } else {
        png_init_io(png, f);
        png_read_info(png, info);
        int passes = png_set_interlace_handling(png);
        png_read_update_info(png, info);
        png_uint_32 h = png_get_image_height(png, info);
        row = ms_alloc(png_get_rowbytes(png, info));
        if (!row)
            st = ms_fail(MS_ERR_OUT_OF_MEMORY, "render: out of memory for cubemap \"%s\"", path);
        for (int pass = 0; row && pass < passes; ++pass)
            for (png_uint_32 y = 0; y < h; ++y)
                png_read_row(png, row, NULL);
    }
    ms_free(row);
    png_destroy_read_struct(png ? &png : NULL, info ? &info : NULL, NULL);
    fclose(f);
    return st;
}

static int file_exists(const char *path)
{
    struct stat sb;
    return stat(path, &sb) == 0 && S_ISREG(sb.st_mode);
}

/* Face f of the cubemap directory dir: its path into path, or a refusal. */
static ms_status face_path(const char *dir, int f, char *path, size_t size)
{
    snprintf(path, size, "%s/%s.png", dir, short_names[f]);
    if (!file_exists(path))
        snprintf(path, size, "%s/%s.png", dir, long_names[f]);
    if (!file_exists(path))
        return ms_fail(MS_ERR_IO,
                       "render: cubemap directory \"%s\" has no %s.png (or %s.png) as a "
                       "regular file; it needs six faces px nx py ny pz nz",
                       dir, short_names[f], long_names[f]);
    return MS_OK;
}

/* Face f of w x h texels after faces of `size` (f > 0): square, one size. */
static ms_status check_face(const char *path, int f, int w, int h, int size)
{
    if (w != h || (f > 0 && w != size))
        return ms_fail(MS_ERR_INVALID_ARGUMENT,
                       "render: cubemap face \"%s\" is %d x %d texels; faces must be "
                       "square and all of one size (%d)",
                       path, w, h, f > 0 ? size : w);
    return MS_OK;
}

/* A single-file cubemap of w x h pixels: six square faces stacked. */
static ms_status check_strip(const char *path, int w, int h)
{
    if (h != 6 * w || w > MAX_FACE)
        return ms_fail(MS_ERR_INVALID_ARGUMENT,
                       "render: cubemap \"%s\" is %d x %d pixels; a single-file cubemap is six "
                       "square faces stacked (height = 6 x width, width <= %d)",
                       path, w, h, MAX_FACE);
    return MS_OK;
}

static ms_status load_dir(const char *dir, ms_cubemap *out)
{
    for (int f = 0; f < 6; ++f) {
        char path[4096];
        MS_TRY(face_path(dir, f, path, sizeof path));
        int w, h;
        MS_TRY(read_png(path, MAX_FACE, MAX_FACE, &out->face[f], &w, &h));
        MS_TRY(check_face(path, f, w, h, out->size));
        out->size = w;
    }
    return MS_OK;
}

static ms_status load_strip(const char *path, ms_cubemap *out)
{
    unsigned char *px;
    int w, h;
    ms_status st = read_png(path, MAX_FACE, 6 * MAX_FACE, &px, &w, &h);
    if (st != MS_OK)
        return st;
    if ((st = check_strip(path, w, h)) != MS_OK) {
        ms_free(px);
        return st;
    }
    size_t face = (size_t)w * (size_t)w * 4;
    for (int f = 0; f < 6; ++f) {
        out->face[f] = ms_alloc(face);
        if (!out->face[f]) {
            ms_free(px);
            return ms_fail(MS_ERR_OUT_OF_MEMORY, "render: out of memory for cubemap \"%s\"", path);
        }
        memcpy(out->face[f], px + (size_t)f * face, face);
    }
    out->size = w;
    ms_free(px);
    return MS_OK;
}

ms_status ms_cubemap_check_path(const char *path)
{
    ms_status st = ms_check_not_null("render", "cubemap", path);
    if (st != MS_OK || strcmp(path, "builtin") == 0)
        return st;
    struct stat sb;
    if (!*path || stat(path, &sb) != 0)
        return ms_fail(MS_ERR_IO,
                       "render: cubemap \"%s\" %s (%s); allowed: \"builtin\", a directory of six "
                       "PNG faces or one PNG strip",
                       path, *path && errno == ENOENT ? "does not exist" : "cannot be opened",
                       *path ? strerror(errno) : "empty name");
    if (S_ISDIR(sb.st_mode)) {
        char face[4096];
        for (int f = 0; f < 6 && st == MS_OK; ++f)
            st = face_path(path, f, face, sizeof face);
        return st;
    }
    if (!S_ISREG(sb.st_mode))
        return ms_fail(MS_ERR_IO,
                       "render: cubemap \"%s\" is %s; allowed: \"builtin\", a directory of "
                       "six PNG faces or one PNG strip (regular files)",
                       path, ms_file_kind(sb.st_mode));
    return MS_OK;
}

ms_status ms_cubemap_load(const char *path, ms_cubemap *out)
{
    out->size = 0;
    for (int f = 0; f < 6; ++f)
        out->face[f] = NULL;
    ms_status st = ms_cubemap_check_path(path);
    if (st != MS_OK)
        return st;
    struct stat sb;
    if (stat(path, &sb) != 0)
        return ms_fail(MS_ERR_IO, "render: cubemap \"%s\" cannot be opened (%s)", path,
                       strerror(errno));
    st = S_ISDIR(sb.st_mode) ? load_dir(path, out) : load_strip(path, out);
    if (st != MS_OK)
        ms_cubemap_free(out);
    return st;
}

ms_status ms_sky_write_cubemap(const char *dir, int size, const float light_dir[3])
{
    ms_status st;
    if ((st = ms_check_not_null("render", "dir", dir)) != MS_OK ||
        (st = ms_check_not_null("render", "light_dir", light_dir)) != MS_OK ||
        (st = ms_check_int_range("render", "cubemap size", size, 16, MAX_FACE)) != MS_OK)
        return st;
    for (int k = 0; k < 3; ++k)
        if ((st = ms_check_range("render", "light_dir", light_dir[k], -1e6, 1e6, "")) != MS_OK)
            return st;
    double l = sqrt((double)light_dir[0] * light_dir[0] + (double)light_dir[1] * light_dir[1] +
                    (double)light_dir[2] * light_dir[2]);
    if (!(l > 1e-6))
        return ms_fail(MS_ERR_INVALID_ARGUMENT,
                       "render: light_dir [%g, %g, %g] is the zero vector; it must be a "
                       "direction",
                       (double)light_dir[0], (double)light_dir[1], (double)light_dir[2]);
    if (!*dir)
        return ms_fail(MS_ERR_INVALID_ARGUMENT, "render: cubemap directory \"\" is empty");
    /* dir and its parents, as mkdir -p */
    size_t dn = strlen(dir);
    char *p = ms_alloc(dn + 1);
    if (!p)
        return ms_fail(MS_ERR_OUT_OF_MEMORY, "render: out of memory for a file name");
    memcpy(p, dir, dn + 1);
    int err = 0;
    for (size_t i = 1; i <= dn && !err; ++i)
        if (p[i] == '/' || p[i] == '\0') {
            char c = p[i];
            p[i] = '\0';
            if (mkdir(p, 0777) != 0 && errno != EEXIST)
                err = errno;
            p[i] = c;
        }
    ms_free(p);
    struct stat sb;
    if (!err && (stat(dir, &sb) != 0 || !S_ISDIR(sb.st_mode)))
        err = ENOTDIR;
    if (err)
        return ms_fail(MS_ERR_IO, "render: cannot create the cubemap directory \"%s\": %s", dir,
                       strerror(err));
    const float unit[3] = {(float)(light_dir[0] / l), (float)(light_dir[1] / l),
                           (float)(light_dir[2] / l)};
    ms_cubemap sky = {0, {NULL}};
    if ((st = ms_sky_builtin(size, unit, &sky)) != MS_OK)
        return st;
    for (int f = 0; f < 6 && st == MS_OK; ++f) {
        size_t n = strlen(dir) + 16;
        char *path = ms_alloc(n);
        if (!path) {
            st = ms_fail(MS_ERR_OUT_OF_MEMORY, "render: out of memory for a file name");
            break;
        }
        snprintf(path, n, "%s/%s.png", dir, short_names[f]);
        st = ms_png_write_rgba(path, sky.face[f], size, size);
        ms_free(path);
    }
    ms_cubemap_free(&sky);
    return st;
}

ms_status ms_cubemap_probe(const char *path)
{
    MS_TRY(ms_cubemap_check_path(path));
    struct stat sb;
    if (stat(path, &sb) != 0)
        return ms_fail(MS_ERR_IO, "render: cubemap \"%s\" cannot be opened (%s)", path,
                       strerror(errno));
    png_image img;
    FILE *fp;
    if (!S_ISDIR(sb.st_mode)) {
        MS_TRY(open_png(path, MAX_FACE, 6 * MAX_FACE, &img, &fp));
        int w = (int)img.width, h = (int)img.height;
        png_image_free(&img);
        fclose(fp);
        MS_TRY(check_strip(path, w, h));
        return decode_rows(path);
    }
    int size = 0;
    for (int f = 0; f < 6; ++f) {
        char face[4096];
        MS_TRY(face_path(path, f, face, sizeof face));
        MS_TRY(open_png(face, MAX_FACE, MAX_FACE, &img, &fp));
        int w = (int)img.width, h = (int)img.height;
        png_image_free(&img);
        fclose(fp);
        MS_TRY(check_face(face, f, w, h, size));
        MS_TRY(decode_rows(face));
        size = w;
    }
    return MS_OK;
}
