/* `--set KEY=VALUE` of `modesplit run` and `modesplit check`: collected here
 * and handed to ms_scene_load_with_overrides, which checks them as it
 * checks the file (the message of a bad one names the "--set"). */
#include <string.h>

#include "tool.h"

int tool_set_option(int argc, char **argv, int *i, tool_sets *s, int *bad)
{
    const char *v = NULL;
    if (!tool_opt_value(argc, argv, i, "--set", &v, bad))
        return 0;
    if (*bad)
        return 1;
    if (!strchr(v, '=') || v[0] == '=') {
        tool_error("--set %s: not KEY=VALUE; allowed: e.g. --set volume.spacing=0.025", v);
        *bad = 1;
    } else if (s->n == TOOL_MAX_SETS) {
        tool_error("--set %s: more than %d overrides", v, TOOL_MAX_SETS);
        *bad = 1;
    } else {
        s->v[s->n++] = v;
    }
    return 1;
}

int tool_load_scene(const char *path, const tool_sets *s, ms_scene **out)
{
    if (ms_scene_load_with_overrides(path, s->n, s->v, out) != MS_OK) {
        tool_error("%s", ms_last_error());
        return -1;
    }
    return 0;
}
