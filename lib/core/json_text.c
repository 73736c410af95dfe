/* A JSON value as text in the library's own memory (ms_malloc: the
 * engine's allocator when it set one). jansson's json_dumps returns a
 * block of jansson's allocator, which the library would have to give back
 * with jansson's free; json_dumpb writes into a buffer of ours instead,
 * measured by a first call. */
#include <jansson.h>
#include <string.h>

#include "core/core_internal.h"

char *ms_json_text(const struct json_t *v, size_t flags)
{
    if (!v)
        return NULL;
    size_t n = json_dumpb(v, NULL, 0, flags);
    if (n == 0)
        return NULL;
    char *text = ms_malloc(n + 1);
    if (!text)
        return NULL;
    if (json_dumpb(v, text, n, flags) != n) {
        ms_free(text);
        return NULL;
    }
    text[n] = '\0';
    return text;
}
