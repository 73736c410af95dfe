/* Scripted motion along a polyline at constant speed: the boat (Fig. 10b),
 * the dragging pointer (Fig. 1), moving obstacles and the moved glass. */
#include <string.h>

#include "core/core_internal.h"
#include "scene/scene_internal.h"

void ms_scene_motion_eval(const ms_scene_motion *p, double t, float *pos, float *vel)
{
    int dim = p->dim, n = p->npoints;
    for (int k = 0; k < dim; ++k)
        vel[k] = 0;
    if (n <= 0)
        return;
    memcpy(pos, p->points, sizeof *pos * (size_t)dim);
    if (n == 1 || t <= p->start)
        return;
    /* arc length of the polyline (closed when it loops) */
    int nseg = p->loop ? n : n - 1;
    double total = 0;
    for (int s = 0; s < nseg; ++s) {
        const float *a = p->points + s * dim, *b = p->points + ((s + 1) % n) * dim;
        double d2 = 0;
        for (int k = 0; k < dim; ++k)
            d2 += (double)(b[k] - a[k]) * (b[k] - a[k]);
        total += sqrt(d2);
    }
    if (!(total > 0))
        return;
    double s_along = (t - p->start) * p->speed;
    if (p->loop)
        s_along = fmod(s_along, total);
    else if (s_along >= total) {
        memcpy(pos, p->points + (n - 1) * dim, sizeof *pos * (size_t)dim);
        return;
    }
    for (int s = 0; s < nseg; ++s) {
        const float *a = p->points + s * dim, *b = p->points + ((s + 1) % n) * dim;
        double d2 = 0;
        for (int k = 0; k < dim; ++k)
            d2 += (double)(b[k] - a[k]) * (b[k] - a[k]);
        double len = sqrt(d2);
        if (s_along <= len || s == nseg - 1) {
            double f = len > 0 ? MS_MIN(s_along / len, 1.0) : 0;
            for (int k = 0; k < dim; ++k) {
                pos[k] = (float)(a[k] + f * (b[k] - a[k]));
                vel[k] = len > 0 ? (float)((b[k] - a[k]) / len * p->speed) : 0;
            }
            return;
        }
        s_along -= len;
    }
}
