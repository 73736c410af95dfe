/* libFuzzer harness: the scene parser (ms_scene_parse) on arbitrary bytes.
 * Every input must either parse or be refused with a status and a
 * sentence; never crash, leak, read out of bounds or hang. Run by
 * .ci/fuzz, seeded from data/scenes/ and tests/data/bad_scenes/. */
#include <stddef.h>
#include <stdint.h>
#include <string.h>

#include "modesplit/modesplit.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    ms_scene *sc = NULL;
    ms_status st = ms_scene_parse((const char *)data, size, &sc);
    if (st == MS_OK) {
        /* touch what the tool reads */
        volatile size_t n =
            strlen(ms_scene_name(sc)) + strlen(ms_scene_text(sc)) + strlen(ms_scene_path(sc));
        volatile double d = ms_scene_duration(sc) + ms_scene_frame_dt(sc) +
                            ms_scene_output_fields(sc) + ms_scene_output_every(sc) +
                            ms_scene_has_render(sc);
        (void)n;
        (void)d;
        ms_scene_destroy(sc);
    } else if (sc != NULL || ms_last_error()[0] == '\0') {
        __builtin_trap(); /* a refusal leaves no handle and says why */
    }
    return 0;
}
