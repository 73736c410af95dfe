/* The scene schema (sections.c). Internal. */
#ifndef MS_SCENE_SECTIONS_H
#define MS_SCENE_SECTIONS_H

#include <jansson.h>

#include "scene/reader.h"
#include "scene/scene_internal.h"

/* Read every section of root into sc (zeroed by the caller). dir: the
 * scene file's directory with a trailing '/' ("" when parsed from memory),
 * for relative paths; default_name: the name when the scene gives none. */
ms_status ms_scene_read_sections(ms_scene_ctx *c, json_t *root, ms_scene *sc, const char *dir,
                                 const char *default_name);


#endif
