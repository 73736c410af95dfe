/* The known sizes of the surface's public structs that lead with `size`
 * (core.h: struct sizes; lib/core/struct_size.c reads and writes them):
 * the struct, the last field of its version 0.1 layout, and how a caller
 * gets a valid size. Each part keeps its own, so core knows no part; a
 * part that reads another's desc (the sim, the scene) includes this. */
#ifndef MS_SURFACE_SIZES_H
#define MS_SURFACE_SIZES_H

#include "core/core_internal.h"
#include "modesplit/surface.h"

#define MS_SIZES_SURFACE_DESC \
    MS_STRUCT_SIZES(ms_surface_desc, max_substeps, "ms_surface_desc_default()")
#define MS_SIZES_RAIN MS_STRUCT_SIZES(ms_rain, amplitude, "ms_rain_default()")
#define MS_SIZES_DISTURBER_DESC \
    MS_STRUCT_SIZES(ms_disturber_desc, depth, "ms_disturber_desc_default()")
#define MS_SIZES_SURFACE_INFO MS_STRUCT_SIZES(ms_surface_info, drops, "ms_surface_info_init()")

#endif /* MS_SURFACE_SIZES_H */
