/* Compiled by `make check-headers` as C11 (pedantic) and as C++11: every
 * public header must stand alone in both languages. */
#include <modesplit/modesplit.h>
#include <modesplit/plugin.h>

int ms_headers_compile_probe(void);
int ms_headers_compile_probe(void)
{
    ms_surface_desc s = ms_surface_desc_default();
    ms_volume_desc v = ms_volume_desc_default();
    ms_sim_desc d = ms_sim_desc_default();
    d.surface = &s;
    d.volume = &v;
    ms_stats st = ms_stats_init(); /* the struct-size initialisers compile in both */
    ms_surface_info si = ms_surface_info_init();
    return (int)MS_OK + (int)sizeof d + (int)MS_PLUGIN_ABI + (int)st.size + (int)si.size;
}
