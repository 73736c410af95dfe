/* libFuzzer harness: the run-file reader behind `modesplit info`
 * (ms_reader_*) on arbitrary bytes written to a scratch file. A file must
 * either open (and then every accessor and read behave) or be refused
 * with a sentence. Run by .ci/fuzz, seeded from small run files that
 * tests/fuzz/seed_runs.c writes. */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "modesplit/modesplit.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

static char path[256];

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    if (!path[0]) {
        const char *dir = getenv("MS_FUZZ_TMP");
        snprintf(path, sizeof path, "%s/ms_fuzz_reader_%ld.h5", dir && *dir ? dir : "/tmp",
                 (long)getpid());
    }
    FILE *f = fopen(path, "wb");
    if (!f)
        return 0;
    fwrite(data, 1, size, f);
    fclose(f);
    ms_reader *r = NULL;
    ms_status st = ms_reader_open(path, &r);
    if (st != MS_OK) {
        if (r != NULL || ms_last_error()[0] == '\0')
            __builtin_trap();
        return 0;
    }
    long frames = ms_reader_frames(r);
    unsigned fields = ms_reader_fields(r);
    volatile size_t n = strlen(ms_reader_scene(r)) + strlen(ms_reader_scene_name(r)) +
                        strlen(ms_reader_library_version(r));
    (void)n;
    (void)ms_reader_frame_dt(r);
    (void)ms_reader_output_every(r);
    (void)ms_reader_format_version(r);
    long pick[3] = {0, frames / 2, frames - 1};
    for (int i = 0; i < 3 && frames > 0; ++i) {
        double t;
        ms_reader_time(r, pick[i], &t);
        for (unsigned bit = 1; bit <= 4; bit <<= 1) {
            ms_grid g;
            if (!(fields & bit) || ms_reader_field_grid(r, bit, &g) != MS_OK)
                continue;
            uint64_t stored, raw;
            ms_reader_field_bytes(r, bit, &stored, &raw);
            size_t cells = (size_t)g.nx * (size_t)g.ny;
            if (cells > (1u << 20))
                continue;
            float *h = malloc(cells * sizeof *h);
            if (h)
                ms_reader_read_field(r, bit, pick[i], h, cells);
            free(h);
        }
        int np = 0;
        if (ms_reader_particle_count(r, pick[i], &np) == MS_OK && np > 0 && np <= (1 << 20)) {
            float *p[6];
            for (int c = 0; c < 6; ++c)
                p[c] = malloc((size_t)np * sizeof(float));
            if (p[0] && p[1] && p[2] && p[3] && p[4] && p[5])
                ms_reader_read_particles(r, pick[i], np, p, p + 3);
            for (int c = 0; c < 6; ++c)
                free(p[c]);
        }
    }
    /* out-of-range requests are refused, never read */
    float one;
    if (ms_reader_read_field(r, MS_FIELD_COMBINED, frames, &one, 1) == MS_OK)
        __builtin_trap();
    ms_reader_close(r);
    return 0;
}
