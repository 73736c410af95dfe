/* The known sizes of every public struct that carries a leading `size`
 * (core.h: struct sizes), in one place: the struct, the last field of its
 * version 0.1 layout, and how a caller gets a valid size. When a struct
 * grows in a later release, its 0.1 layout stays known through v1_end. */
#ifndef MS_CORE_STRUCT_SIZES_H
#define MS_CORE_STRUCT_SIZES_H

#include "core/core_internal.h"
#include "modesplit/modesplit.h"
#include "modesplit/plugin.h"

#define MS_SIZES_SURFACE_DESC \
    MS_STRUCT_SIZES(ms_surface_desc, max_substeps, "ms_surface_desc_default()")
#define MS_SIZES_RAIN MS_STRUCT_SIZES(ms_rain, amplitude, "ms_rain_default()")
#define MS_SIZES_DISTURBER_DESC \
    MS_STRUCT_SIZES(ms_disturber_desc, depth, "ms_disturber_desc_default()")
#define MS_SIZES_SURFACE_INFO MS_STRUCT_SIZES(ms_surface_info, drops, "ms_surface_info_init()")
#define MS_SIZES_VOLUME_DESC \
    MS_STRUCT_SIZES(ms_volume_desc, density_kernel, "ms_volume_desc_default()")
#define MS_SIZES_VOLUME_INFO MS_STRUCT_SIZES(ms_volume_info, threads, "ms_volume_info_init()")
#define MS_SIZES_SIM_DESC MS_STRUCT_SIZES(ms_sim_desc, user_task_context, "ms_sim_desc_default()")
#define MS_SIZES_STATS MS_STRUCT_SIZES(ms_stats, n_time, "ms_stats_init()")
#define MS_SIZES_SIM_INFO MS_STRUCT_SIZES(ms_sim_info, obstacles, "ms_sim_info_init()")
#define MS_SIZES_RENDERER_DESC \
    MS_STRUCT_SIZES(ms_renderer_desc, mesh_step, "ms_renderer_desc_default()")
#define MS_SIZES_RENDER_STATS MS_STRUCT_SIZES(ms_render_stats, mesh_ny, "ms_render_stats_init()")
#define MS_SIZES_PREVIEW_DESC MS_STRUCT_SIZES(ms_preview_desc, scale, "ms_preview_desc_default()")
#define MS_SIZES_PLUGIN_DESCRIPTION \
    MS_STRUCT_SIZES(ms_plugin_description, abi, "ms_plugin_description_init()")

#endif /* MS_CORE_STRUCT_SIZES_H */
