/* libFuzzer harness: forged checkpoints restored through ms_sim_restore.
 *
 * A checksum finds damage, not forgery: a forger edits a record and
 * reseals the blob. So the harness reseals every input the way a forger
 * does (the header of a real snapshot of the same sim, its total and
 * checksum recomputed), and the mutations reach the records themselves:
 * counts, ids, floats, the settings that bound work. The first byte picks
 * the route:
 *   even: the rest is the records of a blob (after the 72-byte header);
 *   odd:  the rest is a run file, its newest checkpoint read back through
 *         ms_reader (as `modesplit run --resume` does), then resealed.
 * A restore either succeeds, and then one frame steps and a snapshot
 * round-trips, or is refused with a sentence and leaves the sim failed
 * (refusing to step) until a good blob revives it.
 *
 * With MS_FUZZ_SEEDS=DIR set, the initializer writes the seeds there
 * (real blobs and a run file of this sim with both checkpoint slots) before
 * the corpus is read. Run by .ci/fuzz. */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "core/blob.h"
#include "modesplit/modesplit.h"

int LLVMFuzzerInitialize(int *argc, char ***argv);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

#define HEADER 72
#define H_TOTAL 16
#define H_SUM 32

/* small: every effect with state in a snapshot (SPH, waves, rain, a boat,
 * floaters), few particles so a step under ASan takes milliseconds */
static const char scene_json[] =
    "{\"name\": \"fuzz_restore\", \"duration\": 1.0, \"frame_dt\": 0.02, \"threads\": 1,"
    " \"seed\": 3, \"domain\": {\"min\": [0, 0, 0], \"max\": [0.6, 0.5, 0.3]},"
    " \"volume\": {\"spacing\": 0.06, \"fill\": [{\"min\": [0, 0, 0], \"max\": [0.3, 0.5, 0.12]}],"
    "  \"field\": [10, 8]},"
    " \"surface\": {\"cells\": [24, 20], \"wave_speed\": 0.3, \"damping\": 0.9},"
    " \"effects\": {\"rain\": {\"rate\": 20.0, \"radius\": 0.03, \"amplitude\": -0.002},"
    "  \"boat\": {\"path\": {\"points\": [[0.1, 0.1], [0.5, 0.4]], \"speed\": 0.3, \"loop\": true},"
    "   \"radius\": 0.03, \"depth\": 0.01},"
    "  \"floaters\": {\"count\": 4, \"region\": {\"min\": [0.1, 0.1], \"max\": [0.5, 0.4]}}},"
    " \"output\": {\"fields\": [\"combined\", \"particles\"], \"every\": 1,"
    "  \"checkpoint_every\": 2}}";

static ms_scene *scene;
static ms_sim *sim;
static unsigned char *good;
static size_t good_bytes;
static char run_path[256];

static void die(const char *what)
{
    fprintf(stderr, "fuzz_restore: %s: %s\n", what, ms_last_error());
    abort();
}

static void write_file(const char *dir, const char *name, const void *p, size_t n)
{
    char path[512];
    snprintf(path, sizeof path, "%s/%s", dir, name);
    FILE *f = fopen(path, "wb");
    if (!f || fwrite(p, 1, n, f) != n)
        die(path);
    fclose(f);
}

/* The seeds: blobs after 0, 3 and 6 frames (route byte 0, then the
 * records), and a run file of 6 frames with its checkpoints (route 1). */
static void write_seeds(const char *dir)
{
    ms_sim *s;
    if (ms_sim_create_from_scene(scene, 1, &s) != MS_OK)
        die("seed sim");
    /* written in the scratch folder: the seed folder is the corpus */
    const char *run = run_path;
    remove(run);
    ms_writer *w;
    if (ms_writer_open(run, s, MS_FIELD_COMBINED | MS_FIELD_PARTICLES, &w) != MS_OK)
        die("seed writer");
    char xmf[2][600];
    snprintf(xmf[0], sizeof xmf[0], "%s", ms_writer_xdmf_path(w));
    snprintf(xmf[1], sizeof xmf[1], "%s", ms_writer_xdmf_legacy_path(w));
    for (int frame = 0; frame <= 6; ++frame) {
        if (frame % 3 == 0) {
            size_t n;
            if (ms_sim_snapshot_size(s, &n) != MS_OK)
                die("seed size");
            unsigned char *b = malloc(n + 1);
            if (!b || ms_sim_snapshot(s, b + 1, n, &n) != MS_OK)
                die("seed snapshot");
            b[0] = 0;
            char name[32];
            snprintf(name, sizeof name, "blob%d", frame);
            /* the route byte, then the records */
            memmove(b + 1, b + 1 + HEADER, n - HEADER);
            write_file(dir, name, b, n - HEADER + 1);
            free(b);
        }
        if (frame == 6)
            break;
        if (ms_sim_step(s, ms_scene_frame_dt(scene)) != MS_OK || ms_writer_frame(w, s) != MS_OK)
            die("seed step");
    }
    if (ms_writer_close(w) != MS_OK)
        die("seed close");
    FILE *f = fopen(run, "rb");
    if (!f)
        die(run);
    fseek(f, 0, SEEK_END);
    long len = ftell(f);
    fseek(f, 0, SEEK_SET);
    unsigned char *b = malloc((size_t)len + 1);
    if (!b || fread(b + 1, 1, (size_t)len, f) != (size_t)len)
        die("seed read");
    fclose(f);
    b[0] = 1;
    write_file(dir, "run", b, (size_t)len + 1);
    free(b);
    remove(run);
    remove(xmf[0]);
    remove(xmf[1]);
    ms_sim_destroy(s);
}

int LLVMFuzzerInitialize(int *argc, char ***argv)
{
    (void)argc;
    (void)argv;
    if (ms_scene_parse(scene_json, sizeof scene_json - 1, &scene) != MS_OK)
        die("scene");
    if (ms_sim_create_from_scene(scene, 1, &sim) != MS_OK)
        die("sim");
    for (int i = 0; i < 3; ++i)
        if (ms_sim_step(sim, ms_scene_frame_dt(scene)) != MS_OK)
            die("step");
    if (ms_sim_snapshot_size(sim, &good_bytes) != MS_OK || !(good = malloc(good_bytes)) ||
        ms_sim_snapshot(sim, good, good_bytes, &good_bytes) != MS_OK)
        die("snapshot");
    const char *dir = getenv("MS_FUZZ_TMP");
    snprintf(run_path, sizeof run_path, "%s/ms_fuzz_restore_%ld.h5", dir && *dir ? dir : "/tmp",
             (long)getpid());
    const char *seeds = getenv("MS_FUZZ_SEEDS");
    if (seeds && *seeds)
        write_seeds(seeds);
    return 0;
}

/* The newest checkpoint of the run file held in data (NULL if none). */
static unsigned char *checkpoint_of(const uint8_t *data, size_t size, size_t *bytes)
{
    FILE *f = fopen(run_path, "wb");
    if (!f)
        return NULL;
    fwrite(data, 1, size, f);
    fclose(f);
    ms_reader *r = NULL;
    unsigned char *b = NULL;
    if (ms_reader_open(run_path, &r) != MS_OK) {
        if (r != NULL || ms_last_error()[0] == '\0')
            __builtin_trap();
        return NULL;
    }
    long frames[2];
    if (ms_reader_checkpoints(r, frames) > 0 && ms_reader_checkpoint_size(r, 0, bytes) == MS_OK &&
        *bytes >= HEADER && *bytes <= ((size_t)64 << 20) && (b = malloc(*bytes)) != NULL &&
        ms_reader_read_checkpoint(r, 0, b, *bytes) != MS_OK) {
        free(b);
        b = NULL;
    }
    ms_reader_close(r);
    return b;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    if (size < 1)
        return 0;
    unsigned char *blob = NULL;
    size_t bytes = 0;
    if (data[0] % 2 == 0) {
        bytes = HEADER + size - 1;
        blob = malloc(bytes);
        if (!blob)
            return 0;
        memcpy(blob + HEADER, data + 1, size - 1);
    } else {
        blob = checkpoint_of(data + 1, size - 1, &bytes);
        if (!blob)
            return 0;
    }
    /* reseal as a forger does: this sim's header, the total and checksum
     * of these records */
    memcpy(blob, good, HEADER);
    uint64_t total = bytes, sum = ms_blob_hash(MS_BLOB_HASH0, blob + HEADER, bytes - HEADER);
    memcpy(blob + H_TOTAL, &total, sizeof total);
    memcpy(blob + H_SUM, &sum, sizeof sum);

    if (ms_sim_restore(sim, good, good_bytes) != MS_OK)
        die("the good blob no longer restores");
    ms_status st = ms_sim_restore(sim, blob, bytes);
    float dt = ms_scene_frame_dt(scene);
    if (st != MS_OK) {
        /* refused with a sentence; the sim is failed and says so */
        if (ms_last_error()[0] == '\0' || ms_sim_step(sim, dt) != MS_ERR_STATE)
            __builtin_trap();
    } else {
        /* accepted: every value is in range, so a frame steps (or fails
         * with a sentence, as an unstable scene does) and the state
         * snapshots again */
        if (ms_sim_step(sim, dt) != MS_OK && ms_last_error()[0] == '\0')
            __builtin_trap();
        size_t n = 0;
        if (ms_sim_snapshot_size(sim, &n) == MS_OK && n <= ((size_t)64 << 20)) {
            unsigned char *again = malloc(n);
            if (again)
                (void)ms_sim_snapshot(sim, again, n, &n);
            free(again);
        }
    }
    free(blob);
    return 0;
}
