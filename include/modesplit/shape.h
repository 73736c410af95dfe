/* ms_shape: a collision object (plane, box, sphere, capsule, glass, terrain,
 * ...) provided by a shape plugin (see plugin.h). It gives the signed
 * distance and the smoothed normal used by the collider force field of the
 * paper's eq. 15, a pose (position and orientation) and a velocity and
 * angular velocity (moving and turning obstacles).
 */
#ifndef MODESPLIT_SHAPE_H
#define MODESPLIT_SHAPE_H

#include "core.h"

#ifdef __cplusplus
extern "C" {
#endif

/* kind: a shape plugin's name ("sphere", "box", ...); params_json: its
 * parameters as a JSON object text (NULL = the plugin's defaults). */
MS_API ms_status ms_shape_create(const char *kind, const char *params_json, ms_shape **out);
MS_API void ms_shape_destroy(ms_shape *s);
/* Position (m) of the shape's origin and its velocity (m/s). */
MS_API ms_status ms_shape_set_pose(ms_shape *s, const float pos[3], const float vel[3]);
/* Signed distance (m, negative inside) from p (m, world) to the surface,
 * and the outward smoothed unit normal there (normal may be NULL). */
MS_API float ms_shape_distance(const ms_shape *s, const float p[3], float normal[3]);

/* Velocity (m/s) of the shape's material at world point p (moving obstacles
 * push the liquid with it). */
MS_API void ms_shape_velocity(const ms_shape *s, const float p[3], float vel[3]);
/* Current position (m) and velocity (m/s) of the shape's origin. */
MS_API void ms_shape_get_pose(const ms_shape *s, float pos[3], float vel[3]);
/* Orientation of the shape about its origin: a rotation quaternion
 * (w, x, y, z) from its own frame to the world's (normalised here; NULL
 * keeps the current one; the default is (1, 0, 0, 0)), and the angular
 * velocity omega (rad/s, world axes, |omega_k| <= 1000; NULL = 0) at which
 * it turns, so that its material moves at vel + omega x (p - pos) (a glass
 * tilted to pour, a paddle). Refused: a zero or non-finite quaternion. */
MS_API ms_status ms_shape_set_orientation(ms_shape *s, const float orientation[4],
                                          const float omega[3]);
MS_API void ms_shape_get_orientation(const ms_shape *s, float orientation[4], float omega[3]);
/* World-space bounding box (m). */
MS_API void ms_shape_bounds(const ms_shape *s, float lo[3], float hi[3]);
/* Rasterise the shape's footprint at water level z (m) onto grid g: mask
 * cells whose centre lies inside the shape are set to 1, others are left
 * as they are (so several shapes OR into one obstacle mask). */
MS_API ms_status ms_shape_footprint(const ms_shape *s, const ms_grid *g, float z,
                                    unsigned char *mask);
/* Water depth (m) over the shape at each cell centre of g for a water
 * level z: z minus the height of the shape's top there, clamped at 0, and
 * min()-ed into depth (initialise depth with the depth without the shape).
 * Terrain uses it to set the wave speed map (c = sqrt(g depth)). */
MS_API ms_status ms_shape_depth(const ms_shape *s, const ms_grid *g, float z, float *depth);
/* The shape's kind name ("sphere"). */
MS_API const char *ms_shape_kind(const ms_shape *s);

#ifdef __cplusplus
}
#endif

#endif /* MODESPLIT_SHAPE_H */
