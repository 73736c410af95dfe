/* ms_scene: a scene file (JSON, see data/scenes/README.md) turned into the
 * descs of the parts it calls for. A section that is absent is an effect
 * that is not simulated and costs nothing. Errors name file:line:col, the
 * key and what is allowed.
 */
#ifndef MODESPLIT_SCENE_H
#define MODESPLIT_SCENE_H

#include "core.h"

#ifdef __cplusplus
extern "C" {
#endif

MS_API ms_status ms_scene_load(const char *path, ms_scene **out);
MS_API ms_status ms_scene_parse(const char *json, size_t len, ms_scene **out);
MS_API void ms_scene_destroy(ms_scene *sc);

#ifdef __cplusplus
}
#endif

#endif /* MODESPLIT_SCENE_H */
