/* lib/shape: collision shapes (internal view).
 *
 * Owns the ms_shape handle: a shape plugin's instance (lib/plugin finds the
 * plugin by name) placed in the world by a pose (a translation, m, and a
 * rotation) moving at a velocity (m/s) and turning at an angular velocity
 * (rad/s). A world point x is at R^T (x - pos) in the plugin's frame. shape.c: create, pose, signed distance and smoothed
 * normal for the collider force of eq. 15 (the plugin works in the local
 * frame, this part translates). raster.c: the footprint of a shape on a
 * surface grid at the water level (the obstacle mask that makes waves
 * reflect, eq. 2) and the water depth above it (terrain: the wave speed
 * map, c = sqrt(g depth)).
 */
#ifndef MS_SHAPE_INTERNAL_H
#define MS_SHAPE_INTERNAL_H

#include "modesplit/plugin.h"
#include "modesplit/shape.h"
#include "plugin/plugin_internal.h"

struct ms_shape {
    const ms_plugin_rec *plugin;
    const ms_shape_vtable *vt;
    void *self;     /* the plugin's instance */
    float pos[3];   /* m, world position of the local origin */
    float vel[3];   /* m/s */
    float quat[4];  /* orientation, unit quaternion (w, x, y, z), local -> world */
    float rot[9];   /* the same as a row-major rotation matrix R */
    float omega[3]; /* rad/s, world axes, about pos */
    int turned;     /* R != I or omega != 0: the rotated paths are taken */
};

/* Rigid motion, shared by the shape's own queries and the volume's
 * colliders (which place a shape at the times of a sub-step). R is
 * row-major, from the shape's frame to the world's. */
/* q = R^T (x - o): world point x into the frame at origin o. */
static inline void ms_rigid_to_local(const float R[9], const float o[3], const float x[3],
                                     float q[3])
{
    const float r[3] = {x[0] - o[0], x[1] - o[1], x[2] - o[2]};
    for (int k = 0; k < 3; ++k)
        q[k] = R[k] * r[0] + R[3 + k] * r[1] + R[6 + k] * r[2];
}

/* w = R n: a direction (or a point about the origin) into the world. */
static inline void ms_rigid_to_world(const float R[9], const float n[3], float w[3])
{
    for (int k = 0; k < 3; ++k)
        w[k] = R[3 * k] * n[0] + R[3 * k + 1] * n[1] + R[3 * k + 2] * n[2];
}

/* u = v + omega x (x - o): the velocity of the body's material at x. */
static inline void ms_rigid_velocity(const float v[3], const float omega[3], const float o[3],
                                     const float x[3], float u[3])
{
    const float r[3] = {x[0] - o[0], x[1] - o[1], x[2] - o[2]};
    u[0] = v[0] + omega[1] * r[2] - omega[2] * r[1];
    u[1] = v[1] + omega[2] * r[0] - omega[0] * r[2];
    u[2] = v[2] + omega[0] * r[1] - omega[1] * r[0];
}

/* The rotation of the shape t seconds after its pose was set, turning at
 * omega: R(t) = exp(t [omega]x) R (Rodrigues). */
void ms_shape_rotation_at(const ms_shape *s, float t, float R[9]);
/* The refusals of ms_shape_set_orientation, with part naming the caller:
 * a non-finite or zero quaternion (NULL: none given), |omega_k| > 1000. */
ms_status ms_shape_check_orientation(const char *part, const float quat[4], const float omega[3]);
/* Signed distance and normal in the plugin's own frame. */
float ms_shape_distance_local(const ms_shape *s, const float q[3], float normal[3]);
/* World bounds that hold the shape in any orientation about pos: a cube of
 * half-side the distance of the farthest local bound corner (unbounded
 * stays unbounded). */
void ms_shape_bounds_any_turn(const ms_shape *s, float lo[3], float hi[3]);

#endif /* MS_SHAPE_INTERNAL_H */
