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
#include "plugin/registry.h"

struct ms_shape {
    const ms_plugin_rec *plugin;
    const ms_shape_vtable *vt;
    void *self;    /* the plugin's instance */
    float pos[3];  /* m, world position of the local origin */
    float vel[3];  /* m/s */
    float quat[4]; /* orientation, unit quaternion (w, x, y, z), local -> world */
    float rot[9];  /* the same as a row-major rotation matrix R */
    float omega[3]; /* rad/s, world axes, about pos */
    int turned;    /* R != I or omega != 0: the rotated paths are taken */
};

/* The rotation of the shape t seconds after its pose was set, turning at
 * omega: R(t) = exp(t [omega]x) R (Rodrigues). */
void ms_shape_rotation_at(const ms_shape *s, float t, float R[9]);
/* Signed distance and normal in the plugin's own frame. */
float ms_shape_distance_local(const ms_shape *s, const float q[3], float normal[3]);
/* World bounds that hold the shape in any orientation about pos: a cube of
 * half-side the distance of the farthest local bound corner (unbounded
 * stays unbounded). */
void ms_shape_bounds_any_turn(const ms_shape *s, float lo[3], float hi[3]);

#endif /* MS_SHAPE_INTERNAL_H */
