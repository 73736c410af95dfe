/* The window's pixels as a PNG file (F12, --record): RGBA8 top row first,
 * written through "path.tmp" and a rename so a reader never sees half a
 * file. libpng, as the library's own writer. */
#include <png.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "view.h"

int view_png_write(const char *path, const unsigned char *rgba, int w, int h)
{
    size_t n = strlen(path) + 5;
    char *tmp = malloc(n);
    if (!tmp)
        return -1;
    snprintf(tmp, n, "%s.tmp", path);
    FILE *f = fopen(tmp, "wb");
    if (!f) {
        free(tmp);
        return -1;
    }
    png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, NULL, NULL, NULL);
    png_infop info = png ? png_create_info_struct(png) : NULL;
    int ok = png && info;
    if (ok && setjmp(png_jmpbuf(png)) == 0) {
        png_init_io(png, f);
        png_set_compression_level(png, 3); /* a frame a step: speed over size */
        png_set_IHDR(png, info, (png_uint_32)w, (png_uint_32)h, 8, PNG_COLOR_TYPE_RGBA,
                     PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
        png_write_info(png, info);
        for (int y = 0; y < h; ++y)
            png_write_row(png, rgba + (size_t)y * (size_t)w * 4);
        png_write_end(png, NULL);
    } else {
        ok = 0;
    }
    png_destroy_write_struct(&png, &info);
    ok = (fclose(f) == 0) && ok;
    if (ok)
        ok = rename(tmp, path) == 0;
    else
        remove(tmp);
    free(tmp);
    return ok ? 0 : -1;
}
