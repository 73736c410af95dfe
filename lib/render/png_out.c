/* The rendered image as a PNG (libpng's simplified API): RGBA8, sRGB,
 * written to "<path>.tmp" and renamed, so no half-written image is ever
 * seen under the final name. */
#include <errno.h>
#include <png.h>
#include <stdio.h>
#include <string.h>

#include "core/core_internal.h"
#include "render/render_internal.h"

#define MS_IMAGE_MAX_SIDE 16384 /* pixels, ms_image_write_png */

ms_status ms_png_write_rgba(const char *path, const unsigned char *rgba, int w, int h)
{
    size_t n = strlen(path) + 5;
    char *tmp = ms_alloc(n);
    if (!tmp)
        return ms_fail(MS_ERR_OUT_OF_MEMORY, "render: out of memory for a file name");
    snprintf(tmp, n, "%s.tmp", path);
    png_image img;
    memset(&img, 0, sizeof img);
    img.version = PNG_IMAGE_VERSION;
    img.width = (png_uint_32)w;
    img.height = (png_uint_32)h;
    img.format = PNG_FORMAT_RGBA;
    img.flags = PNG_IMAGE_FLAG_FAST; /* favour speed over size */
    ms_status st = MS_OK;
    errno = 0;
    if (!png_image_write_to_file(&img, tmp, 0, rgba, (png_int_32)(4 * w), NULL)) {
        int err = errno;
        st = ms_fail(MS_ERR_IO, "render: cannot write \"%s\": %s%s%s", path, img.message,
                     err ? ": " : "", err ? strerror(err) : "");
        remove(tmp);
    } else if (rename(tmp, path) != 0) {
        st = ms_fail(MS_ERR_IO, "render: cannot rename \"%s\" to \"%s\": %s", tmp, path,
                     strerror(errno));
        remove(tmp);
    }
    png_image_free(&img);
    ms_free(tmp);
    return st;
}

ms_status ms_image_write_png(const char *path, const unsigned char *rgba, int w, int h)
{
    if (!path || !*path)
        return ms_fail(MS_ERR_INVALID_ARGUMENT, "image: the PNG path is NULL or empty");
    if (!rgba)
        return ms_fail(MS_ERR_INVALID_ARGUMENT, "image: the pixels of \"%s\" are NULL", path);
    if (w < 1 || w > MS_IMAGE_MAX_SIDE || h < 1 || h > MS_IMAGE_MAX_SIDE)
        return ms_fail(MS_ERR_INVALID_ARGUMENT,
                       "image: %d x %d pixels for \"%s\": each side must be in [1, %d]", w, h, path,
                       MS_IMAGE_MAX_SIDE);
    return ms_png_write_rgba(path, rgba, w, h);
}
