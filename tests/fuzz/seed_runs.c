/* Writes small run files into a directory: the seed corpus of
 * fuzz_reader.c (.ci/fuzz). Built against the library's raw writer, so it
 * needs no sim: every layout the format has (each field alone, all of
 * them, particles with 0 and n entries, a non-square grid, a scene text). */
#include <stdio.h>
#include <stdlib.h>

#include "io/io_internal.h"

int main(int argc, char **argv)
{
    if (argc != 2) {
        fprintf(stderr, "usage: seed_runs DIR\n");
        return 2;
    }
    static const unsigned sets[] = {MS_FIELD_COMBINED, MS_FIELD_SURFACE | MS_FIELD_PARTICLES,
                                    MS_FIELD_VOLUME, MS_IO_ALL_FIELDS};
    for (int s = 0; s < 4; ++s) {
        ms_writer_layout l = {0};
        l.fields = sets[s];
        l.grid[0] = l.grid[1] = (ms_grid){5, 3, 0.1f, 0.2f, {0.0f, -0.3f}};
        l.grid[2] = (ms_grid){2, 2, 0.25f, 0.3f, {0.0f, -0.3f}};
        l.scene_text = "{\"name\": \"seed\", \"surface\": {\"cells\": [5, 3]}}";
        l.scene_name = "seed";
        l.frame_dt = 0.02;
        l.output_every = 1 + s;
        l.deflate = s % 2; /* both with and without filters */
        char path[512];
        snprintf(path, sizeof path, "%s/seed%d.h5", argv[1], s);
        ms_writer *w;
        if (ms_writer_open_layout(path, &l, &w) != MS_OK) {
            fprintf(stderr, "seed_runs: %s\n", ms_last_error());
            return 1;
        }
        float f[3][15], p[6][4];
        for (int k = 0; k < 1 + s; ++k) {
            for (int i = 0; i < 15; ++i)
                f[0][i] = f[1][i] = f[2][i] = 0.3f + 0.01f * (float)(i + k);
            for (int c = 0; c < 6; ++c)
                for (int i = 0; i < 4; ++i)
                    p[c][i] = (float)(c + i + k);
            ms_writer_data d = {.time = 0.02 * (k + 1),
                                .field = {f[0], f[1], f[2]},
                                .particles = k % 2 ? 4 : 0,
                                .pos = {p[0], p[1], p[2]},
                                .vel = {p[3], p[4], p[5]}};
            if (ms_writer_write(w, &d) != MS_OK) {
                fprintf(stderr, "seed_runs: %s\n", ms_last_error());
                return 1;
            }
        }
        if (ms_writer_close(w) != MS_OK)
            return 1;
        snprintf(path, sizeof path, "%s/seed%d.xmf", argv[1], s);
        remove(path);
    }
    return 0;
}
