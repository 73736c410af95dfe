/* modesplit plugins: the registered shape and shader plugins and the
 * files they came from, the search path, and any plugin file that was
 * skipped (with the reason). */
#include <string.h>

#include "tool.h"

int cmd_plugins(int argc, char **argv)
{
    for (int i = 1; i < argc; ++i) {
        if (!strcmp(argv[i], "--help") || !strcmp(argv[i], "-h")) {
            tool_command_usage(stdout, "plugins");
            return EXIT_OK;
        }
        tool_error("plugins: takes no arguments (got %s)", argv[i]);
        return EXIT_USAGE;
    }
    int n = ms_plugin_count();
    printf("search path: %s\n", ms_plugin_search_path());
    if (n == 0)
        printf("no plugins found\n");
    for (int i = 0; i < n; ++i) {
        ms_plugin_description d = ms_plugin_description_init();
        if (ms_plugin_describe(i, &d) != MS_OK)
            continue;
        printf("%-6s %-10s %-8s %s\n       from %s (ABI %u.%u)\n", d.kind, d.name,
               d.version ? d.version : "", d.description ? d.description : "", d.path,
               (unsigned)(d.abi >> 16), (unsigned)(d.abi & 0xffffu));
    }
    int np = ms_plugin_problem_count();
    for (int i = 0; i < np; ++i)
        tool_error("plugins: %s", ms_plugin_problem(i));
    return EXIT_OK;
}
