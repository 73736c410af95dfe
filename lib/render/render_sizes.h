/* The known sizes of the renderer's public structs that lead with `size`
 * (core.h: struct sizes; lib/core/struct_size.c reads and writes them):
 * the struct, the last field of its version 0.1 layout, and how a caller
 * gets a valid size. Each part keeps its own, so core knows no part; a
 * part that reads another's desc (the sim, the scene) includes this. */
#ifndef MS_RENDER_SIZES_H
#define MS_RENDER_SIZES_H

#include "core/core_internal.h"
#include "modesplit/render.h"

#define MS_SIZES_RENDERER_DESC \
    MS_STRUCT_SIZES(ms_renderer_desc, mesh_step, "ms_renderer_desc_default()")
#define MS_SIZES_RENDER_STATS MS_STRUCT_SIZES(ms_render_stats, mesh_ny, "ms_render_stats_init()")

#endif /* MS_RENDER_SIZES_H */
