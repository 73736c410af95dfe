/* The viewer's camera: it orbits a target point (right-drag), comes closer
 * or backs off (wheel) and slides with the pointer (middle-drag); the
 * pointer's ray meets the water plane for dragging (left-drag). z is up. */
#include <math.h>

#include "view.h"

#define PI 3.14159265358979f

void view_camera_from(view_camera *c, const float eye[3], const float target[3], float fov)
{
    float d[3] = {eye[0] - target[0], eye[1] - target[1], eye[2] - target[2]};
    for (int k = 0; k < 3; ++k)
        c->target[k] = target[k];
    c->dist = sqrtf(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    c->yaw = atan2f(d[1], d[0]);
    c->pitch = asinf(d[2] / c->dist);
    c->fov = fov;
    c->min_dist = 0.05f * c->dist;
    c->max_dist = 20.0f * c->dist;
}

void view_camera_eye(const view_camera *c, float eye[3])
{
    eye[0] = c->target[0] + c->dist * cosf(c->pitch) * cosf(c->yaw);
    eye[1] = c->target[1] + c->dist * cosf(c->pitch) * sinf(c->yaw);
    eye[2] = c->target[2] + c->dist * sinf(c->pitch);
}

void view_camera_orbit(view_camera *c, float dx, float dy)
{
    c->yaw -= dx * PI;
    c->pitch += dy * 0.5f * PI;
    /* from just above the horizon to just short of straight down (the
     * look-at needs an up that is not the view direction) */
    c->pitch = fminf(fmaxf(c->pitch, 2.0f * PI / 180.0f), 88.0f * PI / 180.0f);
}

void view_camera_zoom(view_camera *c, float notches)
{
    c->dist *= powf(0.9f, notches);
    c->dist = fminf(fmaxf(c->dist, c->min_dist), c->max_dist);
}

/* The camera's unit right, up and forward vectors. */
static void basis(const view_camera *c, float right[3], float up[3], float fwd[3])
{
    float eye[3];
    view_camera_eye(c, eye);
    for (int k = 0; k < 3; ++k)
        fwd[k] = (c->target[k] - eye[k]) / c->dist;
    /* right = fwd x z */
    right[0] = fwd[1], right[1] = -fwd[0], right[2] = 0;
    float l = sqrtf(right[0] * right[0] + right[1] * right[1]);
    right[0] /= l, right[1] /= l;
    /* up = right x fwd */
    up[0] = right[1] * fwd[2] - right[2] * fwd[1];
    up[1] = right[2] * fwd[0] - right[0] * fwd[2];
    up[2] = right[0] * fwd[1] - right[1] * fwd[0];
}

void view_camera_pan(view_camera *c, float dx, float dy, float aspect)
{
    float right[3], up[3], fwd[3];
    basis(c, right, up, fwd);
    /* the view's height at the target's distance: a drag across the
     * window moves the target across the view */
    float hgt = 2.0f * c->dist * tanf(0.5f * c->fov * PI / 180.0f);
    for (int k = 0; k < 3; ++k)
        c->target[k] += -dx * hgt * aspect * right[k] + dy * hgt * up[k];
}

int view_camera_unproject(const view_camera *c, float aspect, float fx, float fy, float plane_z,
                          float out[2])
{
    float right[3], up[3], fwd[3], eye[3];
    basis(c, right, up, fwd);
    view_camera_eye(c, eye);
    float ty = tanf(0.5f * c->fov * PI / 180.0f), tx = ty * aspect;
    float sx = (2.0f * fx - 1.0f) * tx, sy = (1.0f - 2.0f * fy) * ty, dir[3];
    for (int k = 0; k < 3; ++k)
        dir[k] = fwd[k] + sx * right[k] + sy * up[k];
    if (fabsf(dir[2]) < 1e-6f)
        return 0;
    float t = (plane_z - eye[2]) / dir[2];
    if (t <= 0)
        return 0;
    out[0] = eye[0] + t * dir[0];
    out[1] = eye[1] + t * dir[1];
    return 1;
}
