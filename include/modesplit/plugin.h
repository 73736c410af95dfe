/* plugin.h: everything a plugin author needs, and nothing else.
 *
 * A plugin is a shared object exporting one symbol, ms_plugin_entry, that
 * returns a const ms_plugin_info *. The info starts with the ABI version
 * and its own size; the loader checks both before it reads anything else.
 * Structs here only grow at the end.
 */
#ifndef MODESPLIT_PLUGIN_H
#define MODESPLIT_PLUGIN_H

#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

#define MS_PLUGIN_ABI_MAJOR 1u
#define MS_PLUGIN_ABI_MINOR 0u
#define MS_PLUGIN_ABI ((MS_PLUGIN_ABI_MAJOR << 16) | MS_PLUGIN_ABI_MINOR)
#define MS_PLUGIN_ENTRY_SYMBOL "ms_plugin_entry"

#ifdef __cplusplus
}
#endif

#endif /* MODESPLIT_PLUGIN_H */
