/* A program linked against the INSTALLED shared library (built by
 * tests/test_plugin.c with pkg-config): prints the plugin search path and,
 * per plugin, "name path"; then the distance from (0.3, 0, 0.5) to a torus
 * made by the out-of-tree plugin, if it is there. */
#include <stdio.h>

#include <modesplit/modesplit.h>
#include <modesplit/plugin.h>

int main(void)
{
    printf("path %s\n", ms_plugin_search_path());
    for (int i = 0; i < ms_plugin_count(); ++i) {
        ms_plugin_description d = ms_plugin_description_init();
        if (ms_plugin_describe(i, &d) == MS_OK)
            printf("plugin %s %s\n", d.name, d.path);
    }
    ms_shape *s;
    if (ms_shape_create("torus", "{\"major\": 0.3, \"minor\": 0.1}", &s) == MS_OK) {
        printf("torus %.6f\n", ms_shape_distance(s, (const float[3]){0.3f, 0, 0.5f}, NULL));
        ms_shape_destroy(s);
    } else {
        printf("error %s\n", ms_last_error());
    }
    return 0;
}
