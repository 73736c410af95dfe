/* The known sizes of the sim's public structs that lead with `size`
 * (core.h: struct sizes; lib/core/struct_size.c reads and writes them):
 * the struct, the last field of its version 0.1 layout, and how a caller
 * gets a valid size. Each part keeps its own, so core knows no part; a
 * part that reads another's desc (the sim, the scene) includes this. */
#ifndef MS_SIM_SIZES_H
#define MS_SIM_SIZES_H

#include "core/core_internal.h"
#include "modesplit/sim.h"

#define MS_SIZES_SIM_DESC MS_STRUCT_SIZES(ms_sim_desc, user_task_context, "ms_sim_desc_default()")
#define MS_SIZES_STATS MS_STRUCT_SIZES(ms_stats, n_time, "ms_stats_init()")
#define MS_SIZES_SIM_INFO MS_STRUCT_SIZES(ms_sim_info, obstacles, "ms_sim_info_init()")

#endif /* MS_SIM_SIZES_H */
