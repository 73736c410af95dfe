/* The known sizes of the volume's public structs that lead with `size`
 * (core.h: struct sizes; lib/core/struct_size.c reads and writes them):
 * the struct, the last field of its version 0.1 layout, and how a caller
 * gets a valid size. Each part keeps its own, so core knows no part; a
 * part that reads another's desc (the sim, the scene) includes this. */
#ifndef MS_VOLUME_SIZES_H
#define MS_VOLUME_SIZES_H

#include "core/core_internal.h"
#include "modesplit/volume.h"

#define MS_SIZES_VOLUME_DESC \
    MS_STRUCT_SIZES(ms_volume_desc, density_kernel, "ms_volume_desc_default()")
#define MS_SIZES_VOLUME_INFO MS_STRUCT_SIZES(ms_volume_info, threads, "ms_volume_info_init()")

#endif /* MS_VOLUME_SIZES_H */
