/* Positions of keys in a scene's JSON text (see locate.c). Internal. */
#ifndef MS_SCENE_LOCATE_H
#define MS_SCENE_LOCATE_H

#include <stddef.h>

/* One step of a path into a JSON document: an object key, or (key NULL)
 * an array index. */
typedef struct ms_scene_pathelem {
    const char *key;
    long index;
} ms_scene_pathelem;

/* Byte offset of the place the path names in text (the key's opening quote
 * for an object member, the element for an array index, the root for
 * depth 0). 1 if found; 0 otherwise, with *pos at the deepest step found. */
int ms_scene_locate(const char *text, size_t len, const ms_scene_pathelem *path, int depth,
                    size_t *pos);
/* 1-based line and column (in characters) of byte offset pos. */
void ms_scene_line_col(const char *text, size_t len, size_t pos, int *line, int *col);

#endif
