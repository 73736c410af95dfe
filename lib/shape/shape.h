/* lib/shape: collision shapes (internal view).
 *
 * Owns the ms_shape handle: a shape plugin's instance (lib/plugin finds the
 * plugin by name) placed in the world by a pose (translation, m) moving at
 * a velocity (m/s). shape.c: create, pose, signed distance and smoothed
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
};

#endif /* MS_SHAPE_INTERNAL_H */
