/* Files are untrusted input, as the tool meets them: paths that are not
 * regular files (FIFOs, devices, run files linking to other files) are
 * refused before they are opened, and `check` refuses what `run` refuses;
 * `export` refuses what `info` refuses, in the same sentence, and a file
 * claiming more frames than the disk holds or a frame larger than memory
 * before anything is read; strings from a file reach the terminal
 * escaped; a resume of a file of another grid says so. Every hostile file is made here, from a real
 * run file edited with HDF5 as a forger would. A hang fails by the case's
 * time-out. */
#define _GNU_SOURCE
#include <check.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <hdf5.h>
#include <png.h>

#include "modesplit/modesplit.h"
#include "support.h"

static char tmp_dir[256];

/* A path in the case's folder; valid until the case ends. */
static char *paths[256];
static int npaths;

static const char *tmp_path(const char *name)
{
    ck_assert_int_lt(npaths, 256);
    char *p = malloc(strlen(tmp_dir) + strlen(name) + 2);
    ck_assert_ptr_nonnull(p);
    sprintf(p, "%s/%s", tmp_dir, name);
    return paths[npaths++] = p;
}

typedef struct result {
    int code; /* exit status, -1 when killed */
    char *out, *err;
} result;

static result run_tool(const char *const *args)
{
    result r;
    const char *out = tmp_path("stdout.txt"), *err = tmp_path("stderr.txt");
    int st = ms_test_run_tool(args, out, err);
    r.code = WIFEXITED(st) ? WEXITSTATUS(st) : -1;
    r.out = ms_test_slurp(out);
    r.err = ms_test_slurp(err);
    ck_assert_ptr_nonnull(r.out);
    ck_assert_ptr_nonnull(r.err);
    return r;
}

static void result_free(result *r)
{
    free(r->out);
    free(r->err);
}

/* The tool exited with `code` and its stderr holds `word`. */
#define ASSERT_REFUSED(r, want, word)                                                           \
    do {                                                                                        \
        ck_assert_msg((r).code == (want), "exit %d, expected %d; stderr: %s", (r).code, (want), \
                      (r).err);                                                                 \
        ck_assert_msg(strstr((r).err, (word)) != NULL, "stderr lacks \"%s\": %s", (word),       \
                      (r).err);                                                                 \
        ck_assert_msg(strstr((r).err, "Traceback") == NULL, "a traceback: %s", (r).err);        \
    } while (0)

static void write_text(const char *path, const char *text)
{
    FILE *f = fopen(path, "w");
    ck_assert_ptr_nonnull(f);
    fputs(text, f);
    fclose(f);
}

/* A small scene (waves and a few hundred particles, every field written)
 * with `extra` JSON members added at the end. */
static const char *scene_with(const char *name, const char *extra)
{
    char text[2048];
    snprintf(text, sizeof text,
             "{\"name\": \"untrusted\", \"duration\": 1.0, \"frame_dt\": 0.02, \"threads\": 1,"
             " \"domain\": {\"min\": [0, 0, 0], \"max\": [1.2, 0.9, 0.4]},"
             " \"volume\": {\"spacing\": 0.06, \"fill\": [{\"min\": [0, 0, 0], "
             "\"max\": [0.6, 0.9, 0.18]}], \"field\": [16, 12]},"
             " \"surface\": {\"cells\": [64, 48], \"wave_speed\": 0.3, \"damping\": 0.9},"
             " \"output\": {\"fields\": [\"combined\", \"surface\", \"volume\", \"particles\"],"
             " \"every\": 1}%s}",
             extra);
    const char *p = tmp_path(name);
    write_text(p, text);
    return p;
}

/* run SCENE --frames 3 --out NAME: a real run file to forge from. */
static const char *real_run(const char *scene, const char *name)
{
    const char *out = tmp_path(name);
    result r =
        run_tool((const char *[]){"run", scene, "--frames", "3", "--quiet", "--out", out, NULL});
    ck_assert_msg(r.code == 0, "%s", r.err);
    result_free(&r);
    return out;
}

static void setup(void)
{
    ck_assert_int_eq(ms_test_tmp_dir(tmp_dir, sizeof tmp_dir, "ms_untrusted"), 0);
}

static void teardown(void)
{
    ms_test_remove_tree(tmp_dir);
    while (npaths > 0)
        free(paths[--npaths]);
}

/* ---- paths that are not regular files ---- */

/* `check` and `run` of one scene both refuse, with exit 2 and `word`. */
static void check_and_run_refuse(const char *scene, const char *word)
{
    result c = run_tool((const char *[]){"check", scene, NULL});
    ASSERT_REFUSED(c, 2, word);
    result r = run_tool((const char *[]){"run", scene, "--frames", "1", "--no-out", NULL});
    ASSERT_REFUSED(r, 2, word);
    result_free(&c);
    result_free(&r);
}

START_TEST(fifos_devices_and_a_cubemap_without_faces_are_refused_by_check_and_run)
{
    const char *fifo = tmp_path("pipe.png");
    ck_assert_int_eq(mkfifo(fifo, 0600), 0);
    static const struct {
        const char *extra, *word;
    } cases[] = {
        /* a terrain PNG that is a FIFO (relative to the scene) or a device */
        {", \"obstacles\": [{\"shape\": \"terrain\", \"params\": {\"png\": \"pipe.png\","
         " \"size\": [1, 1], \"height_range\": [0, 0.05]}}]",
         "FIFO"},
        {", \"obstacles\": [{\"shape\": \"terrain\", \"params\": {\"png\": \"/dev/zero\","
         " \"size\": [1, 1], \"height_range\": [0, 0.05]}}]",
         "character device"},
        {", \"obstacles\": [{\"shape\": \"terrain\", \"params\": {\"png\": \"/dev/stdin\","
         " \"size\": [1, 1], \"height_range\": [0, 0.05]}}]",
         "png \"/dev/stdin\" cannot be read"},
        /* cubemaps: a directory without the six faces, a device, a FIFO */
        {", \"render\": {\"cubemap\": \"/etc\"}", "has no px.png"},
        {", \"render\": {\"cubemap\": \"/dev/zero\"}", "character device"},
        {", \"render\": {\"cubemap\": \"pipe.png\"}", "FIFO"},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; ++i)
        check_and_run_refuse(scene_with("s.json", cases[i].extra), cases[i].word);
    /* a FIFO as the run file (the open would block for good) */
    result r = run_tool(
        (const char *[]){"run", scene_with("s.json", ""), "--frames", "1", "--out", fifo, NULL});
    ASSERT_REFUSED(r, 1, "it is a FIFO (named pipe), not a regular file");
    result_free(&r);
}
END_TEST

/* A waves-only scene of 512^2 cells over 1 m^2 with `effects` (JSON). */
static const char *waves_with(const char *name, const char *effects)
{
    size_t n = strlen(effects) + 512;
    char *text = malloc(n);
    ck_assert_ptr_nonnull(text);
    snprintf(text, n,
             "{\"name\": \"work\", \"duration\": 1.0, \"frame_dt\": 0.02, \"threads\": 1,"
             " \"domain\": {\"min\": [0, 0, 0], \"max\": [1, 1, 0.4]},"
             " \"surface\": {\"cells\": [512, 512], \"wave_speed\": 0.3},"
             " \"effects\": %s}",
             effects);
    const char *p = tmp_path(name);
    write_text(p, text);
    free(text);
    return p;
}

/* `count` scripted drops at t = 0 of radius `radius` m, as JSON. */
static char *drops_json(int count, double radius)
{
    size_t n = (size_t)count * 80 + 32;
    char *s = malloc(n), *p = s;
    ck_assert_ptr_nonnull(s);
    p += sprintf(p, "{\"drops\": [");
    for (int i = 0; i < count; ++i)
        p += sprintf(p, "%s{\"at\": [0.5, 0.5], \"time\": 0, \"radius\": %g}", i ? ", " : "",
                     radius);
    sprintf(p, "]}");
    return s;
}

/* Every effect's work is bounded, and check refuses what run would: 4096
 * scripted drops at t = 0, each over the whole 512^2 grid (about a minute
 * for two frames before), and rain under the drops-a-second cap whose
 * drops are the grid's size, are refused by both with exit 2; drops just
 * under the cap (about 3 s of one core in all) pass check. */
START_TEST(drops_and_rain_of_unbounded_work_are_refused_by_check_and_run)
{
    char *many = drops_json(4096, 0.5);
    check_and_run_refuse(waves_with("drops.json", many), "visit 1.07e+09 wave cells in all");
    free(many);
    char *under = drops_json(1020, 0.5); /* 1020 * 512^2 cells: just under 2^28 */
    result c = run_tool((const char *[]){"check", waves_with("under.json", under), NULL});
    ck_assert_msg(c.code == 0, "%s", c.err);
    result_free(&c);
    free(under);
    /* 1e5 drops a second (the count cap) of a 0.5 m radius */
    check_and_run_refuse(waves_with("rain.json", "{\"rain\": {\"rate\": 1e5, \"radius\": 0.5}}"),
                         "wave cells a second; at most 2.68e+08");
    /* the same rain with the default radius is the count cap's, and passes */
    c = run_tool(
        (const char *[]){"check", waves_with("fine.json", "{\"rain\": {\"rate\": 1e5}}"), NULL});
    ck_assert_msg(c.code == 0, "%s", c.err);
    result_free(&c);
}
END_TEST

/* The path policy (docs/scenes.md): a scene may name its PNGs (a
 * terrain's height map, a cubemap folder) by `..` and absolute paths, as it
 * may any file its user can read; check and run accept both, and a missing
 * one is refused naming the path. */
START_TEST(a_scene_reads_pngs_by_parent_and_absolute_paths)
{
    ck_assert_int_eq(mkdir(tmp_path("assets"), 0700), 0);
    ck_assert_int_eq(mkdir(tmp_path("scenes"), 0700), 0);
    png_image img;
    memset(&img, 0, sizeof img);
    img.version = PNG_IMAGE_VERSION;
    img.width = img.height = 8;
    img.format = PNG_FORMAT_GRAY;
    unsigned char px[64];
    for (int i = 0; i < 64; ++i)
        px[i] = (unsigned char)(4 * i);
    const char *ground = tmp_path("assets/ground.png");
    ck_assert(png_image_write_to_file(&img, ground, 0, px, 0, NULL));
    const char *sky = tmp_path("assets/sky");
    result c = run_tool((const char *[]){"cubemap", "--out", sky, "--size", "16", NULL});
    ck_assert_msg(c.code == 0, "%s", c.err);
    result_free(&c);
    char abs_png[700], abs_sky[700];
    snprintf(abs_png, sizeof abs_png, "%s", ground);
    snprintf(abs_sky, sizeof abs_sky, "%s", sky);
    const char *const pngs[2] = {"../assets/ground.png", abs_png};
    const char *const skies[2] = {"../assets/sky", abs_sky};
    for (int i = 0; i < 2; ++i) {
        char extra[2048];
        snprintf(extra, sizeof extra,
                 ", \"obstacles\": [{\"shape\": \"terrain\", \"params\": {\"png\": \"%s\","
                 " \"size\": [1, 1], \"height_range\": [0, 0.05]}}],"
                 " \"render\": {\"cubemap\": \"%s\"}",
                 pngs[i], skies[i]);
        const char *scene = scene_with("scenes/s.json", extra);
        result ck = run_tool((const char *[]){"check", scene, NULL});
        ck_assert_msg(ck.code == 0, "%s: %s", pngs[i], ck.err);
        result_free(&ck);
        result r = run_tool((const char *[]){"run", scene, "--frames", "1", "--no-out", NULL});
        ck_assert_msg(r.code == 0, "%s: %s", pngs[i], r.err);
        result_free(&r);
    }
    const char *missing =
        scene_with("scenes/m.json", ", \"obstacles\": [{\"shape\": \"terrain\", \"params\": "
                                    "{\"png\": \"../assets/none.png\", \"size\": [1, 1],"
                                    " \"height_range\": [0, 0.05]}}]");
    check_and_run_refuse(missing, "assets/none.png");
}
END_TEST

static const char *sentence(const char *err);

/* Cut every file of a cubemap folder to `keep` bytes (0: empty). */
static void cut_faces(const char *dir, long keep)
{
    static const char *const faces[6] = {"px", "nx", "py", "ny", "pz", "nz"};
    for (int i = 0; i < 6; ++i) {
        char face[600];
        snprintf(face, sizeof face, "%s/%s.png", dir, faces[i]);
        ck_assert_int_eq(truncate(face, keep), 0);
    }
}

/* Faces whose headers are good and whose pixels are cut off, or that are
 * empty: check decodes what run --png decodes, and both refuse with the
 * same sentence (before, check said ok to the cut faces and run --png
 * failed at its renderer). */
START_TEST(check_refuses_the_cubemap_faces_run_cannot_decode)
{
    static const struct {
        long keep;
        const char *word;
    } cases[] = {{0, "is not a readable PNG"}, {60, "cannot be decoded"}};
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; ++i) {
        const char *dir = tmp_path(i ? "cut" : "empty");
        result r = run_tool((const char *[]){"cubemap", "--out", dir, "--size", "32", NULL});
        ck_assert_msg(r.code == 0, "%s", r.err);
        result_free(&r);
        cut_faces(dir, cases[i].keep);
        char extra[700];
        snprintf(extra, sizeof extra, ", \"render\": {\"cubemap\": \"%s\"}", dir);
        const char *scene = scene_with("s.json", extra);
        result c = run_tool((const char *[]){"check", scene, NULL});
        ASSERT_REFUSED(c, 2, cases[i].word);
        result p = run_tool((const char *[]){"run", scene, "--frames", "1", "--no-out", "--png",
                                             tmp_path("frames"), NULL});
        ASSERT_REFUSED(p, 2, cases[i].word);
        ck_assert_str_eq(sentence(p.err), sentence(c.err));
        result_free(&c);
        result_free(&p);
    }
}
END_TEST

/* Replace /time of a run file with an external link to `target`, or with a
 * dataset whose values are stored in `target` (HDF5's external storage). */
static void forge_time(const char *run, const char *target, int external_storage)
{
    hid_t f = H5Fopen(run, H5F_ACC_RDWR, H5P_DEFAULT);
    ck_assert_int_ge(f, 0);
    ck_assert_int_ge(H5Ldelete(f, "time", H5P_DEFAULT), 0);
    if (!external_storage) {
        ck_assert_int_ge(H5Lcreate_external(target, "/time", f, "time", H5P_DEFAULT, H5P_DEFAULT),
                         0);
    } else {
        hsize_t n = 3;
        hid_t sp = H5Screate_simple(1, &n, NULL), dcpl = H5Pcreate(H5P_DATASET_CREATE);
        ck_assert_int_ge(H5Pset_external(dcpl, target, 0, 3 * sizeof(double)), 0);
        hid_t d = H5Dcreate2(f, "time", H5T_IEEE_F64LE, sp, H5P_DEFAULT, dcpl, H5P_DEFAULT);
        ck_assert_int_ge(d, 0);
        H5Dclose(d);
        H5Pclose(dcpl);
        H5Sclose(sp);
    }
    H5Fclose(f);
}

START_TEST(a_run_file_naming_other_files_is_refused_before_they_are_opened)
{
    const char *scene = scene_with("s.json", "");
    const char *fifo = tmp_path("pipe");
    ck_assert_int_eq(mkfifo(fifo, 0600), 0);
    for (int storage = 0; storage < 2; ++storage) {
        const char *run = real_run(scene, storage ? "stored.h5" : "linked.h5");
        forge_time(run, fifo, storage);
        const char *word = storage ? "lacks /time" : "external or soft link";
        result r = run_tool((const char *[]){"info", run, NULL});
        ASSERT_REFUSED(r, 2, word);
        result_free(&r);
        r = run_tool((const char *[]){"export", run, "--usd", tmp_path("o.usdc"), NULL});
        ASSERT_REFUSED(r, 2, word);
        result_free(&r);
        r = run_tool((const char *[]){"run", scene, "--frames", "6", "--resume", run, NULL});
        ASSERT_REFUSED(r, 1, word);
        result_free(&r);
    }
    /* a device as the run file itself */
    result r = run_tool((const char *[]){"export", "/dev/zero", "--usd", tmp_path("o.usdc"), NULL});
    ASSERT_REFUSED(r, 2, "not a regular file");
    result_free(&r);
}
END_TEST

/* ---- export refuses what info refuses ---- */

static void set_int_attr(hid_t loc, const char *name, long long v)
{
    hid_t a = H5Aopen(loc, name, H5P_DEFAULT);
    ck_assert_int_ge(a, 0);
    ck_assert_int_ge(H5Awrite(a, H5T_NATIVE_LLONG, &v), 0);
    H5Aclose(a);
}

/* The sentence after "modesplit: " of a refusal, without "export: ". */
static const char *sentence(const char *err)
{
    const char *s = strstr(err, "modesplit: ");
    ck_assert_ptr_nonnull(s);
    s += strlen("modesplit: ");
    if (!strncmp(s, "export: ", 8))
        s += 8;
    return s;
}

START_TEST(export_refuses_what_info_refuses_in_the_same_sentence)
{
    const char *scene = scene_with("s.json", "");
    const char *good = real_run(scene, "good.h5");
    for (int kind = 0; kind < 3; ++kind) {
        char name[32];
        snprintf(name, sizeof name, "bad%d.h5", kind);
        const char *bad = tmp_path(name);
        char cmd[1200];
        snprintf(cmd, sizeof cmd, "cp '%s' '%s'", good, bad);
        ck_assert_int_eq(system(cmd), 0);
        hid_t f = H5Fopen(bad, H5F_ACC_RDWR, H5P_DEFAULT);
        ck_assert_int_ge(f, 0);
        if (kind == 0) { /* a format from the future */
            set_int_attr(f, "format_version", 99);
        } else if (kind == 1) { /* the combined field as int32 */
            ck_assert_int_ge(H5Ldelete(f, "fields/combined", H5P_DEFAULT), 0);
            hsize_t dims[3] = {3, 48, 64};
            hid_t sp = H5Screate_simple(3, dims, NULL);
            hid_t d = H5Dcreate2(f, "fields/combined", H5T_STD_I32LE, sp, H5P_DEFAULT, H5P_DEFAULT,
                                 H5P_DEFAULT);
            ck_assert_int_ge(d, 0);
            H5Dclose(d);
            H5Sclose(sp);
        } else { /* NaN grid spacing */
            hid_t d = H5Dopen2(f, "fields/combined", H5P_DEFAULT);
            hid_t a = H5Aopen(d, "dx", H5P_DEFAULT);
            const double nan2[2] = {NAN, 0.01};
            ck_assert_int_ge(H5Awrite(a, H5T_NATIVE_DOUBLE, nan2), 0);
            H5Aclose(a);
            H5Dclose(d);
        }
        H5Fclose(f);
        result i = run_tool((const char *[]){"info", bad, NULL});
        result e = run_tool((const char *[]){"export", bad, "--usd", tmp_path("o.usdc"), NULL});
        ck_assert_msg(i.code == 2 && e.code == 2, "info %d, export %d: %s / %s", i.code, e.code,
                      i.err, e.err);
        ck_assert_str_eq(sentence(e.err), sentence(i.err));
        ck_assert_ptr_null(strstr(e.err, "Traceback"));
        result_free(&i);
        result_free(&e);
    }
    /* a missing folder is not made */
    result r =
        run_tool((const char *[]){"export", good, "--usd", tmp_path("no/such/o.usdc"), NULL});
    ASSERT_REFUSED(r, 2, "does not exist");
    result_free(&r);
    struct stat sb;
    ck_assert_int_ne(stat(tmp_path("no"), &sb), 0);
    /* nor is a FIFO written */
    const char *fifo = tmp_path("pipe.usd");
    ck_assert_int_eq(mkfifo(fifo, 0600), 0);
    r = run_tool((const char *[]){"export", good, "--usd", fifo, NULL});
    ASSERT_REFUSED(r, 2, "is not a regular file");
    result_free(&r);
}
END_TEST

/* Sparse claims: 1e9 frames (extended, never written), 1e8 particles (a
 * step whose arrays are declared and never stored). The export streams its
 * frames, so the frames' count bounds the file it writes, not its memory. */
START_TEST(export_refuses_a_sparse_file_claiming_more_than_memory_holds)
{
    const char *scene = scene_with("s.json", "");
    const char *run = real_run(scene, "frames.h5");
    hid_t f = H5Fopen(run, H5F_ACC_RDWR, H5P_DEFAULT);
    ck_assert_int_ge(f, 0);
    const hsize_t frames = 1000000000ull;
    hid_t t = H5Dopen2(f, "time", H5P_DEFAULT);
    ck_assert_int_ge(H5Dset_extent(t, &frames), 0);
    H5Dclose(t);
    static const char *const fields[3] = {"fields/combined", "fields/surface", "fields/volume"};
    for (int i = 0; i < 3; ++i) {
        hid_t d = H5Dopen2(f, fields[i], H5P_DEFAULT);
        hid_t sp = H5Dget_space(d);
        hsize_t dims[3];
        H5Sget_simple_extent_dims(sp, dims, NULL);
        H5Sclose(sp);
        dims[0] = frames;
        ck_assert_int_ge(H5Dset_extent(d, dims), 0);
        H5Dclose(d);
    }
    set_int_attr(f, "frames", (long long)frames);
    H5Fclose(f);
    struct stat sb;
    ck_assert_int_eq(stat(run, &sb), 0);
    ck_assert_int_lt(sb.st_blocks * 512LL, 64LL << 20); /* the claim is not in the file */
    /* streamed as .usdc, it would not fit on the disk; as .usda, not in
     * memory either */
    result r = run_tool((const char *[]){"export", run, "--usd", tmp_path("o.usdc"), NULL});
    ASSERT_REFUSED(r, 2, "1000000000 frames of a 64 x 48 field would write about");
    ck_assert_msg(strstr(r.err, "free, so it is refused") != NULL, "%s", r.err);
    result_free(&r);
    r = run_tool((const char *[]){"export", run, "--usd", tmp_path("o.usda"), NULL});
    ASSERT_REFUSED(r, 2, "1000000000 frames as a .usda text layer");
    ck_assert_msg(strstr(r.err, "of memory") != NULL, "%s", r.err);
    result_free(&r);

    run = real_run(scene, "particles.h5");
    f = H5Fopen(run, H5F_ACC_RDWR, H5P_DEFAULT);
    ck_assert_int_ge(f, 0);
    static const char *const arrays[6] = {"x", "y", "z", "vx", "vy", "vz"};
    for (int k = 0; k < 6; ++k) {
        char name[64];
        snprintf(name, sizeof name, "Step#1/%s", arrays[k]);
        ck_assert_int_ge(H5Ldelete(f, name, H5P_DEFAULT), 0);
        hsize_t n = 100000000ull, chunk = 1u << 16;
        hid_t sp = H5Screate_simple(1, &n, NULL), dcpl = H5Pcreate(H5P_DATASET_CREATE);
        H5Pset_chunk(dcpl, 1, &chunk);
        hid_t d = H5Dcreate2(f, name, H5T_IEEE_F32LE, sp, H5P_DEFAULT, dcpl, H5P_DEFAULT);
        ck_assert_int_ge(d, 0);
        H5Dclose(d);
        H5Pclose(dcpl);
        H5Sclose(sp);
    }
    H5Fclose(f);
    r = run_tool((const char *[]){"export", run, "--usd", tmp_path("o.usdc"), NULL});
    ASSERT_REFUSED(r, 2, "does not hold its values");
    result_free(&r);
    r = run_tool((const char *[]){"info", run, NULL});
    ck_assert_msg(r.code == 0 && strstr(r.out, "Step#0"), "%s%s", r.out, r.err);
    result_free(&r);
}
END_TEST

/* The export holds one frame at a time, so the frame itself is what must
 * fit: a field of 65536 x 4096 cells (the reader's largest, declared and
 * never stored) is refused before Python starts, as a .usdc too. */
START_TEST(export_refuses_a_frame_larger_than_memory_holds)
{
    const char *scene = scene_with("s.json", "");
    const char *run = real_run(scene, "wide.h5");
    hid_t f = H5Fopen(run, H5F_ACC_RDWR, H5P_DEFAULT);
    ck_assert_int_ge(f, 0);
    ck_assert_int_ge(H5Ldelete(f, "fields/combined", H5P_DEFAULT), 0);
    hsize_t dims[3] = {3, 4096, 65536}, chunk[3] = {1, 4096, 65536};
    hid_t sp = H5Screate_simple(3, dims, NULL), dcpl = H5Pcreate(H5P_DATASET_CREATE);
    ck_assert_int_ge(H5Pset_chunk(dcpl, 3, chunk), 0);
    hid_t d = H5Dcreate2(f, "fields/combined", H5T_IEEE_F32LE, sp, H5P_DEFAULT, dcpl, H5P_DEFAULT);
    ck_assert_int_ge(d, 0);
    hsize_t two = 2;
    hid_t asp = H5Screate_simple(1, &two, NULL);
    const double dx[2] = {1e-3, 1e-3}, origin[2] = {0, 0};
    hid_t a = H5Acreate2(d, "dx", H5T_NATIVE_DOUBLE, asp, H5P_DEFAULT, H5P_DEFAULT);
    ck_assert_int_ge(H5Awrite(a, H5T_NATIVE_DOUBLE, dx), 0);
    H5Aclose(a);
    a = H5Acreate2(d, "origin", H5T_NATIVE_DOUBLE, asp, H5P_DEFAULT, H5P_DEFAULT);
    ck_assert_int_ge(H5Awrite(a, H5T_NATIVE_DOUBLE, origin), 0);
    H5Aclose(a);
    H5Sclose(asp);
    H5Dclose(d);
    H5Pclose(dcpl);
    H5Sclose(sp);
    H5Fclose(f);
    result r = run_tool((const char *[]){"export", run, "--usd", tmp_path("o.usdc"), NULL});
    ASSERT_REFUSED(r, 2, "one frame of a 65536 x 4096 field would need about");
    ck_assert_msg(strstr(r.err, "of memory") != NULL, "%s", r.err);
    result_free(&r);
    struct stat sb;
    ck_assert_int_ne(stat(tmp_path("o.usdc"), &sb), 0);
}
END_TEST

/* ---- terminal-safe output, and a resume of another grid ---- */

static void set_string_attr(hid_t loc, const char *name, const char *v)
{
    if (H5Aexists(loc, name) > 0)
        H5Adelete(loc, name);
    hid_t t = H5Tcopy(H5T_C_S1);
    H5Tset_size(t, H5T_VARIABLE);
    hid_t sp = H5Screate(H5S_SCALAR);
    hid_t a = H5Acreate2(loc, name, t, sp, H5P_DEFAULT, H5P_DEFAULT);
    ck_assert_int_ge(H5Awrite(a, t, &v), 0);
    H5Aclose(a);
    H5Sclose(sp);
    H5Tclose(t);
}

static void assert_no_control(const char *text, const char *escaped)
{
    for (const unsigned char *p = (const unsigned char *)text; *p; ++p)
        ck_assert_msg(*p >= 0x20 || *p == '\n' || *p == '\t', "raw control byte 0x%02x in: %s", *p,
                      text);
    ck_assert_msg(strstr(text, escaped) != NULL, "\"%s\" not in: %s", escaped, text);
}

START_TEST(strings_from_a_file_reach_the_terminal_escaped)
{
    const char *scene = scene_with("s.json", "");
    const char *run = real_run(scene, "run.h5");
    hid_t f = H5Fopen(run, H5F_ACC_RDWR, H5P_DEFAULT);
    ck_assert_int_ge(f, 0);
    set_string_attr(f, "library_version", "0.0\x1b]0;owned\x07\x1b[2J");
    H5Fclose(f);
    /* --resume names the version that differs: escaped */
    result r = run_tool((const char *[]){"run", scene, "--frames", "6", "--resume", run, NULL});
    ck_assert_msg(r.code == 2, "exit %d: %s", r.code, r.err);
    assert_no_control(r.err, "0.0\\x1b]0;owned\\x07\\x1b[2J");
    result_free(&r);
    /* a C1 control in UTF-8 (U+009B, a CSI to a terminal that takes C1)
     * and bytes that are not UTF-8; well-formed text (U+00E9) is kept */
    f = H5Fopen(run, H5F_ACC_RDWR, H5P_DEFAULT);
    ck_assert_int_ge(f, 0);
    set_string_attr(f, "library_version",
                    "0.0\xc2\x9b"
                    "2J\xff\xfe\xc3\xa9\xe2\x82");
    H5Fclose(f);
    r = run_tool((const char *[]){"run", scene, "--frames", "6", "--resume", run, NULL});
    ck_assert_msg(r.code == 2, "exit %d: %s", r.code, r.err);
    assert_no_control(r.err, "0.0\\u009b2J\\xff\\xfe\xc3\xa9\\xe2\\x82");
    ck_assert_ptr_null(strstr(r.err, "\xc2\x9b"));
    result_free(&r);
    /* info's --set lines come from the file's scene text */
    f = H5Fopen(run, H5F_ACC_RDWR, H5P_DEFAULT);
    ck_assert_int_ge(f, 0);
    set_string_attr(f, "scene", "{\"name\": \"x\", \"overrides\": [\"a=\\u001b[2J\"]}");
    H5Fclose(f);
    r = run_tool((const char *[]){"info", run, NULL});
    ck_assert_msg(r.code == 0, "exit %d: %s", r.code, r.err);
    assert_no_control(r.out, "--set     a=\\x1b[2J");
    result_free(&r);
}
END_TEST

/* A scene's name is printed by check and run and is the viewer's title
 * and its log's header line: a control character in it is refused by
 * both, in the scene file and through --set. */
START_TEST(a_scene_name_with_control_characters_is_refused)
{
    /* in the scene file (the one scene_with makes, its name edited) */
    const char *scene = scene_with("s.json", "");
    char *text = ms_test_slurp(scene);
    ck_assert_ptr_nonnull(text);
    char *at = strstr(text, "\"untrusted\"");
    ck_assert_ptr_nonnull(at);
    char edited[4096];
    snprintf(edited, sizeof edited, "%.*s\"a\\u001b]0;owned\\u0007\"%s", (int)(at - text), text,
             at + strlen("\"untrusted\""));
    free(text);
    write_text(scene, edited);
    check_and_run_refuse(scene, "name holds the control character 0x1b at byte 1");
    /* through --set */
    scene = scene_with("t.json", "");
    result r = run_tool((const char *[]){"check", scene, "--set", "name=\"x\\ny\"", NULL});
    ASSERT_REFUSED(r, 2, "name holds the control character 0x0a at byte 1");
    result_free(&r);
    r = run_tool((const char *[]){"run", scene, "--no-out", "--set", "name=\"x\\ty\"", NULL});
    ASSERT_REFUSED(r, 2, "name holds the control character 0x09 at byte 1");
    result_free(&r);
}
END_TEST

START_TEST(a_resume_of_another_grid_says_what_differs)
{
    const char *scene = scene_with("s.json", "");
    const char *run = real_run(scene, "run.h5");
    /* the combined field transposed: 48 x 64 cells where the scene makes
     * 64 x 48 (same values, same attributes) */
    hid_t f = H5Fopen(run, H5F_ACC_RDWR, H5P_DEFAULT);
    ck_assert_int_ge(f, 0);
    hid_t d = H5Dopen2(f, "fields/combined", H5P_DEFAULT);
    float *v = malloc(3 * 48 * 64 * sizeof *v);
    ck_assert_int_ge(H5Dread(d, H5T_NATIVE_FLOAT, H5S_ALL, H5S_ALL, H5P_DEFAULT, v), 0);
    H5Dclose(d);
    ck_assert_int_ge(H5Ldelete(f, "fields/combined", H5P_DEFAULT), 0);
    hsize_t dims[3] = {3, 64, 48};
    hid_t sp = H5Screate_simple(3, dims, NULL);
    d = H5Dcreate2(f, "fields/combined", H5T_IEEE_F32LE, sp, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
    ck_assert_int_ge(H5Dwrite(d, H5T_NATIVE_FLOAT, H5S_ALL, H5S_ALL, H5P_DEFAULT, v), 0);
    hsize_t two = 2;
    hid_t asp = H5Screate_simple(1, &two, NULL);
    const double dx[2] = {1.2 / 64, 0.9 / 48}, origin[2] = {0, 0};
    hid_t a = H5Acreate2(d, "dx", H5T_NATIVE_DOUBLE, asp, H5P_DEFAULT, H5P_DEFAULT);
    H5Awrite(a, H5T_NATIVE_DOUBLE, dx);
    H5Aclose(a);
    a = H5Acreate2(d, "origin", H5T_NATIVE_DOUBLE, asp, H5P_DEFAULT, H5P_DEFAULT);
    H5Awrite(a, H5T_NATIVE_DOUBLE, origin);
    H5Aclose(a);
    H5Sclose(asp);
    H5Dclose(d);
    H5Sclose(sp);
    H5Fclose(f);
    free(v);
    result r = run_tool((const char *[]){"run", scene, "--frames", "6", "--resume", run, NULL});
    ASSERT_REFUSED(r, 2, "combined field is 48 x 64 cells, this scene's sim makes 64 x 48");
    ck_assert_ptr_null(strstr(r.err, "another build"));
    result_free(&r);
}
END_TEST

static Suite *untrusted_suite(void)
{
    Suite *s = suite_create("untrusted");
    TCase *tc = tcase_create("paths");
    tcase_add_checked_fixture(tc, setup, teardown);
    tcase_set_timeout(tc, 120);
    tcase_add_test(tc, fifos_devices_and_a_cubemap_without_faces_are_refused_by_check_and_run);
    tcase_add_test(tc, a_run_file_naming_other_files_is_refused_before_they_are_opened);
    tcase_add_test(tc, check_refuses_the_cubemap_faces_run_cannot_decode);
    tcase_add_test(tc, a_scene_reads_pngs_by_parent_and_absolute_paths);
    tcase_add_test(tc, drops_and_rain_of_unbounded_work_are_refused_by_check_and_run);
    suite_add_tcase(s, tc);
    tc = tcase_create("files");
    tcase_add_checked_fixture(tc, setup, teardown);
    tcase_set_timeout(tc, 120);
    tcase_add_test(tc, export_refuses_what_info_refuses_in_the_same_sentence);
    tcase_add_test(tc, export_refuses_a_sparse_file_claiming_more_than_memory_holds);
    tcase_add_test(tc, export_refuses_a_frame_larger_than_memory_holds);
    tcase_add_test(tc, strings_from_a_file_reach_the_terminal_escaped);
    tcase_add_test(tc, a_resume_of_another_grid_says_what_differs);
    tcase_add_test(tc, a_scene_name_with_control_characters_is_refused);
    suite_add_tcase(s, tc);
    return s;
}

int main(void)
{
    return ms_test_run(untrusted_suite());
}
