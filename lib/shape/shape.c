/* ms_shape: create from a plugin, pose (translation and rotation), signed
 * distance and smoothed normal (the n_object and d of the collider force,
 * eq. 15), velocity of the material (v + omega x r). The plugin works in
 * its own frame; this part maps points in (R^T (x - pos)) and normals out
 * (R n). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "core/core_internal.h"
#include "shape/shape_internal.h"

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
    ms_shape *s = ms_alloc_array(1, sizeof *s);
    if (!s)
        return ms_fail(MS_ERR_OUT_OF_MEMORY, "shape %s: out of memory", kind);
    s->plugin = rec;
    s->vt = &rec->vt.shape;
    s->quat[0] = 1.0f;
    s->rot[0] = s->rot[4] = s->rot[8] = 1.0f;
    char err[512] = "";
    int rc = s->vt->create(params_json, &s->self, err, sizeof err);
    if (rc != MS_PLUGIN_OK) {
        ms_free(s);
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
    ms_free(s);
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

/* Row-major R of the unit quaternion (w, x, y, z). */
static void quat_matrix(const float q[4], float R[9])
{
    const float w = q[0], x = q[1], y = q[2], z = q[3];
    R[0] = 1 - 2 * (y * y + z * z);
    R[1] = 2 * (x * y - w * z);
    R[2] = 2 * (x * z + w * y);
    R[3] = 2 * (x * y + w * z);
    R[4] = 1 - 2 * (x * x + z * z);
    R[5] = 2 * (y * z - w * x);
    R[6] = 2 * (x * z - w * y);
    R[7] = 2 * (y * z + w * x);
    R[8] = 1 - 2 * (x * x + y * y);
}

ms_status ms_shape_check_orientation(const char *part, const float quat[4], const float omega[3])
{
    static const char *const qkey[4] = {"orientation[0]", "orientation[1]", "orientation[2]",
                                        "orientation[3]"};
    static const char *const wkey[3] = {"omega[0]", "omega[1]", "omega[2]"};
    ms_status st;
    double n2 = 0.0;
    for (int k = 0; quat && k < 4; ++k) {
        if ((st = ms_check_finite(part, qkey[k], quat[k])) != MS_OK)
            return st;
        n2 += (double)quat[k] * quat[k];
    }
    if (quat && !(n2 > 1e-12))
        return ms_fail(MS_ERR_INVALID_ARGUMENT,
                       "%s: orientation quaternion has length %g; it must be a rotation "
                       "(w, x, y, z) of length 1 (it is normalised), not 0",
                       part, sqrt(n2));
    for (int k = 0; omega && k < 3; ++k)
        if ((st = ms_check_range(part, wkey[k], omega[k], -1e3, 1e3, "rad/s")) != MS_OK)
            return st;
    return MS_OK;
}

ms_status ms_shape_set_orientation(ms_shape *s, const float quat[4], const float omega[3])
{
    ms_status st = ms_check_not_null("shape", "shape", s);
    if (st == MS_OK)
        st = ms_shape_check_orientation("shape", quat, omega);
    if (st != MS_OK)
        return st;
    if (quat) {
        double n2 = 0.0;
        for (int k = 0; k < 4; ++k)
            n2 += (double)quat[k] * quat[k];
        const double inv = 1.0 / sqrt(n2);
        for (int k = 0; k < 4; ++k)
            s->quat[k] = (float)(quat[k] * inv);
        quat_matrix(s->quat, s->rot);
    }
    for (int k = 0; k < 3; ++k)
        s->omega[k] = omega ? omega[k] : 0.0f;
    s->turned =
        s->quat[0] != 1.0f || s->omega[0] != 0.0f || s->omega[1] != 0.0f || s->omega[2] != 0.0f;
    return MS_OK;
}

void ms_shape_get_orientation(const ms_shape *s, float quat[4], float omega[3])
{
    for (int k = 0; k < 4; ++k)
        if (quat)
            quat[k] = s->quat[k];
    for (int k = 0; k < 3; ++k)
        if (omega)
            omega[k] = s->omega[k];
}

void ms_shape_rotation_at(const ms_shape *s, float t, float R[9])
{
    const float w2 =
        s->omega[0] * s->omega[0] + s->omega[1] * s->omega[1] + s->omega[2] * s->omega[2];
    const float ang = sqrtf(w2) * t; /* rad */
    if (!(ang != 0.0f)) {
        for (int k = 0; k < 9; ++k)
            R[k] = s->rot[k];
        return;
    }
    /* Rodrigues: exp(ang [a]x) = I + sin(ang) [a]x + (1 - cos(ang)) [a]x^2 */
    const float inv = 1.0f / sqrtf(w2);
    const float a[3] = {s->omega[0] * inv, s->omega[1] * inv, s->omega[2] * inv};
    const float sn = sinf(ang), cs = 1.0f - cosf(ang);
    const float E[9] = {
        1 + cs * (a[0] * a[0] - 1),    -sn * a[2] + cs * a[0] * a[1], sn * a[1] + cs * a[0] * a[2],
        sn * a[2] + cs * a[0] * a[1],  1 + cs * (a[1] * a[1] - 1),    -sn * a[0] + cs * a[1] * a[2],
        -sn * a[1] + cs * a[0] * a[2], sn * a[0] + cs * a[1] * a[2],  1 + cs * (a[2] * a[2] - 1)};
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c)
            R[3 * r + c] =
                E[3 * r] * s->rot[c] + E[3 * r + 1] * s->rot[3 + c] + E[3 * r + 2] * s->rot[6 + c];
}

float ms_shape_distance_local(const ms_shape *s, const float q[3], float normal[3])
{
    return s->vt->distance(s->self, q, normal);
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
    if (!s->turned) {
        const float r[3] = {p[0] - s->pos[0], p[1] - s->pos[1], p[2] - s->pos[2]};
        return s->vt->distance(s->self, r, normal);
    }
    float q[3], n[3] = {0.0f, 0.0f, 1.0f};
    ms_rigid_to_local(s->rot, s->pos, p, q);
    float d = s->vt->distance(s->self, q, normal ? n : NULL);
    if (normal)
        ms_rigid_to_world(s->rot, n, normal);
    return d;
}

void ms_shape_velocity(const ms_shape *s, const float p[3], float vel[3])
{
    ms_rigid_velocity(s->vel, s->omega, s->pos, p, vel);
}

void ms_shape_bounds(const ms_shape *s, float lo[3], float hi[3])
{
    float l[3], h[3];
    s->vt->bounds(s->self, l, h);
    int open = 0;
    for (int k = 0; k < 3; ++k)
        open |= !(fabsf(l[k]) < 1e29f) || !(fabsf(h[k]) < 1e29f);
    if (!s->turned || s->quat[0] == 1.0f) {
        for (int k = 0; k < 3; ++k) {
            lo[k] = fabsf(l[k]) < 1e29f ? l[k] + s->pos[k] : l[k];
            hi[k] = fabsf(h[k]) < 1e29f ? h[k] + s->pos[k] : h[k];
        }
        return;
    }
    if (open) { /* a turned half-space or slab: unbounded on every axis */
        for (int k = 0; k < 3; ++k) {
            lo[k] = -1e30f;
            hi[k] = 1e30f;
        }
        return;
    }
    /* the box of the turned local box: |R| times the half extents */
    const float *R = s->rot;
    for (int k = 0; k < 3; ++k) {
        float c = s->pos[k], e = 0.0f;
        for (int m = 0; m < 3; ++m) {
            c += R[3 * k + m] * 0.5f * (l[m] + h[m]);
            e += fabsf(R[3 * k + m]) * 0.5f * (h[m] - l[m]);
        }
        lo[k] = c - e;
        hi[k] = c + e;
    }
}

void ms_shape_bounds_any_turn(const ms_shape *s, float lo[3], float hi[3])
{
    float l[3], h[3], r2 = 0.0f;
    s->vt->bounds(s->self, l, h);
    int open = 0;
    for (int k = 0; k < 3; ++k) {
        open |= !(fabsf(l[k]) < 1e29f) || !(fabsf(h[k]) < 1e29f);
        float m = fmaxf(fabsf(l[k]), fabsf(h[k]));
        r2 += m * m;
    }
    const float r = sqrtf(r2);
    for (int k = 0; k < 3; ++k) {
        lo[k] = open ? -1e30f : s->pos[k] - r;
        hi[k] = open ? 1e30f : s->pos[k] + r;
    }
}

const char *ms_shape_kind(const ms_shape *s)
{
    return s ? s->plugin->info.name : "";
}
