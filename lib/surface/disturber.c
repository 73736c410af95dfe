/* Moving disturbers: the paper's swimming object and boat (Fig. 3c, 10b):
 * "displacing several f(x_i, t0) can create e.g. wave trains or the
 * typical wave propagation of a moving boat".
 *
 * A disturber is a pressure head P(x) = depth * b(|x - x_b| / R) (b a
 * raised cosine) entering the wave equation as d2f/dt2 = div(c^2 grad(f +
 * P)): at rest the surface settles into the dent f = -P, and moving it
 * leaves bow waves and a wake. Being a flux, the term adds no water: the
 * mean height stays exactly where it was. */
#include <stdlib.h>
#include <string.h>

#include "surface/surface_internal.h"
#include "surface/surface_sizes.h"

#define PART "surface"

static disturber *find(const ms_surface *s, int id)
{
    for (int i = 0; i < s->ndist; ++i)
        if (s->dist[i].id == id)
            return &s->dist[i];
    return NULL;
}

ms_disturber_desc ms_disturber_desc_default(void)
{
    ms_disturber_desc d;
    memset(&d, 0, sizeof d);
    d.size = (uint32_t)sizeof d;
    d.radius = 0.05f; /* m */
    d.depth = 0.01f;  /* m */
    return d;
}

ms_status ms_surface_check_disturber(const ms_surface *s, const ms_disturber_desc *d)
{
    ms_status st;
    if ((st = ms_check_finite(PART, "disturber x", d->x)) ||
        (st = ms_check_finite(PART, "disturber y", d->y)) ||
        (st = ms_check_finite(PART, "disturber vx", d->vx)) ||
        (st = ms_check_finite(PART, "disturber vy", d->vy)) ||
        (st = ms_check_finite(PART, "disturber depth", d->depth)))
        return st;
    const float extent = (float)MS_MAX(s->nx, s->ny) * s->desc.dx;
    if (!isfinite(d->radius) || d->radius < s->desc.dx || d->radius > extent)
        return ms_fail(MS_ERR_INVALID_ARGUMENT,
                       "surface: disturber radius %g m is outside [%g, %g] m (one cell to the "
                       "grid's extent)",
                       (double)d->radius, (double)s->desc.dx, (double)extent);
    return MS_OK;
}

ms_status ms_surface_reserve_disturbers(ms_surface *s, int cap)
{
    if (cap <= s->cap_dist)
        return MS_OK;
    disturber *nd = ms_realloc(s->dist, (size_t)cap * sizeof *nd);
    if (!nd)
        return ms_fail(MS_ERR_OUT_OF_MEMORY, "surface: out of memory for a disturber");
    s->dist = nd;
    s->cap_dist = cap;
    float *t = ms_malloc((size_t)MS_SURFACE_MAX_LEVELS * 2 * (size_t)cap * sizeof *t);
    if (!t)
        return ms_fail(MS_ERR_OUT_OF_MEMORY, "surface: out of memory for a disturber");
    ms_free(s->level_xy);
    s->level_xy = t;
    s->level_cap = cap;
    return MS_OK;
}

ms_status ms_surface_add_disturber(ms_surface *s, const ms_disturber_desc *user, int *id)
{
    ms_status st;
    ms_disturber_desc desc = ms_disturber_desc_default(), *d = &desc;
    if ((st = ms_check_not_null(PART, "surface", s)) ||
        (st = ms_struct_in(user, &desc, MS_SIZES_DISTURBER_DESC, PART)) ||
        (st = ms_surface_check_disturber(s, d)))
        return st;
    if (s->ndist == s->cap_dist &&
        (st = ms_surface_reserve_disturbers(s, s->cap_dist ? 2 * s->cap_dist : 4)))
        return st;
    disturber *b = &s->dist[s->ndist++];
    memset(b, 0, sizeof *b);
    b->id = s->next_id++;
    b->d = *d;
    if (id)
        *id = b->id;
    return MS_OK;
}

static ms_status lookup(const ms_surface *s, int id, disturber **out)
{
    ms_status st;
    if ((st = ms_check_not_null(PART, "surface", s)))
        return st;
    *out = find(s, id);
    if (!*out)
        return ms_fail(MS_ERR_INVALID_ARGUMENT, "surface: no disturber with id %d", id);
    return MS_OK;
}

ms_status ms_surface_move_disturber(ms_surface *s, int id, float x, float y, float vx, float vy)
{
    disturber *b;
    ms_status st = lookup(s, id, &b);
    if (st)
        return st;
    ms_disturber_desc d = b->d;
    d.x = x;
    d.y = y;
    d.vx = vx;
    d.vy = vy;
    if ((st = ms_surface_check_disturber(s, &d)))
        return st;
    b->d = d;
    ms_free(b->path);
    b->path = NULL;
    b->npath = b->path_cap = 0;
    return MS_OK;
}

/* Place b at arc length s along its path, with the path's velocity. */
static void place_on_path(disturber *b)
{
    const int n = b->npath, segs = b->loop ? n : n - 1;
    double s = b->path_s;
    for (int k = 0; k < segs; ++k) {
        const float *p0 = b->path + 2 * k, *p1 = b->path + 2 * ((k + 1) % n);
        double ex = p1[0] - p0[0], ey = p1[1] - p0[1], len = sqrt(ex * ex + ey * ey);
        if (s <= len || k == segs - 1) {
            double t = len > 0 ? MS_MIN(s / len, 1.0) : 1.0;
            b->d.x = (float)(p0[0] + t * ex);
            b->d.y = (float)(p0[1] + t * ey);
            int moving = len > 0 && (b->loop || s < len);
            b->d.vx = moving ? (float)(b->path_speed * ex / len) : 0.0f;
            b->d.vy = moving ? (float)(b->path_speed * ey / len) : 0.0f;
            return;
        }
        s -= len;
    }
}

static double path_length(const disturber *b)
{
    double total = 0;
    const int segs = b->loop ? b->npath : b->npath - 1;
    for (int k = 0; k < segs; ++k) {
        const float *p0 = b->path + 2 * k, *p1 = b->path + 2 * ((k + 1) % b->npath);
        total += hypot(p1[0] - p0[0], p1[1] - p0[1]);
    }
    return total;
}

ms_status ms_surface_set_disturber_path(ms_surface *s, int id, int npoints, const float *xy,
                                        float speed, int loop)
{
    disturber *b;
    ms_status st = lookup(s, id, &b);
    if (st || (st = ms_check_not_null(PART, "path", xy)) ||
        (st = ms_check_int_range(PART, "path npoints", npoints, 1, 1 << 20)) ||
        (st = ms_check_range(PART, "path speed", speed, 0, 1e4, "m/s")))
        return st;
    for (int k = 0; k < 2 * npoints; ++k)
        if (!isfinite(xy[k]))
            return ms_fail(MS_ERR_INVALID_ARGUMENT,
                           "surface: path point %d has a non-finite coordinate %g", k / 2,
                           (double)xy[k]);
    if (npoints > b->path_cap) { /* a path as long as the last reuses its block */
        float *copy = ms_malloc((size_t)npoints * 2 * sizeof *copy);
        if (!copy)
            return ms_fail(MS_ERR_OUT_OF_MEMORY, "surface: out of memory for a path");
        ms_free(b->path);
        b->path = copy;
        b->path_cap = npoints;
    }
    memmove(b->path, xy, (size_t)npoints * 2 * sizeof *b->path);
    b->npath = npoints;
    b->loop = loop != 0;
    b->path_speed = speed;
    b->path_s = 0;
    place_on_path(b);
    return MS_OK;
}

ms_status ms_surface_disturber_position(const ms_surface *s, int id, float *x, float *y)
{
    disturber *b;
    ms_status st = lookup(s, id, &b);
    if (st)
        return st;
    if (x)
        *x = b->d.x;
    if (y)
        *y = b->d.y;
    return MS_OK;
}

ms_status ms_surface_remove_disturber(ms_surface *s, int id)
{
    disturber *b;
    ms_status st = lookup(s, id, &b);
    if (st)
        return st;
    ms_free(b->path);
    *b = s->dist[--s->ndist];
    return MS_OK;
}

void ms_surface_disturbers_advance(ms_surface *s, float dt)
{
    for (int i = 0; i < s->ndist; ++i) {
        disturber *b = &s->dist[i];
        if (b->path) {
            double len = path_length(b);
            b->path_s += (double)b->path_speed * dt;
            if (b->loop && len > 0)
                b->path_s = fmod(b->path_s, len);
            else if (b->path_s > len)
                b->path_s = len;
            place_on_path(b);
        } else {
            b->d.x += b->d.vx * dt;
            b->d.y += b->d.vy * dt;
        }
    }
}

void ms_surface_disturbers_positions(const ms_surface *s, float *xy)
{
    for (int k = 0; k < s->ndist; ++k) {
        xy[2 * k] = s->dist[k].d.x;
        xy[2 * k + 1] = s->dist[k].d.y;
    }
}

/* Pressure head of b, centred at (bx, by), at world point (x, y), m. */
static float head(const disturber *b, float bx, float by, float x, float y)
{
    float rx = x - bx, ry = y - by;
    float r = sqrtf(rx * rx + ry * ry) / b->d.radius;
    return r < 1.0f ? b->d.depth * 0.5f * (1.0f + cosf(3.14159265358979f * r)) : 0.0f;
}

/* Add the flux of P to the velocity update of interior row y:
 * v_i += a_i sum_j a_j (P_j - P_i), over the cells the heads touch and
 * their neighbours, with the heads at xy (2 floats per disturber: where
 * they are at this sub-step). */
void ms_surface_disturbers_force_row(const ms_surface *s, int y, float *v_row, const float *xy)
{
    const float dx = s->desc.dx;
    const ptrdiff_t W = s->stride;
    const float cy = ((float)y + 0.5f) * dx;
    const float *a = s->a + ms_surface_row(s, y + 1), *dl = s->delta + ms_surface_row(s, y + 1);
    for (int k = 0; k < s->ndist; ++k) {
        const disturber *b = &s->dist[k];
        const float bx = xy[2 * k], by = xy[2 * k + 1];
        const float reach = b->d.radius + dx;
        if (b->d.depth == 0 || fabsf(cy - by) > reach + dx)
            continue;
        int x0 = MS_MAX((int)floorf((bx - reach) / dx) - 1, 0);
        int x1 = MS_MIN((int)ceilf((bx + reach) / dx) + 1, s->nx - 1);
        /* every cell centre is computed the same way wherever it is used,
         * so P_j - P_i = -(P_i - P_j) exactly and the term adds no water */
        const float cyn = ((float)(y + 1) + 0.5f) * dx, cys = ((float)(y - 1) + 0.5f) * dx;
        for (int x = x0; x <= x1; ++x) {
            const float cx = ((float)x + 0.5f) * dx;
            const float cxe = ((float)(x + 1) + 0.5f) * dx, cxw = ((float)(x - 1) + 0.5f) * dx;
            const int i = x + 1;
            const float pc = head(b, bx, by, cx, cy);
            const float flux = a[i + 1] * (head(b, bx, by, cxe, cy) - pc) +
                               a[i - 1] * (head(b, bx, by, cxw, cy) - pc) +
                               a[i + W] * (head(b, bx, by, cx, cyn) - pc) +
                               a[i - W] * (head(b, bx, by, cx, cys) - pc);
            v_row[i] += (0.5f + 0.5f * dl[i]) * a[i] * flux;
        }
    }
}

/* The heads of all disturbers at xy added to field (nx * ny values, row
 * major, no ghosts): the dispersive model applies its operator to f + P
 * (dispersive.c). Solid cells get none: the model keeps them at 0. */
void ms_surface_disturbers_head_field(const ms_surface *s, const float *xy, float *field)
{
    const float dx = s->desc.dx;
    for (int k = 0; k < s->ndist; ++k) {
        const disturber *b = &s->dist[k];
        const float bx = xy[2 * k], by = xy[2 * k + 1];
        const float reach = b->d.radius + dx;
        if (b->d.depth == 0)
            continue;
        const int x0 = MS_MAX((int)floorf((bx - reach) / dx), 0);
        const int x1 = MS_MIN((int)ceilf((bx + reach) / dx), s->nx - 1);
        const int y0 = MS_MAX((int)floorf((by - reach) / dx), 0);
        const int y1 = MS_MIN((int)ceilf((by + reach) / dx), s->ny - 1);
        for (int y = y0; y <= y1; ++y) {
            const float cy = ((float)y + 0.5f) * dx;
            for (int x = x0; x <= x1; ++x) {
                if (s->solid && s->solid[ms_surface_at(s, x, y)])
                    continue;
                field[(size_t)y * s->nx + x] += head(b, bx, by, ((float)x + 0.5f) * dx, cy);
            }
        }
    }
}
