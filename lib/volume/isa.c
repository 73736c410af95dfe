/* The instruction-set paths of the volume's passes: which this build
 * has (passes_<isa>.c), which this CPU runs, the one a new volume takes
 * (the widest, or MODESPLIT_ISA's), and the build's description
 * (ms_get_build_info). Every path gives the same bytes. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "volume/passes.h"

static const char *const isa_names[MS_VOLUME_ISA_COUNT] = {"c", "sse2", "avx2", "avx512", "neon"};

const char *ms_volume_isa_name(int isa)
{
    return isa >= 0 && isa < MS_VOLUME_ISA_COUNT ? isa_names[isa] : "?";
}

int ms_volume_isa_runs(int isa)
{
    if (!ms_volume_passes_of(isa))
        return 0;
#if MS_VOLUME_LANES_X86
    __builtin_cpu_init();
    switch (isa) {
    case MS_VOLUME_ISA_AVX512:
        /* every extension passes_avx512.c and the attribute-built AVX-512
         * code (neighbours.c, forces.c's avx512dq, extract.c's popcnt) are
         * built with: a CPU with AVX-512F but not DQ (Knights Landing)
         * takes AVX2 rather than an illegal instruction */
        return __builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512dq") &&
               __builtin_cpu_supports("bmi") && __builtin_cpu_supports("bmi2") &&
               __builtin_cpu_supports("popcnt");
    case MS_VOLUME_ISA_AVX2:
        return __builtin_cpu_supports("avx2");
    default:
        return 1; /* C, and SSE2: in every x86-64 */
    }
#else
    return 1; /* C, and NEON: in every aarch64 */
#endif
}

int ms_volume_pick_isa(void)
{
    int best = MS_VOLUME_ISA_C;
#if defined(__SANITIZE_THREAD__)
    const int widest = MS_VOLUME_ISA_SSE2; /* TSan: the paths it instruments */
#else
    const int widest = MS_VOLUME_ISA_COUNT - 1;
#endif
    for (int isa = MS_VOLUME_ISA_C; isa <= widest; ++isa)
        if (ms_volume_isa_runs(isa))
            best = isa;
    return best;
}

/* The names of the paths built (cpu 0) or run by this CPU (cpu 1),
 * space-separated, narrowest first. */
static void list_paths(int cpu, char *out, size_t n)
{
    size_t len = 0;
    out[0] = '\0';
    for (int isa = 0; isa < MS_VOLUME_ISA_COUNT; ++isa)
        if (cpu ? ms_volume_isa_runs(isa) : ms_volume_passes_of(isa) != NULL) {
            int w = snprintf(out + len, n - len, "%s%s", len ? " " : "", isa_names[isa]);
            if (w > 0 && (size_t)w < n - len)
                len += (size_t)w;
        }
}

ms_status ms_volume_choose_isa(int *out)
{
    const char *want = getenv("MODESPLIT_ISA");
    *out = ms_volume_pick_isa();
    if (!want || !*want)
        return MS_OK;
    char runs[64];
    list_paths(1, runs, sizeof runs);
    for (int isa = 0; isa < MS_VOLUME_ISA_COUNT; ++isa)
        if (!strcmp(want, isa_names[isa])) {
            if (!ms_volume_isa_runs(isa))
                return ms_fail(MS_ERR_UNSUPPORTED,
                               "volume: MODESPLIT_ISA=%s is not a path this CPU runs with this "
                               "build (it has: %s)",
                               want, runs);
            *out = isa;
            return MS_OK;
        }
    return ms_fail(MS_ERR_INVALID_ARGUMENT,
                   "volume: MODESPLIT_ISA=%.32s names no path (c, sse2, avx2, avx512, neon; "
                   "this CPU has: %s)",
                   want, runs);
}

ms_status ms_get_build_info(ms_build_info *out)
{
    static char built[64], cpu[64];
    if (!out)
        return ms_fail(MS_ERR_INVALID_ARGUMENT, "build info: out is NULL");
    list_paths(0, built, sizeof built);
    list_paths(1, cpu, sizeof cpu);
#if defined(__clang__)
    out->compiler = "clang " __clang_version__;
#elif defined(__GNUC__)
    out->compiler = "gcc " __VERSION__;
#else
    out->compiler = "unknown";
#endif
    out->paths_built = built;
    out->paths_cpu = cpu;
    int isa;
    ms_status st = ms_volume_choose_isa(&isa);
    out->path_chosen = st == MS_OK ? isa_names[isa] : NULL;
    return st;
}
