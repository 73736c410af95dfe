/* ms_shape: a collision object (plane, box, sphere, capsule, glass, terrain,
 * ...) provided by a shape plugin (see plugin.h). It gives the signed
 * distance and the smoothed normal used by the collider force field of the
 * paper's eq. 15, a pose and a velocity (moving obstacles).
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

#ifdef __cplusplus
}
#endif

#endif /* MODESPLIT_SHAPE_H */
