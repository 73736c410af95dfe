/* The known sizes of the plugin registry's public structs that lead with `size`
 * (core.h: struct sizes; lib/core/struct_size.c reads and writes them):
 * the struct, the last field of its version 0.1 layout, and how a caller
 * gets a valid size. Each part keeps its own, so core knows no part; a
 * part that reads another's desc (the sim, the scene) includes this. */
#ifndef MS_PLUGIN_SIZES_H
#define MS_PLUGIN_SIZES_H

#include "core/core_internal.h"
#include "modesplit/plugin.h"

#define MS_SIZES_PLUGIN_DESCRIPTION \
    MS_STRUCT_SIZES(ms_plugin_description, abi, "ms_plugin_description_init()")

#endif /* MS_PLUGIN_SIZES_H */
