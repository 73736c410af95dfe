/* The scene schema (sections.c; the effects, render and output sections in
 * effects.c, section_render.c, section_output.c). Internal. */
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

#define MS_SCENE_BIG 1e4       /* m: coordinates of a scene lie in [-BIG, BIG] */
#define MS_SCENE_MAX_SPEED 1e3 /* m/s */

/* The "effects" section (effects.c), read after domain, surface, volume and
 * obstacles (floaters spread over the domain; surface effects need one). */
ms_status ms_scene_read_effects(ms_scene_ctx *c, json_t *root, ms_scene *sc);

/* The "render" section (section_render.c; dir as above, for the cubemap)
 * and the "output" section (section_output.c), read last. */
ms_status ms_scene_read_render(ms_scene_ctx *c, json_t *root, ms_scene *sc, const char *dir);
ms_status ms_scene_read_output(ms_scene_ctx *c, json_t *root, ms_scene *sc);

/* Shared by the readers of sections.c and effects.c: the motion path at
 * obj[key] ({"points", "speed", "loop", "start"}; dim 2 or 3), and a shape
 * of a plugin (obstacle or container) in the object o. */
ms_status ms_scene_read_path(ms_scene_ctx *c, json_t *obj, const char *key, int dim,
                             ms_scene_motion *p);
ms_status ms_scene_read_shape(ms_scene_ctx *c, json_t *o, ms_scene_shape *s);

#endif
