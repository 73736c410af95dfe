/* ms_shape: create from a plugin, pose, signed distance and smoothed normal
 * (the n_object and d of the collider force, eq. 15), velocity. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "core/internal.h"
#include "shape/shape.h"

ms_status ms_shape_create(const char *kind, const char *params_json, ms_shape **out)
{
    ms_status st = ms_check_not_null("shape", "out", out);
    if (st != MS_OK)
        return st;
    *out = NULL;
    if ((st = ms_check_not_null("shape", "kind", kind)) != MS_OK)
        return st;
    const ms_plugin_rec *rec;
    if ((st = ms_plugin_find("shape", kind, MS_PLUGIN_SHAPE, &rec)) != MS_OK)
        return st;
    ms_shape *s = calloc(1, sizeof *s);
    if (!s)
        return ms_fail(MS_ERR_OUT_OF_MEMORY, "shape %s: out of memory", kind);
    s->plugin = rec;
    s->vt = &rec->vt.shape;
    char err[512] = "";
    int rc = s->vt->create(params_json, &s->self, err, sizeof err);
    if (rc != MS_PLUGIN_OK) {
        free(s);
        err[sizeof err - 1] = '\0';
        ms_status code = ms_plugin_status(rc);
        return ms_fail(code, "shape %s: %s", kind,
                       err[0] ? err : "the plugin refused the parameters without a reason");
    }
    *out = s;
    return MS_OK;
}

void ms_shape_destroy(ms_shape *s)
{
    if (!s)
        return;
    s->vt->destroy(s->self);
    free(s);
}

ms_status ms_shape_set_pose(ms_shape *s, const float pos[3], const float vel[3])
{
    ms_status st = ms_check_not_null("shape", "shape", s);
    if (st != MS_OK)
        return st;
    static const char *const pkey[3] = {"pos[0]", "pos[1]", "pos[2]"};
    static const char *const vkey[3] = {"vel[0]", "vel[1]", "vel[2]"};
    for (int k = 0; k < 3; ++k) {
        if (pos && (st = ms_check_range("shape", pkey[k], pos[k], -1e6, 1e6, "m")) != MS_OK)
            return st;
        if (vel && (st = ms_check_range("shape", vkey[k], vel[k], -1e4, 1e4, "m/s")) != MS_OK)
            return st;
    }
    for (int k = 0; k < 3; ++k) {
        if (pos)
            s->pos[k] = pos[k];
        s->vel[k] = vel ? vel[k] : 0.0f;
    }
    return MS_OK;
}

void ms_shape_get_pose(const ms_shape *s, float pos[3], float vel[3])
{
    for (int k = 0; k < 3; ++k) {
        if (pos)
            pos[k] = s->pos[k];
        if (vel)
            vel[k] = s->vel[k];
    }
}

float ms_shape_distance(const ms_shape *s, const float p[3], float normal[3])
{
    const float q[3] = {p[0] - s->pos[0], p[1] - s->pos[1], p[2] - s->pos[2]};
    return s->vt->distance(s->self, q, normal);
}

void ms_shape_velocity(const ms_shape *s, const float p[3], float vel[3])
{
    (void)p; /* translation only: every point moves with the origin */
    vel[0] = s->vel[0];
    vel[1] = s->vel[1];
    vel[2] = s->vel[2];
}

void ms_shape_bounds(const ms_shape *s, float lo[3], float hi[3])
{
    s->vt->bounds(s->self, lo, hi);
    for (int k = 0; k < 3; ++k) {
        if (fabsf(lo[k]) < 1e29f)
            lo[k] += s->pos[k];
        if (fabsf(hi[k]) < 1e29f)
            hi[k] += s->pos[k];
    }
}

const char *ms_shape_kind(const ms_shape *s)
{
    return s ? s->plugin->info.name : "";
}
