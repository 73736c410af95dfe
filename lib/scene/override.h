/* Scene overrides, `--set KEY=VALUE` (override.c). Internal. */
#ifndef MS_SCENE_OVERRIDE_H
#define MS_SCENE_OVERRIDE_H

#include <stddef.h>

#include "modesplit/core.h"

/* "KEY=VALUE" with a non-empty KEY, else MS_ERR_INVALID_ARGUMENT. */
ms_status ms_scene_override_check(const char *set);

/* The scene text with the n overrides applied and listed under
 * "overrides": *out (ms_alloc'd, NUL-terminated), *out_len bytes. */
ms_status ms_scene_apply_overrides(const char *text, size_t len, int n, const char *const *set,
                                   char **out, size_t *out_len);

#endif
