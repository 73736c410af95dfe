/* `modesplit run --png DIR`: one PNG per written frame, DIR/frame_NNNNN.png
 * (NNNNN = the frame's index in the HDF5 file). A scene with a `render`
 * section is drawn by the renderer (ms_renderer_draw_field of the combined
 * field: cubemap, Fresnel, caustics, the scene's shader), whose pixels a
 * writer thread encodes (png_queue.c) while the next frame is simulated
 * and drawn; otherwise, with --preview, or in a build without OSMesa, each
 * frame is the shaded-relief preview of the combined height field
 * (ms_field_write_png).
 *
 * The colour range is taken from the first frame (its span, padded by
 * half of it each side, at least +-2 mm) and only ever widened, and the
 * shading's vertical exaggeration starts at MAX_RELIEF and is only ever
 * lowered (to keep three times the mean slope under 45 degrees), so a
 * sequence stays comparable frame to frame while millimetre ripples on a
 * calm pool still show. */
#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "tool.h"

#define MIN_PAD 0.002f /* m */
#define TARGET_PIXELS 512
#define MAX_RELIEF 20.0f

/* Mean |grad h| over the grid (forward differences), for the relief. */
static double mean_slope(const float *h, const ms_grid *g)
{
    double sum = 0;
    long n = 0;
    for (int y = 0; y + 1 < g->ny; ++y)
        for (int x = 0; x + 1 < g->nx; ++x) {
            const float *c = h + (size_t)y * (size_t)g->nx + (size_t)x;
            double sx = ((double)c[1] - c[0]) / g->dx, sy = ((double)c[g->nx] - c[0]) / g->dy;
            double s = sqrt(sx * sx + sy * sy);
            if (isfinite(s)) {
                sum += s;
                ++n;
            }
        }
    return n ? sum / (double)n : 0.0;
}

static int make_dirs(const char *dir)
{
    char *p = strdup(dir);
    if (!p)
        return ENOMEM;
    int err = 0;
    for (char *s = p + 1;; ++s) {
        if (*s == '/' || *s == '\0') {
            char c = *s;
            *s = '\0';
            if (mkdir(p, 0777) != 0 && errno != EEXIST) {
                err = errno;
                break;
            }
            *s = c;
            if (!c)
                break;
        }
    }
    struct stat sb;
    if (!err && (stat(dir, &sb) != 0 || !S_ISDIR(sb.st_mode)))
        err = ENOTDIR;
    free(p);
    return err;
}

int png_begin(tool_png *p, const char *dir, const ms_scene *sc, int preview, int quiet)
{
    memset(p, 0, sizeof *p);
    int err = make_dirs(dir);
    if (err) {
        tool_error("cannot create the PNG directory %s: %s", dir, strerror(err));
        return -1;
    }
    p->dir = strdup(dir);
    if (!p->dir)
        return -1;
    if (!preview && ms_scene_has_render(sc)) {
        ms_status st = ms_renderer_create_from_scene(sc, &p->renderer);
        if (st == MS_ERR_UNSUPPORTED) {
            if (!quiet)
                tool_error("note: %s; the PNG frames are shaded-relief previews", ms_last_error());
            p->renderer = NULL;
        } else if (st != MS_OK) {
            tool_error("%s", ms_last_error());
            png_end(p);
            return -1;
        }
        if (p->renderer && png_queue_start(&p->queue) != 0) {
            png_end(p);
            return -1;
        }
    }
    return 0;
}

int png_frame(tool_png *p, long index, const float *h, const ms_grid *g, double t)
{
    size_t plen = strlen(p->dir) + 32;
    char *ppath = malloc(plen);
    if (!ppath)
        return -1;
    snprintf(ppath, plen, "%s/frame_%05ld.png", p->dir, index);
    if (p->renderer) {
        /* with the sim: its floaters (leaves) and the scene's boat too */
        ms_status st = p->sim ? ms_renderer_draw(p->renderer, p->sim)
                              : ms_renderer_draw_field(p->renderer, h, g, t);
        if (st != MS_OK) {
            free(ppath);
            tool_error("%s", ms_last_error());
            return -1;
        }
        /* encoded by the writer thread while the next frame is simulated
         * and drawn */
        int w = 0, hh = 0;
        const unsigned char *px = ms_renderer_pixels(p->renderer, &w, &hh);
        int rc = png_queue_push(p->queue, ppath, px, w, hh);
        free(ppath);
        if (rc != 0)
            return -1;
        ++p->written;
        return 0;
    }
    free(ppath);
    size_t n = (size_t)g->nx * (size_t)g->ny;
    float lo = INFINITY, hi = -INFINITY;
    for (size_t i = 0; i < n; ++i)
        if (isfinite(h[i])) {
            lo = h[i] < lo ? h[i] : lo;
            hi = h[i] > hi ? h[i] : hi;
        }
    if (lo <= hi) {
        if (!p->have_range) {
            float pad = 0.5f * (hi - lo);
            pad = pad > MIN_PAD ? pad : MIN_PAD;
            p->lo = lo - pad;
            p->hi = hi + pad;
            p->have_range = 1;
        } else {
            p->lo = lo < p->lo ? lo : p->lo;
            p->hi = hi > p->hi ? hi : p->hi;
        }
    }
    if (p->relief <= 0)
        p->relief = MAX_RELIEF;
    double slope = mean_slope(h, g);
    if (slope > 0 && 3.0 * slope * p->relief > 1.0)
        p->relief = (float)(1.0 / (3.0 * slope)) > 1.0f ? (float)(1.0 / (3.0 * slope)) : 1.0f;
    ms_preview_desc d = ms_preview_desc_default();
    d.relief = p->relief;
    d.dx = g->dx;
    d.dy = g->dy;
    d.height_min = p->have_range ? p->lo : 0.0f;
    d.height_max = p->have_range ? p->hi : 0.0f;
    int side = g->nx > g->ny ? g->nx : g->ny;
    d.scale = side >= TARGET_PIXELS ? 1 : TARGET_PIXELS / side;
    d.scale = d.scale > 16 ? 16 : d.scale;
    size_t len = strlen(p->dir) + 32;
    char *path = malloc(len);
    if (!path)
        return -1;
    snprintf(path, len, "%s/frame_%05ld.png", p->dir, index);
    ms_status st = ms_field_write_png(h, g->nx, g->ny, path, &d);
    free(path);
    if (st != MS_OK) {
        tool_error("%s", ms_last_error());
        return -1;
    }
    ++p->written;
    return 0;
}

int png_finish(tool_png *p)
{
    int rc = png_queue_finish(p->queue);
    p->queue = NULL;
    return rc;
}

void png_end(tool_png *p)
{
    png_finish(p);
    ms_renderer_destroy(p->renderer);
    p->renderer = NULL;
    free(p->dir);
    p->dir = NULL;
}
