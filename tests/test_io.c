/* io: the HDF5 run file (writer and reader, bit-for-bit round trips on a
 * non-square grid), crash safety (SIGKILL mid-run, a full disk, the file
 * size limit), the XDMF sidecar, refusals, and the shaded-relief PNG. */
#define _GNU_SOURCE /* unshare, CLONE_NEWNS for the full-disk case */
#include <check.h>
#include <dirent.h>
#include <errno.h>
#include <fcntl.h>
#include <png.h>
#include <sched.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/mount.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include "io/io_internal.h"
#include "modesplit/modesplit.h"
#include "support.h"

/* ---- helpers ---------------------------------------------------------- */

static char tmp_dir[256];

static void make_tmp_dir(void)
{
    ck_assert_int_eq(ms_test_tmp_dir(tmp_dir, sizeof tmp_dir, "ms_io"), 0);
}

/* The directory and what is in it (the legacy sidecar's run.xdmf2.d too). */
static void remove_tmp_dir(void)
{
    ms_test_remove_tree(tmp_dir);
}

static char *tmp_path(const char *name)
{
    static char p[4][512];
    static int k;
    k = (k + 1) % 4;
    snprintf(p[k], sizeof p[k], "%s/%s", tmp_dir, name);
    return p[k];
}

static int count_of(const char *hay, const char *needle)
{
    int n = 0;
    for (const char *p = strstr(hay, needle); p; p = strstr(p + 1, needle))
        ++n;
    return n;
}

/* A non-square layout: combined and surface on a 37 x 23 wave grid,
 * volume on a 9 x 6 SPH grid, particles. */
static ms_writer_layout test_layout(unsigned fields)
{
    ms_writer_layout l = {0};
    l.fields = fields;
    for (int i = 0; i < 2; ++i)
        l.grid[i] =
            (ms_grid){.nx = 37, .ny = 23, .dx = 0.01f, .dy = 0.02f, .origin = {-0.185f, 0.5f}};
    l.grid[MS_IO_VOLUME] =
        (ms_grid){.nx = 9, .ny = 6, .dx = 0.04f, .dy = 0.08f, .origin = {-0.18f, 0.48f}};
    l.scene_text = "{\"name\": \"test scene\", \"frame_dt\": 0.02}";
    l.scene_name = "test scene";
    l.frame_dt = 0.02;
    l.output_every = 2;
    l.deflate = 1;
    return l;
}

/* The data of frame k, a pure function of k (so a reader can check it):
 * smooth waves in even cells, arbitrary bit patterns (NaN payloads,
 * infinities, denormals) in odd ones; k % 4 particles... */
typedef struct frame_buf {
    float *field[MS_IO_NFIELDS];
    float *p[6];
    int n;
    double t;
} frame_buf;

static uint32_t mix(uint32_t x)
{
    x ^= x >> 16;
    x *= 0x7feb352dU;
    x ^= x >> 15;
    x *= 0x846ca68bU;
    x ^= x >> 16;
    return x;
}

static void frame_fill(frame_buf *b, const ms_writer_layout *l, long k)
{
    for (int s = 0; s < MS_IO_NFIELDS; ++s) {
        const ms_grid *g = &l->grid[s];
        size_t n = (size_t)g->nx * g->ny;
        b->field[s] = realloc(b->field[s], n * sizeof(float));
        for (size_t i = 0; i < n; ++i) {
            uint32_t bits = mix((uint32_t)(k * 7919 + s * 104729 + (long)i));
            if (i % 2 == 0) {
                b->field[s][i] =
                    0.01f * sinf(0.3f * (float)(i % (size_t)g->nx) + 0.1f * (float)k) + 0.3f;
            } else {
                memcpy(&b->field[s][i], &bits, 4);
            }
        }
    }
    b->n = (int)((k * 37) % 50); /* 0 .. 49, with a 0 at k = 0 */
    for (int c = 0; c < 6; ++c) {
        b->p[c] = realloc(b->p[c], (size_t)(b->n + 1) * sizeof(float));
        for (int i = 0; i < b->n; ++i)
            b->p[c][i] = (float)(c + 1) * 0.125f + (float)i * 1e-3f + (float)k;
    }
    b->t = 0.04 * (double)(k + 1) + 1e-17;
}

static void frame_free(frame_buf *b)
{
    for (int s = 0; s < MS_IO_NFIELDS; ++s)
        free(b->field[s]);
    for (int c = 0; c < 6; ++c)
        free(b->p[c]);
    memset(b, 0, sizeof *b);
}

static ms_writer_data frame_data(const frame_buf *b)
{
    ms_writer_data d = {0};
    d.time = b->t;
    for (int s = 0; s < MS_IO_NFIELDS; ++s)
        d.field[s] = b->field[s];
    d.particles = b->n;
    for (int c = 0; c < 3; ++c) {
        d.pos[c] = b->p[c];
        d.vel[c] = b->p[c + 3];
    }
    return d;
}

static void write_frames(ms_writer *w, const ms_writer_layout *l, long from, long to)
{
    frame_buf b = {0};
    for (long k = from; k < to; ++k) {
        frame_fill(&b, l, k);
        ms_writer_data d = frame_data(&b);
        ck_assert_msg(ms_writer_write(w, &d) == MS_OK, "%s", ms_last_error());
    }
    frame_free(&b);
}

/* Every frame of the file equals frame_fill's, bit for bit. */
static void check_frames(ms_reader *r, const ms_writer_layout *l, long frames)
{
    ck_assert_int_eq(ms_reader_frames(r), frames);
    frame_buf b = {0};
    float *got = malloc(37 * 23 * sizeof(float));
    float *pg[6];
    for (int c = 0; c < 6; ++c)
        pg[c] = malloc(64 * sizeof(float));
    for (long k = 0; k < frames; ++k) {
        frame_fill(&b, l, k);
        double t;
        ck_assert_int_eq(ms_reader_time(r, k, &t), MS_OK);
        ck_assert_mem_eq(&t, &b.t, sizeof t);
        for (int s = 0; s < MS_IO_NFIELDS; ++s) {
            if (!(l->fields & (1u << s)))
                continue;
            size_t n = (size_t)l->grid[s].nx * l->grid[s].ny;
            ck_assert_msg(ms_reader_read_field(r, 1u << s, k, got, 37 * 23) == MS_OK, "%s",
                          ms_last_error());
            ck_assert_msg(memcmp(got, b.field[s], n * sizeof(float)) == 0,
                          "field %s frame %ld differs", ms_io_field_names[s], k);
        }
        if (l->fields & MS_FIELD_PARTICLES) {
            int n = -1;
            ck_assert_int_eq(ms_reader_particle_count(r, k, &n), MS_OK);
            ck_assert_int_eq(n, b.n);
            ck_assert_int_eq(ms_reader_read_particles(r, k, 64, pg, pg + 3), MS_OK);
            for (int c = 0; c < 6; ++c)
                ck_assert_mem_eq(pg[c], b.p[c], (size_t)n * sizeof(float));
        }
    }
    for (int c = 0; c < 6; ++c)
        free(pg[c]);
    free(got);
    frame_free(&b);
}

/* ---- round trip --------------------------------------------------------- */

START_TEST(round_trip_is_bit_for_bit_on_a_non_square_grid)
{
    make_tmp_dir();
    ms_writer_layout l = test_layout(MS_IO_ALL_FIELDS);
    ms_writer *w;
    ck_assert_msg(ms_writer_open_layout(tmp_path("run.h5"), &l, &w) == MS_OK, "%s",
                  ms_last_error());
    write_frames(w, &l, 0, 12);
    ck_assert_int_eq(ms_writer_frames(w), 12);
    ck_assert_str_eq(ms_writer_xdmf_path(w), tmp_path("run.xmf"));
    ck_assert_int_eq(ms_writer_close(w), MS_OK);

    ms_reader *r;
    ck_assert_msg(ms_reader_open(tmp_path("run.h5"), &r) == MS_OK, "%s", ms_last_error());
    ck_assert_uint_eq(ms_reader_fields(r), MS_IO_ALL_FIELDS);
    ck_assert_int_eq(ms_reader_format_version(r), MS_FILE_FORMAT_VERSION);
    ck_assert_str_eq(ms_reader_library_version(r), ms_version());
    ck_assert_str_eq(ms_reader_scene(r), l.scene_text);
    ck_assert_str_eq(ms_reader_scene_name(r), "test scene");
    ck_assert_double_eq(ms_reader_frame_dt(r), 0.02);
    ck_assert_int_eq(ms_reader_output_every(r), 2);
    for (int s = 0; s < MS_IO_NFIELDS; ++s) {
        ms_grid g;
        ck_assert_int_eq(ms_reader_field_grid(r, 1u << s, &g), MS_OK);
        ck_assert_int_eq(g.nx, l.grid[s].nx);
        ck_assert_int_eq(g.ny, l.grid[s].ny);
        ck_assert_float_eq(g.dx, l.grid[s].dx);
        ck_assert_float_eq(g.dy, l.grid[s].dy);
        ck_assert_float_eq(g.origin[0], l.grid[s].origin[0]);
        ck_assert_float_eq(g.origin[1], l.grid[s].origin[1]);
        uint64_t stored = 0, raw = 0;
        ck_assert_int_eq(ms_reader_field_bytes(r, 1u << s, &stored, &raw), MS_OK);
        ck_assert_uint_eq(raw, 12u * (uint64_t)g.nx * g.ny * 4u);
        ck_assert_uint_gt(stored, 0);
    }
    check_frames(r, &l, 12);
    ms_reader_close(r);
    MS_ASSERT_H5DUMP_READS(tmp_path("run.h5"));
    remove_tmp_dir();
}
END_TEST

/* output.deflate: level 0 stores the fields as they are (stored bytes =
 * raw bytes, no filters), level 9 compresses; both read back bit for bit. */
START_TEST(deflate_levels_round_trip_and_level_0_stores_raw)
{
    make_tmp_dir();
    static const int levels[] = {0, 9};
    for (int k = 0; k < 2; ++k) {
        ms_writer_layout l = test_layout(MS_IO_ALL_FIELDS);
        l.deflate = levels[k];
        ms_writer *w;
        ck_assert_msg(ms_writer_open_layout(tmp_path("d.h5"), &l, &w) == MS_OK, "%s",
                      ms_last_error());
        write_frames(w, &l, 0, 4);
        ck_assert_int_eq(ms_writer_close(w), MS_OK);
        ms_reader *r;
        ck_assert_int_eq(ms_reader_open(tmp_path("d.h5"), &r), MS_OK);
        for (int s = 0; s < MS_IO_NFIELDS; ++s) {
            uint64_t stored = 0, raw = 0;
            ck_assert_int_eq(ms_reader_field_bytes(r, 1u << s, &stored, &raw), MS_OK);
            if (levels[k] == 0)
                ck_assert_uint_eq(stored, raw);
        }
        check_frames(r, &l, 4);
        ms_reader_close(r);
        MS_ASSERT_H5DUMP_READS(tmp_path("d.h5"));
        remove(tmp_path("d.h5"));
        remove(tmp_path("d.xmf"));
    }
    remove_tmp_dir();
}
END_TEST

START_TEST(only_the_fields_asked_for_are_written)
{
    make_tmp_dir();
    ms_writer_layout l = test_layout(MS_FIELD_VOLUME);
    ms_writer *w;
    ck_assert_int_eq(ms_writer_open_layout(tmp_path("v.h5"), &l, &w), MS_OK);
    write_frames(w, &l, 0, 3);
    ck_assert_int_eq(ms_writer_close(w), MS_OK);
    ms_reader *r;
    ck_assert_int_eq(ms_reader_open(tmp_path("v.h5"), &r), MS_OK);
    ck_assert_uint_eq(ms_reader_fields(r), MS_FIELD_VOLUME);
    check_frames(r, &l, 3);
    int n = -1;
    ck_assert_int_eq(ms_reader_particle_count(r, 0, &n), MS_OK);
    ck_assert_int_eq(n, 0);
    float buf[64];
    MS_ASSERT_REFUSED(ms_reader_read_field(r, MS_FIELD_COMBINED, 0, buf, 64),
                      MS_ERR_INVALID_ARGUMENT, "no field combined");
    ms_reader_close(r);
    char *x = ms_test_slurp(tmp_path("v.xmf"));
    ck_assert_msg(x[0], "missing or empty");
    ck_assert_int_eq(count_of(x, "/fields/combined"), 0);
    ck_assert_int_eq(count_of(x, "Polyvertex"), 0);
    ck_assert_int_eq(count_of(x, "/fields/volume"), 3);
    free(x);
    remove_tmp_dir();
}
END_TEST

START_TEST(a_scene_text_over_64_kib_round_trips)
{
    make_tmp_dir();
    size_t n = 200000;
    char *scene = malloc(n + 1);
    for (size_t i = 0; i < n; ++i)
        scene[i] = (char)('a' + i % 26);
    scene[n] = '\0';
    ms_writer_layout l = test_layout(MS_FIELD_COMBINED);
    l.scene_text = scene;
    ms_writer *w;
    ck_assert_msg(ms_writer_open_layout(tmp_path("big.h5"), &l, &w) == MS_OK, "%s",
                  ms_last_error());
    write_frames(w, &l, 0, 1);
    ck_assert_int_eq(ms_writer_close(w), MS_OK);
    ms_reader *r;
    ck_assert_int_eq(ms_reader_open(tmp_path("big.h5"), &r), MS_OK);
    ck_assert_str_eq(ms_reader_scene(r), scene);
    ms_reader_close(r);
    MS_ASSERT_H5DUMP_READS(tmp_path("big.h5"));
    free(scene);
    remove_tmp_dir();
}
END_TEST

/* ---- XDMF --------------------------------------------------------------- */

START_TEST(xdmf_lists_every_frame_with_z_y_x_axis_order)
{
    make_tmp_dir();
    ms_writer_layout l = test_layout(MS_IO_ALL_FIELDS);
    ms_writer *w;
    ck_assert_int_eq(ms_writer_open_layout(tmp_path("a b&c.h5"), &l, &w), MS_OK);
    ck_assert_str_eq(ms_writer_xdmf_legacy_path(w), tmp_path("a b&c.xdmf2"));
    /* no frame yet: no empty temporal collection (it crashes the legacy
     * reader); the legacy file lists the grids without data */
    char *x0 = ms_test_slurp(tmp_path("a b&c.xmf"));
    ck_assert_ptr_nonnull(strstr(x0, "</Xdmf>\n"));
    ck_assert_int_eq(count_of(x0, "Temporal"), 0);
    free(x0);
    x0 = ms_test_slurp(tmp_path("a b&c.xdmf2"));
    ck_assert_int_eq(count_of(x0, "Temporal"), 0);
    ck_assert_int_eq(count_of(x0, "3DCoRectMesh"), 2);
    ck_assert_int_eq(count_of(x0, "<xi:include"), 0);
    free(x0);
    write_frames(w, &l, 0, 5);
    /* valid after every frame, before close */
    char *x = ms_test_slurp(tmp_path("a b&c.xmf"));
    ck_assert_int_eq(ms_writer_close(w), MS_OK);
    char *y = ms_test_slurp(tmp_path("a b&c.xmf"));
    ck_assert_str_eq(x, y);
    free(y);
    size_t len = strlen(x);
    ck_assert_str_eq(x + len - strlen("</Xdmf>\n"), "</Xdmf>\n");
    ck_assert_int_eq(count_of(x, "<Time Value="), 5);
    /* the file name is escaped; 37 x 23 points, dimensions slowest first */
    ck_assert_ptr_nonnull(strstr(x, "a b&amp;c.h5:/fields/combined"));
    ck_assert_int_eq(count_of(x, "TopologyType=\"3DCoRectMesh\" Dimensions=\"1 23 37\""), 5);
    ck_assert_int_eq(count_of(x, "TopologyType=\"3DCoRectMesh\" Dimensions=\"1 6 9\""), 5);
    /* combined and surface share one grid, volume has its own; the block
     * names are the fields, never the frame */
    ck_assert_int_eq(count_of(x, "TopologyType=\"3DCoRectMesh\""), 2 * 5);
    ck_assert_int_eq(count_of(x, "<Grid Name=\"combined surface\""), 5);
    ck_assert_int_eq(count_of(x, "<Grid Name=\"volume\""), 5);
    /* Xdmf3 selections: frame 3 of a dataset of (at least) 4 frames */
    ck_assert_ptr_nonnull(strstr(x, "c.h5:/fields/surface|3 0 0:1 1 1:1 23 37:4 23 37<"));
    ck_assert_int_eq(count_of(x, "HyperSlab"), 0);
    /* origin (z y x) at the first cell centre, spacing (z dy dx) */
    ck_assert_ptr_nonnull(strstr(x, "Format=\"XML\">1 0.0199999996 0.00999999978<"));
    /* particles of frame 1 (37 of them) as [n][3] arrays with ids, none in frame 0 */
    ck_assert_ptr_nonnull(strstr(x, "NumberOfElements=\"37\""));
    ck_assert_ptr_nonnull(strstr(x, "a b&amp;c.h5:/particles/1/velocity"));
    ck_assert_ptr_nonnull(strstr(x, "a b&amp;c.h5:/Step#1/id"));
    ck_assert_ptr_null(strstr(x, "/Step#0/"));
    ck_assert_int_eq(count_of(x, "<Grid"), count_of(x, "</Grid>"));
    free(x);

    /* the legacy flavour: one temporal file per grid, included by run.xdmf2 */
    x = ms_test_slurp(tmp_path("a b&c.xdmf2"));
    ck_assert_int_eq(count_of(x, "<xi:include href=\"a b&amp;c.xdmf2.d/"), 3);
    ck_assert_int_eq(count_of(x, "3DCoRectMesh"), 0);
    free(x);
    x = ms_test_slurp(tmp_path("a b&c.xdmf2.d/combined.xml"));
    ck_assert_msg(x[0], "missing or empty");
    ck_assert_int_eq(count_of(x, "CollectionType=\"Temporal\""), 1);
    ck_assert_int_eq(count_of(x, "<Time Value="), 5);
    ck_assert_int_eq(count_of(x, "ItemType=\"HyperSlab\" Dimensions=\"1 23 37\""), 2 * 5);
    ck_assert_ptr_nonnull(strstr(x, ">3 0 0 1 1 1 1 23 37<"));
    ck_assert_ptr_nonnull(strstr(x, "Dimensions=\"4 23 37\""));
    ck_assert_int_eq(count_of(x, "<Grid"), count_of(x, "</Grid>"));
    free(x);
    x = ms_test_slurp(tmp_path("a b&c.xdmf2.d/particles.xml"));
    ck_assert_int_eq(count_of(x, "<Time Value="), 4); /* frame 0 has none */
    free(x);
    x = ms_test_slurp(tmp_path("a b&c.xdmf2.d/volume.xml"));
    ck_assert_int_eq(count_of(x, "<Grid Name=\"volume\" GridType=\"Uniform\""), 5);
    free(x);
    remove_tmp_dir();
}
END_TEST

/* Particles carry ids (their insertion index) and [n][3] copies of
 * positions and velocities that equal the H5Part arrays. */
START_TEST(particles_have_ids_and_xyz_arrays_equal_to_h5part)
{
    make_tmp_dir();
    ms_writer_layout l = test_layout(MS_IO_ALL_FIELDS);
    ms_writer *w;
    ck_assert_int_eq(ms_writer_open_layout(tmp_path("p.h5"), &l, &w), MS_OK);
    write_frames(w, &l, 0, 3);
    ck_assert_int_eq(ms_writer_close(w), MS_OK);
    hid_t f = H5Fopen(tmp_path("p.h5"), H5F_ACC_RDONLY, H5P_DEFAULT);
    ck_assert_int_ge(f, 0);
    int64_t version = 0;
    ck_assert_int_ge(ms_h5_read_int64(f, "format_version", &version), 0);
    ck_assert_int_eq(version, 2);
    for (long k = 1; k < 3; ++k) {
        char name[64];
        snprintf(name, sizeof name, "/Step#%ld/id", k);
        hid_t d = H5Dopen2(f, name, H5P_DEFAULT);
        ck_assert_int_ge(d, 0);
        int n = (int)H5Sget_simple_extent_npoints(H5Dget_space(d));
        ck_assert_int_gt(n, 0);
        int *id = malloc((size_t)n * sizeof *id);
        float *xyz = malloc((size_t)n * 3 * sizeof *xyz), *a = malloc((size_t)n * sizeof *a);
        ck_assert_int_ge(H5Dread(d, H5T_NATIVE_INT, H5S_ALL, H5S_ALL, H5P_DEFAULT, id), 0);
        H5Dclose(d);
        for (int i = 0; i < n; ++i)
            ck_assert_int_eq(id[i], i);
        static const char *const comp[2][3] = {{"x", "y", "z"}, {"vx", "vy", "vz"}};
        static const char *const vec[2] = {"position", "velocity"};
        for (int v = 0; v < 2; ++v) {
            snprintf(name, sizeof name, "/particles/%ld/%s", k, vec[v]);
            d = H5Dopen2(f, name, H5P_DEFAULT);
            ck_assert_int_ge(d, 0);
            ck_assert_int_ge(H5Dread(d, H5T_NATIVE_FLOAT, H5S_ALL, H5S_ALL, H5P_DEFAULT, xyz), 0);
            H5Dclose(d);
            for (int c = 0; c < 3; ++c) {
                snprintf(name, sizeof name, "/Step#%ld/%s", k, comp[v][c]);
                d = H5Dopen2(f, name, H5P_DEFAULT);
                ck_assert_int_ge(H5Dread(d, H5T_NATIVE_FLOAT, H5S_ALL, H5S_ALL, H5P_DEFAULT, a), 0);
                H5Dclose(d);
                for (int i = 0; i < n; ++i)
                    ck_assert_msg(memcmp(&xyz[3 * i + c], &a[i], sizeof *a) == 0,
                                  "frame %ld %s[%d][%d] differs", k, vec[v], i, c);
            }
        }
        free(id);
        free(xyz);
        free(a);
    }
    H5Fclose(f);
    remove_tmp_dir();
}
END_TEST

/* The superblock format eoa_guard.c patches is the one HDF5 writes, and
 * its checksum is HDF5's: a closed run file's superblock verifies. */
START_TEST(superblock_checksum_matches_hdf5)
{
    make_tmp_dir();
    ms_writer_layout l = test_layout(MS_FIELD_COMBINED);
    ms_writer *w;
    ck_assert_int_eq(ms_writer_open_layout(tmp_path("sb.h5"), &l, &w), MS_OK);
    write_frames(w, &l, 0, 3);
    ck_assert_int_eq(ms_writer_close(w), MS_OK);
    unsigned char sb[48];
    FILE *f = fopen(tmp_path("sb.h5"), "rb");
    ck_assert_int_eq(fread(sb, 1, 48, f), 48);
    fclose(f);
    ck_assert(ms_h5_superblock_ok(sb));
    sb[30] ^= 1;
    ck_assert(!ms_h5_superblock_ok(sb));
    /* lookup3's published test value: hashlittle("Four score and seven years ago", 30, 0) */
    ck_assert_uint_eq(ms_lookup3("Four score and seven years ago", 30, 0), 0x17770551u);
    remove_tmp_dir();
}
END_TEST

START_TEST(xdmf_path_replaces_h5_or_appends)
{
    char *p = ms_xdmf_path_for("dir/run.h5");
    ck_assert_str_eq(p, "dir/run.xmf");
    ms_free(p);
    p = ms_xdmf_path_for("run.hdf5");
    ck_assert_str_eq(p, "run.xmf");
    ms_free(p);
    p = ms_xdmf_path_for("out.dat");
    ck_assert_str_eq(p, "out.dat.xmf");
    ms_free(p);
}
END_TEST

/* ---- crash safety ------------------------------------------------------- */

/* A child writes frames until killed, reporting each committed frame on a
 * pipe; the parent kills it with SIGKILL after `after` frames plus a
 * jitter, then reads the file. */
/* A stand-in checkpoint blob of frame k: its size and bytes depend on k. */
static size_t ckpt_bytes(long k)
{
    return 150000 + (size_t)(k % 5) * 40000;
}

static unsigned char *ckpt_fill(unsigned char *buf, long k)
{
    buf = realloc(buf, ckpt_bytes(k));
    for (size_t i = 0; i < ckpt_bytes(k); ++i)
        buf[i] = (unsigned char)mix((uint32_t)(k * 31 + (long)i));
    return buf;
}

static void kill_mid_run(long after, int jitter_us, int checkpoints)
{
    ms_writer_layout l = test_layout(MS_IO_ALL_FIELDS);
    l.checkpoint_every = checkpoints; /* the slots made with the layout */
    int fds[2];
    ck_assert_int_eq(pipe(fds), 0);
    pid_t pid = fork();
    ck_assert_int_ge(pid, 0);
    if (pid == 0) {
        close(fds[0]);
        ms_writer *w;
        if (ms_writer_open_layout(tmp_path("killed.h5"), &l, &w) != MS_OK)
            _exit(3);
        frame_buf b = {0};
        unsigned char *blob = NULL;
        for (long k = 0;; ++k) {
            frame_fill(&b, &l, k);
            ms_writer_data d = frame_data(&b);
            if (checkpoints) {
                d.checkpoint = blob = ckpt_fill(blob, k);
                d.checkpoint_bytes = ckpt_bytes(k);
            }
            if (ms_writer_write(w, &d) != MS_OK)
                _exit(4);
            long done = k + 1;
            if (write(fds[1], &done, sizeof done) != sizeof done)
                _exit(5);
        }
    }
    close(fds[1]);
    long done = 0, v;
    while (done < after && read(fds[0], &v, sizeof v) == sizeof v)
        done = v;
    ck_assert_int_eq(done, after);
    struct timespec ts = {0, (long)jitter_us * 1000};
    nanosleep(&ts, NULL);
    kill(pid, SIGKILL);
    /* every frame reported before the kill is committed */
    while (read(fds[0], &v, sizeof v) == sizeof v)
        done = v;
    close(fds[0]);
    int status;
    waitpid(pid, &status, 0);
    ck_assert(WIFSIGNALED(status) && WTERMSIG(status) == SIGKILL);
    /* the writer's helper finishes the flush it was handed (h5_atomic.c) */
    ck_assert(ms_test_wait_unused(tmp_path("killed.h5"), 10));

    MS_ASSERT_H5DUMP_READS(tmp_path("killed.h5"));
    ms_reader *r;
    ck_assert_msg(ms_reader_open(tmp_path("killed.h5"), &r) == MS_OK, "%s", ms_last_error());
    long frames = ms_reader_frames(r);
    /* all reported frames, and at most the one in hand when killed */
    ck_assert_int_ge(frames, done);
    ck_assert_int_le(frames, done + 1);
    check_frames(r, &l, frames);
    if (checkpoints) {
        /* the newest checkpoint of a committed frame is whole: the last
         * frame's or, when the kill tore that one, the frame before */
        long at[2];
        int n = ms_reader_checkpoints(r, at);
        ck_assert_int_ge(n, frames >= 2 ? 1 : 0);
        for (int i = 0; i < n; ++i)
            ck_assert_int_lt(at[i], frames);
        ck_assert(n == 0 || at[0] >= frames - 2);
        int whole = 0;
        for (int i = 0; i < n; ++i) {
            size_t bytes;
            ck_assert_int_eq(ms_reader_checkpoint_size(r, i, &bytes), MS_OK);
            unsigned char *got = malloc(bytes), *want = ckpt_fill(NULL, at[i]);
            whole += bytes == ckpt_bytes(at[i]) &&
                     ms_reader_read_checkpoint(r, i, got, bytes) == MS_OK &&
                     memcmp(got, want, bytes) == 0;
            free(got);
            free(want);
        }
        ck_assert_msg(n == 0 || whole >= 1, "no whole checkpoint among %d", n);
    }
    ms_reader_close(r);
    char *x = ms_test_slurp(tmp_path("killed.xmf"));
    ck_assert_msg(x[0], "missing or empty");
    ck_assert_ptr_nonnull(strstr(x, "</Xdmf>\n"));
    ck_assert_int_ge(count_of(x, "<Time Value="), done);
    free(x);
}

START_TEST(sigkill_mid_run_leaves_every_flushed_frame)
{
    make_tmp_dir();
    /* kill at a spread of moments inside the frame being written */
    const int jitter[] = {0, 37, 150, 400, 1100, 2900};
    for (int i = 0; i < 6; ++i)
        kill_mid_run(3 + 4 * i, jitter[i], 0);
    remove_tmp_dir();
}
END_TEST

/* The same with a checkpoint blob in every frame. */
START_TEST(sigkill_mid_run_leaves_a_whole_checkpoint)
{
    make_tmp_dir();
    const int jitter[] = {0, 60, 250, 700, 1500, 3100};
    for (int i = 0; i < 6; ++i)
        kill_mid_run(2 + 3 * i, jitter[i], 1);
    remove_tmp_dir();
}
END_TEST

/* A kill `at` bytes into (< 0: -at bytes short of the end of) the in-place
 * writes of a frame's flush
 * number `batch` (0: its data, 1: its links, 2: `frames`; lib/io/
 * h5_atomic.c), in a child that has committed `before` frames with
 * particles (the root group's links then in dense storage). Returns 1 when
 * the child died there, 0 when that flush was smaller than `at`.
 * *untouched: the file's committed bytes are those before the flush
 * (<file>.before); *readable: h5dump and the reader read the file, which
 * holds `before` frames bit for bit. */
static int kill_inside_a_flush(int before, int batch, long at, int without_helper, int *untouched,
                               int *readable)
{
    ms_writer_layout l = test_layout(MS_IO_ALL_FIELDS);
    const char *path = tmp_path("torn.h5");
    remove(path);
    pid_t pid = fork();
    ck_assert_int_ge(pid, 0);
    if (pid == 0) {
        ms_writer *w;
        ms_h5_atomic_test_die(0, 0, without_helper); /* the control: no helper at all */
        if (ms_writer_open_layout(path, &l, &w) != MS_OK)
            _exit(3);
        write_frames(w, &l, 0, before);
        ms_h5_atomic_test_die(batch, at, without_helper);
        write_frames(w, &l, before, before + 1);
        _exit(7); /* that flush was smaller than `after` */
    }
    int status;
    waitpid(pid, &status, 0);
    ck_assert_msg(WIFSIGNALED(status) || (WIFEXITED(status) && WEXITSTATUS(status) == 7),
                  "child status %d", status);
    if (!WIFSIGNALED(status))
        return 0;
    ck_assert_int_eq(WTERMSIG(status), SIGKILL);
    ck_assert(ms_test_wait_unused(path, 10));
    size_t n0, n1;
    char *was = ms_test_slurp_n(tmp_path("torn.h5.before"), &n0);
    char *now = ms_test_slurp_n(path, &n1);
    ck_assert_uint_ge(n1, n0);
    *untouched = memcmp(was, now, n0) == 0;
    free(was);
    free(now);
    *readable = 0;
    ms_reader *r;
    if (ms_test_h5dump(path) == 1 && ms_reader_open(path, &r) == MS_OK) {
        if (ms_reader_frames(r) == before) {
            check_frames(r, &l, before);
            *readable = 1;
        }
        ms_reader_close(r);
    }
    return 1;
}

/* The driver's promise, wherever a kill lands in a flush: the in-place
 * writes handed to the helper reach the file whole or not at all, so a
 * kill while they are handed over leaves every committed byte as it was,
 * and the file reads with the frames committed before. The control kills
 * the same flush while the process writes it itself (what HDF5's sec2
 * driver does): committed bytes change under the kill. */
START_TEST(a_kill_inside_a_flush_leaves_the_committed_bytes)
{
    if (ms_test_h5dump("/nonexistent") < 0)
        MS_SKIP("h5dump is not installed (apt-get install hdf5-tools)");
    make_tmp_dir();
    static const long at[] = {1, 40, 300, 1150, 9000, -1, -5, -60, -400};
    int died = 0, changed_control = 0, torn_control = 0;
    for (int batch = 0; batch < 3; ++batch)
        for (size_t i = 0; i < sizeof at / sizeof at[0]; ++i) {
            int untouched = 0, readable = 0;
            if (!kill_inside_a_flush(12, batch, at[i], 0, &untouched, &readable))
                continue;
            ++died;
            ck_assert_msg(untouched, "killed at %ld bytes of flush %d: committed bytes changed",
                          at[i], batch);
            ck_assert_msg(readable, "killed at %ld bytes of flush %d: the file does not read",
                          at[i], batch);
            if (kill_inside_a_flush(12, batch, at[i], 1, &untouched, &readable)) {
                changed_control += !untouched;
                torn_control += !readable;
            }
        }
    ck_assert_int_ge(died, 18);
    /* measured: 14 of 24 control kills changed committed bytes, 10 tore
     * the file (h5dump or the reader refused it, or a frame differed) */
    ck_assert_msg(changed_control >= 6 && torn_control >= 3,
                  "control: %d kills changed committed bytes, %d tore the file", changed_control,
                  torn_control);
    remove_tmp_dir();
}
END_TEST

/* A new run is made as "<path>.part" and renamed over path once its
 * layout's first flush is on disk: a kill while HDF5 writes that first
 * flush (its blocks point into each other and nothing committed guards
 * them) leaves an older run at path whole and readable, not a file that
 * does not open. The kills land at chosen bytes of the new file's writes;
 * the old code (create path itself) fails the first assertion. */
START_TEST(a_kill_before_the_layout_is_on_disk_leaves_the_older_run)
{
    make_tmp_dir();
    ms_writer_layout l = test_layout(MS_IO_ALL_FIELDS);
    char path[512], part[520];
    snprintf(path, sizeof path, "%s", tmp_path("older.h5"));
    snprintf(part, sizeof part, "%s.part", path);
    ms_writer *w;
    ck_assert_int_eq(ms_writer_open_layout(path, &l, &w), MS_OK);
    write_frames(w, &l, 0, 3);
    ck_assert_int_eq(ms_writer_close(w), MS_OK);
    size_t n_old;
    char *old = ms_test_slurp_n(path, &n_old);
    static const size_t at[] = {1, 48, 200, 500, 900, 1400, 2100};
    int died = 0;
    for (size_t i = 0; i < sizeof at / sizeof at[0]; ++i) {
        pid_t pid = fork();
        ck_assert_int_ge(pid, 0);
        if (pid == 0) {
            ms_h5_atomic_test_die_writing(at[i]);
            ms_writer *v;
            _exit(ms_writer_open_layout(path, &l, &v) == MS_OK ? 7 : 3);
        }
        int status;
        waitpid(pid, &status, 0);
        ck_assert_msg(WIFSIGNALED(status) || (WIFEXITED(status) && WEXITSTATUS(status) == 7),
                      "child status %d", status);
        if (!WIFSIGNALED(status))
            continue;
        ++died;
        ck_assert(ms_test_wait_unused(path, 10));
        size_t n_now;
        char *now = ms_test_slurp_n(path, &n_now);
        ck_assert_msg(now && n_now == n_old && memcmp(now, old, n_old) == 0,
                      "killed %zu bytes into the new file: the older run at its path changed",
                      at[i]);
        free(now);
        ms_reader *r;
        ck_assert_int_eq(ms_reader_open(path, &r), MS_OK);
        check_frames(r, &l, 3);
        ms_reader_close(r);
        ck_assert_int_eq(access(part, F_OK), 0);
    }
    ck_assert_int_eq(died, 7); /* all inside the first ~3 kB of the new file */
    /* an open that finishes replaces the older run and leaves no .part */
    ck_assert_int_eq(ms_writer_open_layout(path, &l, &w), MS_OK);
    ck_assert_int_ne(access(part, F_OK), 0);
    ck_assert_int_eq(ms_writer_close(w), MS_OK);
    ms_reader *r;
    ck_assert_int_eq(ms_reader_open(path, &r), MS_OK);
    ck_assert_int_eq(ms_reader_frames(r), 0);
    ms_reader_close(r);
    free(old);
    remove_tmp_dir();
}
END_TEST

/* Write frames of incompressible data until the writer refuses one. */
static long fill_until_refused(ms_writer *w, const ms_writer_layout *l, ms_status *st)
{
    frame_buf b = {0};
    long k = 0;
    for (;; ++k) {
        frame_fill(&b, l, k);
        for (int s = 0; s < MS_IO_NFIELDS; ++s) /* random bits: deflate cannot shrink them */
            for (int i = 0; i < l->grid[s].nx * l->grid[s].ny; ++i) {
                uint32_t bits = mix((uint32_t)(k * 1000003 + s * 7777 + i)) | 0x40000000u;
                memcpy(&b.field[s][i], &bits, 4);
            }
        ms_writer_data d = frame_data(&b);
        *st = ms_writer_write(w, &d);
        if (*st != MS_OK || k > 100000)
            break;
    }
    frame_free(&b);
    return k;
}

/* In a forked child with RLIMIT_FSIZE: the writer stops before a frame that
 * cannot fit (or, with the check off, the write fails), and the file keeps
 * the frames committed before. */
static void file_size_limit_case(int with_check)
{
    ms_writer_layout l = test_layout(MS_FIELD_COMBINED | MS_FIELD_SURFACE);
    l.grid[0].nx = l.grid[1].nx = 64;
    l.grid[0].ny = l.grid[1].ny = 64;
    pid_t pid = fork();
    ck_assert_int_ge(pid, 0);
    if (pid == 0) {
        signal(SIGXFSZ, SIG_IGN);
        struct rlimit rl = {600000, 600000};
        setrlimit(RLIMIT_FSIZE, &rl);
        ms_writer *w;
        if (ms_writer_open_layout(tmp_path("limit.h5"), &l, &w) != MS_OK)
            _exit(200);
        if (!with_check)
            ms_writer_skip_space_check(w);
        ms_status st;
        long k = fill_until_refused(w, &l, &st);
        if (st != MS_ERR_IO || k < 2)
            _exit(201);
        if (with_check && !strstr(ms_last_error(), "file size limit"))
            _exit(202);
        if (!with_check && !strstr(ms_last_error(), "File too large"))
            _exit(203);
        if (ms_writer_frames(w) != k)
            _exit(204);
        ms_status again;
        frame_buf b = {0};
        frame_fill(&b, &l, k);
        ms_writer_data d = frame_data(&b);
        again = ms_writer_write(w, &d);
        frame_free(&b);
        if (!with_check && again != MS_ERR_STATE)
            _exit(205);
        ms_writer_close(w);
        _exit(k > 199 ? 199 : (int)k);
    }
    int status;
    waitpid(pid, &status, 0);
    ck_assert(WIFEXITED(status));
    int k = WEXITSTATUS(status);
    ck_assert_msg(k >= 2 && k < 199, "child failed with %d", k);
    MS_ASSERT_H5DUMP_READS(tmp_path("limit.h5"));
    ms_reader *r;
    ck_assert_msg(ms_reader_open(tmp_path("limit.h5"), &r) == MS_OK, "%s", ms_last_error());
    ck_assert_int_eq(ms_reader_frames(r), k);
    ms_reader_close(r);
}

START_TEST(file_size_limit_stops_before_a_frame_that_cannot_fit)
{
    make_tmp_dir();
    file_size_limit_case(1);
    file_size_limit_case(0);
    remove_tmp_dir();
}
END_TEST

/* A real full disk: a 1 MiB tmpfs in a private mount namespace (root
 * only; the mount vanishes with the process). Both the space check and,
 * with it off, HDF5 meeting ENOSPC leave a readable file. */
START_TEST(full_disk_is_an_error_and_leaves_a_readable_file)
{
    if (unshare(CLONE_NEWNS) != 0 || mount(NULL, "/", NULL, MS_REC | MS_PRIVATE, NULL) != 0) {
        char why_[160];
        snprintf(why_, sizeof why_, "needs CAP_SYS_ADMIN: %s", strerror(errno));
        MS_SKIP(why_);
    }
    make_tmp_dir();
    if (mount("tmpfs", tmp_dir, "tmpfs", 0, "size=1m") != 0) {
        char why_[160];
        snprintf(why_, sizeof why_, "cannot mount a tmpfs: %s", strerror(errno));
        remove_tmp_dir();
        MS_SKIP(why_);
    }
    for (int with_check = 1; with_check >= 0; --with_check) {
        ms_writer_layout l = test_layout(MS_FIELD_COMBINED | MS_FIELD_SURFACE);
        l.grid[0].nx = l.grid[1].nx = 64;
        l.grid[0].ny = l.grid[1].ny = 64;
        ms_writer *w;
        ck_assert_int_eq(ms_writer_open_layout(tmp_path("full.h5"), &l, &w), MS_OK);
        if (!with_check)
            ms_writer_skip_space_check(w);
        ms_status st;
        long k = fill_until_refused(w, &l, &st);
        ck_assert_int_eq(st, MS_ERR_IO);
        ck_assert_msg(strstr(ms_last_error(), with_check ? "are free" : "No space left"), "%s",
                      ms_last_error());
        ck_assert_int_gt(k, 2);
        ms_writer_close(w);
        MS_ASSERT_H5DUMP_READS(tmp_path("full.h5"));
        ms_reader *r;
        ck_assert_msg(ms_reader_open(tmp_path("full.h5"), &r) == MS_OK, "%s", ms_last_error());
        ck_assert_int_eq(ms_reader_frames(r), k);
        ms_reader_close(r);
        remove(tmp_path("full.h5"));
        remove(tmp_path("full.xmf"));
    }
    umount(tmp_dir);
    remove_tmp_dir();
}
END_TEST

START_TEST(unwritable_paths_are_refused_with_the_reason)
{
    make_tmp_dir();
    ms_writer_layout l = test_layout(MS_FIELD_COMBINED);
    ms_writer *w = (ms_writer *)&l;
    MS_ASSERT_REFUSED(ms_writer_open_layout(tmp_path("no/such/dir/run.h5"), &l, &w), MS_ERR_IO,
                      "No such file or directory");
    ck_assert_ptr_null(w);
    ck_assert_ptr_nonnull(strstr(ms_last_error(), "cannot create"));
    FILE *f = fopen(tmp_path("plain"), "w");
    fclose(f);
    MS_ASSERT_REFUSED(ms_writer_open_layout(tmp_path("plain/run.h5"), &l, &w), MS_ERR_IO,
                      "Not a directory");
    /* a device or a FIFO is not opened: a FIFO would block for good, a
     * disk would take the probe's zeros (the full disk is a tmpfs in
     * full_disk_is_an_error_and_leaves_a_readable_file) */
    MS_ASSERT_REFUSED(ms_writer_open_layout("/dev/full", &l, &w), MS_ERR_IO,
                      "it is a character device, not a regular file");
    ck_assert_int_eq(mkfifo(tmp_path("pipe.h5"), 0600), 0);
    MS_ASSERT_REFUSED(ms_writer_open_layout(tmp_path("pipe.h5"), &l, &w), MS_ERR_IO,
                      "it is a FIFO (named pipe), not a regular file");
    ck_assert_int_eq(mkfifo(tmp_path("side.xmf"), 0600), 0);
    MS_ASSERT_REFUSED(ms_writer_open_layout(tmp_path("side.h5"), &l, &w), MS_ERR_IO,
                      "side.xmf: it is a FIFO (named pipe), not a regular file");
    struct stat sb;
    ck_assert_int_eq(stat(tmp_path("side.xmf"), &sb), 0);
    ck_assert(S_ISFIFO(sb.st_mode));
    ck_assert_int_ne(stat(tmp_path("side.h5"), &sb), 0);
    if (geteuid() != 0) { /* root writes anywhere */
        ck_assert_int_eq(mkdir(tmp_path("ro"), 0500), 0);
        MS_ASSERT_REFUSED(ms_writer_open_layout(tmp_path("ro/run.h5"), &l, &w), MS_ERR_IO,
                          "Permission denied");
    }
    remove_tmp_dir();
}
END_TEST

START_TEST(hdf5_errors_are_never_printed)
{
    make_tmp_dir();
    /* stderr to a file while the library meets HDF5 errors */
    fflush(stderr);
    int saved = dup(2);
    int fd = open(tmp_path("stderr.txt"), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    ck_assert_int_ge(fd, 0);
    dup2(fd, 2);
    ms_writer_layout l = test_layout(MS_FIELD_COMBINED);
    ms_writer *w;
    ms_reader *r;
    ck_assert_int_ne(ms_writer_open_layout(tmp_path("no/dir.h5"), &l, &w), MS_OK);
    FILE *f = fopen(tmp_path("text.h5"), "w");
    fputs("not hdf5\n", f);
    fclose(f);
    ck_assert_int_ne(ms_reader_open(tmp_path("text.h5"), &r), MS_OK);
    ck_assert_int_ne(ms_writer_open_layout("/dev/full", &l, &w), MS_OK);
    fflush(stderr);
    dup2(saved, 2);
    close(saved);
    close(fd);
    char *s = ms_test_slurp(tmp_path("stderr.txt"));
    ck_assert_str_eq(s, "");
    free(s);
    /* and HDF5's own printing is back to what it was */
    H5E_auto2_t func = NULL;
    void *data = NULL;
    H5Eget_auto2(H5E_DEFAULT, &func, &data);
    ck_assert(func != NULL);
    remove_tmp_dir();
}
END_TEST

/* ---- refusals ----------------------------------------------------------- */

START_TEST(writer_refuses_bad_layouts_and_frames)
{
    make_tmp_dir();
    ms_writer *w;
    const char *p = tmp_path("bad.h5");
    ms_writer_layout l = test_layout(0);
    MS_ASSERT_REFUSED(ms_writer_open_layout(p, &l, &w), MS_ERR_INVALID_ARGUMENT, "no fields");
    l = test_layout(1u << 7);
    MS_ASSERT_REFUSED(ms_writer_open_layout(p, &l, &w), MS_ERR_INVALID_ARGUMENT, "bits");
    l = test_layout(MS_FIELD_COMBINED);
    l.grid[0].nx = 0;
    MS_ASSERT_REFUSED(ms_writer_open_layout(p, &l, &w), MS_ERR_INVALID_ARGUMENT, "grid 0 x 23");
    l = test_layout(MS_FIELD_COMBINED);
    l.grid[0].nx = l.grid[0].ny = 60000;
    MS_ASSERT_REFUSED(ms_writer_open_layout(p, &l, &w), MS_ERR_INVALID_ARGUMENT, "cells");
    l = test_layout(MS_FIELD_SURFACE);
    l.grid[1].dy = 0;
    MS_ASSERT_REFUSED(ms_writer_open_layout(p, &l, &w), MS_ERR_INVALID_ARGUMENT, "cell size");
    l = test_layout(MS_FIELD_VOLUME);
    l.grid[2].origin[1] = NAN;
    MS_ASSERT_REFUSED(ms_writer_open_layout(p, &l, &w), MS_ERR_INVALID_ARGUMENT, "origin");
    l = test_layout(MS_FIELD_COMBINED);
    l.frame_dt = -1;
    MS_ASSERT_REFUSED(ms_writer_open_layout(p, &l, &w), MS_ERR_INVALID_ARGUMENT, "frame_dt");
    l = test_layout(MS_FIELD_COMBINED);
    l.output_every = 0;
    MS_ASSERT_REFUSED(ms_writer_open_layout(p, &l, &w), MS_ERR_INVALID_ARGUMENT, "output_every");
    l = test_layout(MS_FIELD_COMBINED);
    l.deflate = 10;
    MS_ASSERT_REFUSED(ms_writer_open_layout(p, &l, &w), MS_ERR_INVALID_ARGUMENT,
                      "deflate level 10");
    l.deflate = -1;
    MS_ASSERT_REFUSED(ms_writer_open_layout(p, &l, &w), MS_ERR_INVALID_ARGUMENT, "0 .. 9");
    l = test_layout(MS_FIELD_COMBINED);
    l.output_every = 0;
    MS_ASSERT_REFUSED(ms_writer_open_layout("", &l, &w), MS_ERR_INVALID_ARGUMENT, "empty");
    MS_ASSERT_REFUSED(ms_writer_open_layout(NULL, &l, &w), MS_ERR_INVALID_ARGUMENT, "path");

    l = test_layout(MS_FIELD_COMBINED | MS_FIELD_PARTICLES);
    ck_assert_int_eq(ms_writer_open_layout(p, &l, &w), MS_OK);
    frame_buf b = {0};
    frame_fill(&b, &l, 1);
    ms_writer_data d = frame_data(&b);
    d.field[0] = NULL;
    MS_ASSERT_REFUSED(ms_writer_write(w, &d), MS_ERR_INVALID_ARGUMENT, "no data");
    d = frame_data(&b);
    d.time = NAN;
    MS_ASSERT_REFUSED(ms_writer_write(w, &d), MS_ERR_INVALID_ARGUMENT, "time");
    d = frame_data(&b);
    d.particles = -1;
    MS_ASSERT_REFUSED(ms_writer_write(w, &d), MS_ERR_INVALID_ARGUMENT, "particle count");
    d = frame_data(&b);
    d.vel[2] = NULL;
    MS_ASSERT_REFUSED(ms_writer_write(w, &d), MS_ERR_INVALID_ARGUMENT, "NULL");
    MS_ASSERT_REFUSED(ms_writer_write(w, NULL), MS_ERR_INVALID_ARGUMENT, "frame data");
    /* refused frames left nothing behind */
    ck_assert_int_eq(ms_writer_frames(w), 0);
    ck_assert_int_eq(ms_writer_close(w), MS_OK);
    ck_assert_int_eq(ms_writer_close(NULL), MS_OK);
    frame_free(&b);
    ms_reader *r;
    ck_assert_int_eq(ms_reader_open(p, &r), MS_OK);
    ck_assert_int_eq(ms_reader_frames(r), 0);
    ms_reader_close(r);
    remove_tmp_dir();
}
END_TEST

/* Build a small HDF5 file by hand: a root with the given format attributes. */
static void foreign_file(const char *path, const char *format, long version)
{
    hid_t f = H5Fcreate(path, H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
    ck_assert_int_ge(f, 0);
    if (format)
        ck_assert_int_ge(ms_h5_attr_string(f, "format", format), 0);
    if (version)
        ck_assert_int_ge(ms_h5_attr_int64(f, "format_version", version), 0);
    H5Fclose(f);
}

START_TEST(reader_refuses_what_is_not_a_run)
{
    make_tmp_dir();
    ms_reader *r = (ms_reader *)tmp_dir;
    MS_ASSERT_REFUSED(ms_reader_open(tmp_path("absent.h5"), &r), MS_ERR_IO, "No such file");
    ck_assert_ptr_null(r);
    MS_ASSERT_REFUSED(ms_reader_open(tmp_dir, &r), MS_ERR_IO, "not a regular file");
    FILE *f = fopen(tmp_path("text.h5"), "w");
    fputs("{\"name\": \"a scene, not a run\"}\n", f);
    fclose(f);
    MS_ASSERT_REFUSED(ms_reader_open(tmp_path("text.h5"), &r), MS_ERR_IO, "not an HDF5 file");
    foreign_file(tmp_path("other.h5"), NULL, 0);
    MS_ASSERT_REFUSED(ms_reader_open(tmp_path("other.h5"), &r), MS_ERR_PARSE,
                      "not a modesplit run");
    foreign_file(tmp_path("newer.h5"), "modesplit", 99);
    MS_ASSERT_REFUSED(ms_reader_open(tmp_path("newer.h5"), &r), MS_ERR_UNSUPPORTED,
                      "format_version 99");
    foreign_file(tmp_path("bare.h5"), "modesplit", 1);
    MS_ASSERT_REFUSED(ms_reader_open(tmp_path("bare.h5"), &r), MS_ERR_PARSE, "frames");
    MS_ASSERT_REFUSED(ms_reader_open(NULL, &r), MS_ERR_INVALID_ARGUMENT, "path");

    ms_writer_layout l = test_layout(MS_FIELD_COMBINED);
    ms_writer *w;
    ck_assert_int_eq(ms_writer_open_layout(tmp_path("ok.h5"), &l, &w), MS_OK);
    write_frames(w, &l, 0, 2);
    ms_writer_close(w);
    ck_assert_int_eq(ms_reader_open(tmp_path("ok.h5"), &r), MS_OK);
    float buf[37 * 23];
    double t;
    MS_ASSERT_REFUSED(ms_reader_read_field(r, MS_FIELD_COMBINED, 2, buf, 37 * 23),
                      MS_ERR_INVALID_ARGUMENT, "frame 2 is outside [0, 2)");
    MS_ASSERT_REFUSED(ms_reader_read_field(r, MS_FIELD_COMBINED, -1, buf, 37 * 23),
                      MS_ERR_INVALID_ARGUMENT, "outside");
    MS_ASSERT_REFUSED(ms_reader_read_field(r, MS_FIELD_COMBINED, 0, buf, 100),
                      MS_ERR_INVALID_ARGUMENT, "851 floats");
    MS_ASSERT_REFUSED(ms_reader_read_field(r, MS_FIELD_COMBINED | MS_FIELD_SURFACE, 0, buf, 851),
                      MS_ERR_INVALID_ARGUMENT, "not one of");
    MS_ASSERT_REFUSED(ms_reader_time(r, 5, &t), MS_ERR_INVALID_ARGUMENT, "frame 5");
    ms_grid g;
    MS_ASSERT_REFUSED(ms_reader_field_grid(r, MS_FIELD_VOLUME, &g), MS_ERR_INVALID_ARGUMENT,
                      "no field volume");
    ms_reader_close(r);
    ms_reader_close(NULL);
    remove_tmp_dir();
}
END_TEST

/* A file whose datasets lie about themselves is refused, not trusted. */
START_TEST(reader_refuses_malformed_datasets)
{
    make_tmp_dir();
    const char *p = tmp_path("lie.h5");
    /* /time as integers, /fields/combined of rank 2, missing dx */
    for (int variant = 0; variant < 3; ++variant) {
        hid_t f = H5Fcreate(p, H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
        ms_h5_attr_string(f, "format", "modesplit");
        ms_h5_attr_int64(f, "format_version", 1);
        ms_h5_attr_int64(f, "frames", 1);
        hsize_t one = 1, two[2] = {4, 4};
        hid_t sp = H5Screate_simple(1, &one, NULL);
        hid_t d = H5Dcreate2(f, "time", variant == 0 ? H5T_STD_I32LE : H5T_IEEE_F64LE, sp,
                             H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
        H5Dclose(d);
        H5Sclose(sp);
        hid_t g = H5Gcreate2(f, "fields", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
        hsize_t three[3] = {1, 4, 4};
        sp = variant == 1 ? H5Screate_simple(2, two, NULL) : H5Screate_simple(3, three, NULL);
        d = H5Dcreate2(g, "combined", H5T_IEEE_F32LE, sp, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
        H5Dclose(d);
        H5Sclose(sp);
        H5Gclose(g);
        H5Fclose(f);
        ms_reader *r;
        const char *word[3] = {"/time", "/fields/combined is not", "attribute dx"};
        MS_ASSERT_REFUSED(ms_reader_open(p, &r), MS_ERR_PARSE, word[variant]);
    }
    remove_tmp_dir();
}
END_TEST

/* ---- PNG preview -------------------------------------------------------- */

static unsigned char *shade(const float *h, int nx, int ny, const ms_preview_desc *d)
{
    size_t n = (size_t)nx * d->scale * ny * d->scale * 3;
    unsigned char *rgb = malloc(n);
    ck_assert_msg(ms_field_shade(h, nx, ny, d, rgb, n) == MS_OK, "%s", ms_last_error());
    return rgb;
}

START_TEST(preview_has_north_up_and_the_water_ramp)
{
    /* h = y: the top row (largest y) is the highest, pale; the bottom deep. */
    enum { NX = 5, NY = 4 };
    float h[NX * NY];
    for (int y = 0; y < NY; ++y)
        for (int x = 0; x < NX; ++x)
            h[y * NX + x] = (float)y;
    ms_preview_desc d = ms_preview_desc_default();
    d.relief = 0; /* colour only */
    unsigned char *rgb = shade(h, NX, NY, &d);
    const unsigned char *top = rgb, *bottom = rgb + (NY - 1) * NX * 3;
    ck_assert_int_eq(top[0], 242); /* foam 0.95 * 255 */
    ck_assert_int_eq(top[2], 255);
    ck_assert_int_eq(bottom[0], 5);  /* navy 0.02 * 255 */
    ck_assert_int_eq(bottom[2], 71); /* 0.28 * 255 */
    /* every pixel of a row equal */
    for (int x = 1; x < NX; ++x)
        ck_assert_int_eq(memcmp(rgb + x * 3, rgb, 3), 0);
    free(rgb);
    /* a fixed range clamps: everything above height_max is foam */
    d.height_min = -1;
    d.height_max = 0.5f;
    rgb = shade(h, NX, NY, &d);
    ck_assert_int_eq(rgb[(NY - 2) * NX * 3], 242);
    free(rgb);
}
END_TEST

START_TEST(preview_hillshade_lights_slopes_facing_the_sun)
{
    /* A ridge along y: its west flank faces a sun in the west. */
    enum { NX = 21, NY = 3 };
    float h[NX * NY];
    for (int y = 0; y < NY; ++y)
        for (int x = 0; x < NX; ++x)
            h[y * NX + x] = 0.05f * (10.0f - fabsf((float)x - 10.0f));
    ms_preview_desc d = ms_preview_desc_default();
    d.sun_azimuth = 270; /* west */
    d.height_min = d.height_max = 0.3f;
    d.height_min = 0.0f;
    d.relief = 1;
    unsigned char *rgb = shade(h, NX, NY, &d);
    /* same height (same ramp colour) at x = 5 (west flank) and x = 15 */
    const unsigned char *west = rgb + (NX + 5) * 3, *east = rgb + (NX + 15) * 3;
    for (int c = 0; c < 3; ++c)
        ck_assert_int_gt(west[c], east[c]);
    /* a flat field is lit exactly as the ramp says */
    float flat[NX * NY];
    for (int i = 0; i < NX * NY; ++i)
        flat[i] = 0.15f;
    d.height_min = 0;
    d.height_max = 0.3f;
    unsigned char *f = shade(flat, NX, NY, &d);
    d.relief = 0;
    unsigned char *g = shade(flat, NX, NY, &d);
    ck_assert_int_eq(memcmp(f, g, NX * NY * 3), 0);
    free(f);
    free(g);
    free(rgb);
}
END_TEST

START_TEST(preview_png_holds_the_shaded_pixels)
{
    make_tmp_dir();
    enum { NX = 30, NY = 17 };
    float h[NX * NY];
    for (int i = 0; i < NX * NY; ++i)
        h[i] = 0.01f * sinf(0.7f * (float)(i % NX)) * cosf(0.4f * (float)(i / NX));
    h[3] = NAN;
    ms_preview_desc d = ms_preview_desc_default();
    d.scale = 2;
    ck_assert_msg(ms_field_write_png(h, NX, NY, tmp_path("f.png"), &d) == MS_OK, "%s",
                  ms_last_error());
    unsigned char *want = shade(h, NX, NY, &d);
    png_image img;
    memset(&img, 0, sizeof img);
    img.version = PNG_IMAGE_VERSION;
    ck_assert(png_image_begin_read_from_file(&img, tmp_path("f.png")));
    ck_assert_int_eq(img.width, NX * 2);
    ck_assert_int_eq(img.height, NY * 2);
    img.format = PNG_FORMAT_RGB;
    unsigned char *got = malloc(PNG_IMAGE_SIZE(img));
    ck_assert(png_image_finish_read(&img, NULL, got, 0, NULL));
    ck_assert_int_eq(memcmp(got, want, NX * NY * 4 * 3), 0);
    /* the NaN cell (x = 3, y = 0: bottom row) is magenta */
    const unsigned char *m = got + ((size_t)(2 * NY - 1) * 2 * NX + 6) * 3;
    ck_assert(m[0] == 255 && m[1] == 0 && m[2] == 255);
    free(got);
    free(want);
    /* no temporary file is left behind */
    ck_assert_int_ne(access(tmp_path("f.png.tmp"), F_OK), 0);
    remove_tmp_dir();
}
END_TEST

START_TEST(preview_refuses_bad_arguments)
{
    float h[4] = {0, 1, 2, 3};
    unsigned char rgb[64];
    ms_preview_desc d = ms_preview_desc_default();
    MS_ASSERT_REFUSED(ms_field_shade(h, 2, 2, &d, rgb, 5), MS_ERR_INVALID_ARGUMENT, "rgb holds");
    MS_ASSERT_REFUSED(ms_field_shade(NULL, 2, 2, &d, rgb, 64), MS_ERR_INVALID_ARGUMENT,
                      "height field");
    MS_ASSERT_REFUSED(ms_field_shade(h, 0, 2, &d, rgb, 64), MS_ERR_INVALID_ARGUMENT, "nx");
    d.scale = 0;
    MS_ASSERT_REFUSED(ms_field_shade(h, 2, 2, &d, rgb, 64), MS_ERR_INVALID_ARGUMENT, "scale");
    d = ms_preview_desc_default();
    d.sun_elevation = 0;
    MS_ASSERT_REFUSED(ms_field_shade(h, 2, 2, &d, rgb, 64), MS_ERR_INVALID_ARGUMENT,
                      "sun_elevation");
    d = ms_preview_desc_default();
    d.height_min = 1;
    MS_ASSERT_REFUSED(ms_field_shade(h, 2, 2, &d, rgb, 64), MS_ERR_INVALID_ARGUMENT, "height_min");
    d = ms_preview_desc_default();
    d.dx = NAN;
    MS_ASSERT_REFUSED(ms_field_shade(h, 2, 2, &d, rgb, 64), MS_ERR_INVALID_ARGUMENT, "dx");
    d = ms_preview_desc_default();
    d.relief = -1;
    MS_ASSERT_REFUSED(ms_field_shade(h, 2, 2, &d, rgb, 64), MS_ERR_INVALID_ARGUMENT, "relief");
    d = ms_preview_desc_default();
    MS_ASSERT_REFUSED(ms_field_write_png(h, 2, 2, "/no/such/dir/f.png", &d), MS_ERR_IO,
                      "No such file");
    make_tmp_dir();
    ck_assert_int_eq(mkdir(tmp_path("sub"), 0700), 0);
    MS_ASSERT_REFUSED(ms_field_write_png(h, 2, 2, tmp_path("sub"), &d), MS_ERR_IO,
                      "Is a directory");
    ck_assert_int_ne(access(tmp_path("sub.tmp"), F_OK), 0);
    rmdir(tmp_path("sub"));
    remove_tmp_dir();
}
END_TEST

/* ---- reopening to append (resume) ------------------------------------ */

/* A kill between a frame's data and its commit: datasets one longer than
 * `frames` and the step's links, as the writer leaves them. */
static void leave_cut_frame(const char *path, const ms_writer_layout *l, long frames)
{
    hid_t f = H5Fopen(path, H5F_ACC_RDWR, H5P_DEFAULT);
    ck_assert_int_ge(f, 0);
    for (int s = 0; s < MS_IO_NFIELDS; ++s) {
        char name[64];
        snprintf(name, sizeof name, "fields/%s", ms_io_field_names[s]);
        hid_t d = H5Dopen2(f, name, H5P_DEFAULT);
        hsize_t dims[3] = {(hsize_t)frames + 1, (hsize_t)l->grid[s].ny, (hsize_t)l->grid[s].nx};
        ck_assert_int_ge(H5Dset_extent(d, dims), 0);
        H5Dclose(d);
    }
    hid_t d = H5Dopen2(f, "time", H5P_DEFAULT);
    hsize_t tdims[1] = {(hsize_t)frames + 1};
    ck_assert_int_ge(H5Dset_extent(d, tdims), 0);
    H5Dclose(d);
    char step[64];
    ms_h5part_step_name(step, sizeof step, frames);
    hid_t g = H5Gcreate2(f, step, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
    ck_assert_int_ge(g, 0);
    H5Gclose(g);
    H5Fclose(f);
}

START_TEST(append_continues_after_the_last_complete_frame)
{
    make_tmp_dir();
    ms_writer_layout l = test_layout(MS_IO_ALL_FIELDS);
    ms_writer *w;
    ck_assert_int_eq(ms_writer_open_layout(tmp_path("a.h5"), &l, &w), MS_OK);
    write_frames(w, &l, 0, 5);
    ck_assert_int_eq(ms_writer_close(w), MS_OK);
    leave_cut_frame(tmp_path("a.h5"), &l, 5);
    ck_assert_msg(ms_writer_open_append_layout(tmp_path("a.h5"), &l, &w) == MS_OK, "%s",
                  ms_last_error());
    ck_assert_int_eq(ms_writer_frames(w), 5);
    write_frames(w, &l, 5, 9);
    ck_assert_int_eq(ms_writer_close(w), MS_OK);
    /* twice */
    ck_assert_int_eq(ms_writer_open_append_layout(tmp_path("a.h5"), &l, &w), MS_OK);
    ck_assert_int_eq(ms_writer_frames(w), 9);
    write_frames(w, &l, 9, 11);
    ck_assert_int_eq(ms_writer_close(w), MS_OK);
    MS_ASSERT_H5DUMP_READS(tmp_path("a.h5"));
    ms_reader *r;
    ck_assert_int_eq(ms_reader_open(tmp_path("a.h5"), &r), MS_OK);
    check_frames(r, &l, 11);
    ms_reader_close(r);
    char *x = ms_test_slurp(tmp_path("a.xmf"));
    ck_assert_msg(x[0], "missing or empty");
    ck_assert_int_eq(count_of(x, "<Time Value="), 11);
    free(x);
    remove_tmp_dir();
}
END_TEST

START_TEST(append_refuses_another_scene_build_or_fields)
{
    make_tmp_dir();
    ms_writer_layout l = test_layout(MS_IO_ALL_FIELDS);
    ms_writer *w;
    ck_assert_int_eq(ms_writer_open_layout(tmp_path("a.h5"), &l, &w), MS_OK);
    write_frames(w, &l, 0, 3);
    ck_assert_int_eq(ms_writer_close(w), MS_OK);

    ms_writer_layout other = l;
    other.scene_text = "{\"name\": \"test scene\", \"frame_dt\": 0.01}";
    MS_ASSERT_REFUSED(ms_writer_open_append_layout(tmp_path("a.h5"), &other, &w),
                      MS_ERR_INVALID_ARGUMENT, "frame_dt is 0.02 in the file, 0.01 here");
    ck_assert_ptr_null(w);
    other = l;
    other.scene_text = "{\"frame_dt\": 0.02, \"name\": \"test scene\"}"; /* same values */
    MS_ASSERT_REFUSED(ms_writer_open_append_layout(tmp_path("a.h5"), &other, &w),
                      MS_ERR_INVALID_ARGUMENT, "another scene text: line 1");
    other = l;
    other.fields = MS_FIELD_COMBINED | MS_FIELD_PARTICLES;
    MS_ASSERT_REFUSED(ms_writer_open_append_layout(tmp_path("a.h5"), &other, &w),
                      MS_ERR_INVALID_ARGUMENT, "holds the field surface");
    other = l;
    other.grid[MS_IO_VOLUME].nx = 10;
    MS_ASSERT_REFUSED(ms_writer_open_append_layout(tmp_path("a.h5"), &other, &w),
                      MS_ERR_INVALID_ARGUMENT, "[frame][6][10]");
    MS_ASSERT_REFUSED(ms_writer_open_append_layout(tmp_path("none.h5"), &l, &w), MS_ERR_IO,
                      "none.h5");
    FILE *f = fopen(tmp_path("text.h5"), "w");
    fputs("not a run\n", f);
    fclose(f);
    MS_ASSERT_REFUSED(ms_writer_open_append_layout(tmp_path("text.h5"), &l, &w), MS_ERR_IO,
                      "text.h5");
    /* another build */
    hid_t h = H5Fopen(tmp_path("a.h5"), H5F_ACC_RDWR, H5P_DEFAULT);
    ck_assert_int_ge(H5Adelete(h, "library_version"), 0);
    ck_assert_int_ge(ms_h5_attr_string(h, "library_version", "0.0.1-other"), 0);
    H5Fclose(h);
    MS_ASSERT_REFUSED(ms_writer_open_append_layout(tmp_path("a.h5"), &l, &w),
                      MS_ERR_INVALID_ARGUMENT, "library version 0.0.1-other");
    /* the refusals changed nothing */
    ms_reader *r;
    ck_assert_int_eq(ms_reader_open(tmp_path("a.h5"), &r), MS_OK);
    check_frames(r, &l, 3);
    ms_reader_close(r);
    remove_tmp_dir();
}
END_TEST

/* The bytes of a file, compared before and after a refusal. */
static void assert_same_bytes(const char *path, const char *before, size_t n)
{
    size_t m;
    char *now = ms_test_slurp_n(path, &m);
    ck_assert_msg(now && m == n && !memcmp(now, before, n), "%s changed", path);
    free(now);
}

/* Replace /time of the run at `path` with `how`: 0 an external link to
 * victim:/time, 1 a soft link to a hard copy, 2 a dataset whose values
 * live in the raw file `victim` (HDF5's external storage). */
static void forge_time_link(const char *path, int how, const char *victim)
{
    hid_t f = H5Fopen(path, H5F_ACC_RDWR, H5P_DEFAULT);
    ck_assert_int_ge(f, 0);
    if (how == 1)
        ck_assert_int_ge(H5Lmove(f, "time", f, "time_real", H5P_DEFAULT, H5P_DEFAULT), 0);
    else
        ck_assert_int_ge(H5Ldelete(f, "time", H5P_DEFAULT), 0);
    if (how == 0) {
        ck_assert_int_ge(H5Lcreate_external(victim, "/time", f, "time", H5P_DEFAULT, H5P_DEFAULT),
                         0);
    } else if (how == 1) {
        ck_assert_int_ge(H5Lcreate_soft("/time_real", f, "time", H5P_DEFAULT, H5P_DEFAULT), 0);
    } else {
        hsize_t n = 3, maxn = H5S_UNLIMITED;
        hid_t sp = H5Screate_simple(1, &n, &maxn), dcpl = H5Pcreate(H5P_DATASET_CREATE);
        ck_assert_int_ge(H5Pset_external(dcpl, victim, 0, H5F_UNLIMITED), 0);
        hid_t d = H5Dcreate2(f, "time", H5T_IEEE_F64LE, sp, H5P_DEFAULT, dcpl, H5P_DEFAULT);
        ck_assert_int_ge(d, 0);
        H5Dclose(d);
        H5Pclose(dcpl);
        H5Sclose(sp);
    }
    H5Fclose(f);
}

/* A run file naming another file would make an append extend and write
 * that file: the appender runs the reader's link check and refuses
 * external storage, before anything is written to either file; a FIFO or a
 * device is refused before it is opened (the case's time-out catches a
 * hang). */
START_TEST(append_refuses_links_to_other_files_and_leaves_them)
{
    make_tmp_dir();
    ms_writer_layout l = test_layout(MS_IO_ALL_FIELDS);
    ms_writer *w;
    char victim[512], run[512], raw[512];
    snprintf(victim, sizeof victim, "%s", tmp_path("victim.h5"));
    snprintf(run, sizeof run, "%s", tmp_path("forged.h5"));
    snprintf(raw, sizeof raw, "%s", tmp_path("victim.raw"));
    ck_assert_int_eq(ms_writer_open_layout(victim, &l, &w), MS_OK);
    write_frames(w, &l, 0, 3);
    ck_assert_int_eq(ms_writer_close(w), MS_OK);
    FILE *rf = fopen(raw, "wb");
    ck_assert_ptr_nonnull(rf);
    const double t3[3] = {0, 0.02, 0.04};
    ck_assert_int_eq(fwrite(t3, sizeof t3, 1, rf), 1);
    fclose(rf);
    size_t nv, nr;
    char *v0 = ms_test_slurp_n(victim, &nv), *r0 = ms_test_slurp_n(raw, &nr);
    ck_assert_ptr_nonnull(v0);
    ck_assert_ptr_nonnull(r0);
    static const char *const words[3] = {"time is an external or soft link",
                                         "time is an external or soft link",
                                         "/time keeps its values in another file"};
    for (int how = 0; how < 3; ++how) {
        ck_assert_int_eq(ms_writer_open_layout(run, &l, &w), MS_OK);
        write_frames(w, &l, 0, 3);
        ck_assert_int_eq(ms_writer_close(w), MS_OK);
        forge_time_link(run, how, how == 2 ? raw : victim);
        size_t nf;
        char *f0 = ms_test_slurp_n(run, &nf);
        ck_assert_ptr_nonnull(f0);
        MS_ASSERT_REFUSED(ms_writer_open_append_layout(run, &l, &w), MS_ERR_PARSE, words[how]);
        ck_assert_ptr_null(w);
        assert_same_bytes(run, f0, nf);
        free(f0);
        assert_same_bytes(victim, v0, nv);
        assert_same_bytes(raw, r0, nr);
        /* the reader says the same of the links */
        ms_reader *r;
        if (how < 2)
            MS_ASSERT_REFUSED(ms_reader_open(run, &r), MS_ERR_PARSE, words[how]);
        ck_assert_int_eq(unlink(run), 0);
    }
    free(v0);
    free(r0);
    /* a step's x that is a scalar: named, not HDF5's stale reason */
    ck_assert_int_eq(ms_writer_open_layout(run, &l, &w), MS_OK);
    write_frames(w, &l, 0, 3);
    ck_assert_int_eq(ms_writer_close(w), MS_OK);
    hid_t h = H5Fopen(run, H5F_ACC_RDWR, H5P_DEFAULT);
    ck_assert_int_ge(H5Ldelete(h, "Step#1/x", H5P_DEFAULT), 0);
    hid_t sp = H5Screate(H5S_SCALAR);
    hid_t d = H5Dcreate2(h, "Step#1/x", H5T_IEEE_F32LE, sp, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
    ck_assert_int_ge(d, 0);
    H5Dclose(d);
    H5Sclose(sp);
    H5Fclose(h);
    MS_ASSERT_REFUSED(ms_writer_open_append_layout(run, &l, &w), MS_ERR_PARSE,
                      "forged.h5 cannot be read back: its /Step#1/x is missing or not a 1D float "
                      "array");
    ck_assert_int_eq(mkfifo(tmp_path("pipe.h5"), 0600), 0);
    MS_ASSERT_REFUSED(ms_writer_open_append_layout(tmp_path("pipe.h5"), &l, &w), MS_ERR_IO,
                      "it is a FIFO (named pipe), not a regular file");
    MS_ASSERT_REFUSED(ms_writer_open_append_layout("/dev/null", &l, &w), MS_ERR_IO,
                      "it is a character device, not a regular file");
    remove_tmp_dir();
}
END_TEST

static Suite *io_suite(void)
{
    Suite *s = suite_create("io");
    TCase *tc = tcase_create("file");
    tcase_set_timeout(tc, 60);
    tcase_add_test(tc, round_trip_is_bit_for_bit_on_a_non_square_grid);
    tcase_add_test(tc, deflate_levels_round_trip_and_level_0_stores_raw);
    tcase_add_test(tc, only_the_fields_asked_for_are_written);
    tcase_add_test(tc, a_scene_text_over_64_kib_round_trips);
    tcase_add_test(tc, xdmf_lists_every_frame_with_z_y_x_axis_order);
    tcase_add_test(tc, particles_have_ids_and_xyz_arrays_equal_to_h5part);
    tcase_add_test(tc, xdmf_path_replaces_h5_or_appends);
    tcase_add_test(tc, superblock_checksum_matches_hdf5);
    suite_add_tcase(s, tc);
    tc = tcase_create("crash");
    tcase_set_timeout(tc, 60);
    tcase_add_test(tc, sigkill_mid_run_leaves_every_flushed_frame);
    tcase_add_test(tc, sigkill_mid_run_leaves_a_whole_checkpoint);
    tcase_add_test(tc, a_kill_inside_a_flush_leaves_the_committed_bytes);
    tcase_add_test(tc, a_kill_before_the_layout_is_on_disk_leaves_the_older_run);
    tcase_add_test(tc, file_size_limit_stops_before_a_frame_that_cannot_fit);
    tcase_add_test(tc, full_disk_is_an_error_and_leaves_a_readable_file);
    tcase_add_test(tc, unwritable_paths_are_refused_with_the_reason);
    tcase_add_test(tc, hdf5_errors_are_never_printed);
    suite_add_tcase(s, tc);
    tc = tcase_create("refusals");
    tcase_set_timeout(tc, 60);
    tcase_add_test(tc, writer_refuses_bad_layouts_and_frames);
    tcase_add_test(tc, reader_refuses_what_is_not_a_run);
    tcase_add_test(tc, reader_refuses_malformed_datasets);
    tcase_add_test(tc, append_continues_after_the_last_complete_frame);
    tcase_add_test(tc, append_refuses_another_scene_build_or_fields);
    tcase_add_test(tc, append_refuses_links_to_other_files_and_leaves_them);
    suite_add_tcase(s, tc);
    tc = tcase_create("preview");
    tcase_set_timeout(tc, 60);
    tcase_add_test(tc, preview_has_north_up_and_the_water_ramp);
    tcase_add_test(tc, preview_hillshade_lights_slopes_facing_the_sun);
    tcase_add_test(tc, preview_png_holds_the_shaded_pixels);
    tcase_add_test(tc, preview_refuses_bad_arguments);
    suite_add_tcase(s, tc);
    return s;
}

int main(void)
{
    return ms_test_run(io_suite());
}
