/* lib/io: the HDF5 run file (DESIGN 5), written from raw arrays.
 *
 * Owns the file's layout: root attributes, /time, /fields/<name> as float32
 * [frame][y][x] datasets (extendible, one frame per chunk, shuffle +
 * deflate, no chunk cache so each frame goes to disk when written), the
 * H5Part particle steps (h5part.c) and the XDMF sidecar (xdmf.c).
 *
 * Crash safety, in this order per frame:
 *   1. check the space left (file system and RLIMIT_FSIZE) for the frame;
 *   2. extend and write every field and /time, build the particle step as
 *      an anonymous group;
 *   3. H5Fflush: the frame's data and metadata are on disk (the file is
 *      written through h5_atomic.c, whose flushes land all or nothing even
 *      when the process is killed in one; without its helper process the
 *      superblock's EOA is moved ahead first, eoa_guard.c);
 *   4. link /Step#k and /particles/k, raise the root attribute `frames`, guard and flush
 *      again: the commit;
 *   5. append the frame to the XDMF sidecars: run.xmf by renaming in the
 *      copy with the frame made before step 2 (a kill leaves the old or the
 *      new file, a full disk refuses the frame before anything is written),
 *      the legacy grid files by one pwrite each.
 * A checkpoint (a sim snapshot) goes with step 2 into the older
 * of the two /checkpoint/<slot> datasets, its `frame` attribute set to the
 * frame: a reader uses it only once `frames` counts that frame (so a kill
 * before step 4 leaves it unused), and a blob torn by a kill fails its own
 * checksum (ms_sim_restore), which sends the resume to the other slot.
 * Freed file space is never reused (H5F_FSPACE_STRATEGY_NONE), so nothing a
 * flushed state refers to is overwritten by a later frame's data; a kill
 * between two flushes or inside one leaves the last committed state
 * readable. The reader
 * takes the smallest of `frames` and every dataset's length.
 */
#define _GNU_SOURCE /* memfd_create */
#include <errno.h>
#include <fcntl.h>
#include <sys/file.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/statvfs.h>
#include <sys/mman.h>
#include <unistd.h>

#include "io/io_internal.h"

#define TIME_CHUNK 256
/* Half the fan-out of the chunk-index B-tree nodes (HDF5's default is 32):
 * a node splits every CHUNK_BTREE_K frames, and a split is the one change
 * of a flush whose parent is written before its new child. Larger nodes
 * make that rarer at the cost of rewriting a larger node (~100 bytes an
 * entry) each frame. */
#define CHUNK_BTREE_K 128
/* Metadata written per frame beyond the raw arrays (B-tree nodes, object
 * headers, the Step group), generous. */
#define META_SLACK_BYTES (256u * 1024u)

struct ms_writer {
    int lock_fd; /* holds flock(LOCK_EX) on the run file, -1 = none */
    char *path;
    char *xmf_path;
    char *xmf2_path; /* the legacy reader's sidecar */
    hid_t file;
    hid_t dset[MS_IO_NFIELDS];
    hid_t time_dset;
    hid_t floater_dset; /* /floaters [frame][n][3], -1 without floaters */
    hid_t spray_dset;   /* /spray [frame][budget][3], -1 without spray */
    hid_t spray_n_dset; /* /spray_count [frame] */
    hid_t foam_dset;    /* /foam [frame][y][x] */
    float *spray_rows;  /* budget * 3: a frame's rows, NaN past the droplets */
    hid_t frames_attr;
    ms_writer_layout layout; /* strings not kept */
    long frames;             /* committed */
    int failed;              /* a write failed: no more frames */
    int no_space_check;      /* tests: let the write meet the full disk */
    ms_xdmf *xdmf, *xdmf2;
    hid_t ckpt[MS_IO_CHECKPOINTS];      /* /checkpoint/<slot>, -1 = not yet */
    long ckpt_frame[MS_IO_CHECKPOINTS]; /* frame each holds, -1 = none or stale */
    size_t ckpt_pending;                /* bytes of the checkpoint of the frame in hand */
    void *ckpt_buf;                     /* ms_writer_checkpoint_buffer */
    size_t ckpt_cap;
};

static void close_handles(ms_writer *w)
{
    for (int i = 0; i < MS_IO_NFIELDS; ++i)
        if (w->dset[i] >= 0) {
            H5Dclose(w->dset[i]);
            w->dset[i] = -1;
        }
    if (w->time_dset >= 0) {
        H5Dclose(w->time_dset);
        w->time_dset = -1;
    }
    if (w->floater_dset >= 0) {
        H5Dclose(w->floater_dset);
        w->floater_dset = -1;
    }
    hid_t *spray[3] = {&w->spray_dset, &w->spray_n_dset, &w->foam_dset};
    for (int i = 0; i < 3; ++i)
        if (*spray[i] >= 0) {
            H5Dclose(*spray[i]);
            *spray[i] = -1;
        }
    if (w->frames_attr >= 0) {
        H5Aclose(w->frames_attr);
        w->frames_attr = -1;
    }
    for (int i = 0; i < MS_IO_CHECKPOINTS; ++i)
        if (w->ckpt[i] >= 0) {
            H5Dclose(w->ckpt[i]);
            w->ckpt[i] = -1;
        }
}

static void free_writer(ms_writer *w)
{
    if (!w)
        return;
    if (w->lock_fd >= 0)
        close(w->lock_fd); /* after the file is closed: the lock ends last */
    ms_free(w->path);
    ms_free(w->xmf_path);
    ms_free(w->xmf2_path);
    ms_free(w->ckpt_buf);
    ms_free(w->spray_rows);
    ms_free(w);
}

/* Close a file that met a write error without writing to it again.
 * H5Fclose flushes, and a flush that fails keeps the file open inside
 * HDF5, which then loops (and prints) when the program exits. So the file
 * descriptor under HDF5 is first pointed at an anonymous scratch file:
 * the close writes its last metadata there, and the file on disk keeps
 * the state of the last committed frame. */
static void abandon_file(ms_writer *w)
{
    if (w->file < 0)
        return;
    int *fdp = NULL;
    ms_h5_atomic_abandon(w->file);
    if (H5Fget_vfd_handle(w->file, H5P_DEFAULT, (void **)&fdp) >= 0 && fdp && *fdp >= 0) {
        int scratch = -1;
#ifdef MFD_CLOEXEC
        scratch = memfd_create("modesplit-abandoned", MFD_CLOEXEC);
#endif
        if (scratch < 0)
            scratch = open("/dev/null", O_RDWR | O_CLOEXEC);
        if (scratch >= 0) {
            dup2(scratch, *fdp);
            close(scratch);
        }
    }
    H5Fclose(w->file);
    H5Eclear2(H5E_DEFAULT);
    w->file = -1;
}

static uint64_t frame_bound_bytes(const ms_writer *w, int particles);

static ms_status check_layout(const ms_writer_layout *l)
{
    if (l->fields == 0)
        return ms_fail(MS_ERR_INVALID_ARGUMENT, "io: no fields to write (fields is 0)");
    if (l->fields & ~(unsigned)MS_IO_ALL_FIELDS)
        return ms_fail(MS_ERR_INVALID_ARGUMENT,
                       "io: fields 0x%x has bits other than MS_FIELD_COMBINED, _SURFACE, "
                       "_VOLUME and _PARTICLES",
                       l->fields);
    for (int i = 0; i < MS_IO_NFIELDS; ++i) {
        if (!(l->fields & (1u << i)))
            continue;
        const ms_grid *g = &l->grid[i];
        const char *n = ms_io_field_names[i];
        if (g->nx < 1 || g->nx > MS_IO_MAX_SIDE || g->ny < 1 || g->ny > MS_IO_MAX_SIDE)
            return ms_fail(MS_ERR_INVALID_ARGUMENT,
                           "io: field %s grid %d x %d cells is outside [1, %d] a side", n, g->nx,
                           g->ny, MS_IO_MAX_SIDE);
        if ((long)g->nx * g->ny > MS_IO_MAX_CELLS)
            return ms_fail(MS_ERR_INVALID_ARGUMENT,
                           "io: field %s grid %d x %d has more than %ld cells", n, g->nx, g->ny,
                           MS_IO_MAX_CELLS);
        if (!(g->dx > 0) || !(g->dy > 0) || !isfinite(g->dx) || !isfinite(g->dy))
            return ms_fail(MS_ERR_INVALID_ARGUMENT,
                           "io: field %s cell size %g x %g m must be finite and > 0", n,
                           (double)g->dx, (double)g->dy);
        if (!isfinite(g->origin[0]) || !isfinite(g->origin[1]))
            return ms_fail(MS_ERR_INVALID_ARGUMENT, "io: field %s origin must be finite", n);
    }
    if (!isfinite(l->frame_dt) || l->frame_dt < 0)
        return ms_fail(MS_ERR_INVALID_ARGUMENT, "io: frame_dt %g s must be finite and >= 0",
                       l->frame_dt);
    if (l->output_every < 1)
        return ms_fail(MS_ERR_INVALID_ARGUMENT, "io: output_every %d must be >= 1",
                       l->output_every);
    if (l->deflate < 0 || l->deflate > 9)
        return ms_fail(MS_ERR_INVALID_ARGUMENT,
                       "io: deflate level %d is outside 0 .. 9 (0 = no compression)", l->deflate);
    if (l->checkpoint_every < 0 || l->checkpoint_every > 1000000)
        return ms_fail(MS_ERR_INVALID_ARGUMENT,
                       "io: checkpoint_every %d is outside [0, 1000000] (0 = no checkpoints)",
                       l->checkpoint_every);
    if (l->floaters < 0 || l->floaters > 1 << 20)
        return ms_fail(MS_ERR_INVALID_ARGUMENT, "io: %d floaters is outside [0, %d]", l->floaters,
                       1 << 20);
    if (l->spray < 0 || l->spray > 1 << 20)
        return ms_fail(MS_ERR_INVALID_ARGUMENT, "io: a spray budget of %d is outside [0, %d]",
                       l->spray, 1 << 20);
    if (l->spray > 0 && (l->foam.nx < 1 || l->foam.ny < 1 || l->foam.nx > MS_IO_MAX_SIDE ||
                         l->foam.ny > MS_IO_MAX_SIDE || !(l->foam.dx > 0) || !(l->foam.dy > 0)))
        return ms_fail(MS_ERR_INVALID_ARGUMENT,
                       "io: the foam grid %d x %d of %g x %g m cells is not a grid; allowed: "
                       "1 to %d cells a side, cells > 0",
                       l->foam.nx, l->foam.ny, (double)l->foam.dx, (double)l->foam.dy,
                       MS_IO_MAX_SIDE);
    return MS_OK;
}

/* Height fields: shuffle + deflate at the scene's level (output.deflate,
 * default 1: fast, and it already takes most of what shuffle leaves), or
 * no filters at 0, where compression would cost more time than the
 * simulation (README, HDF5 layout). */
static int set_filters(hid_t dcpl, int deflate)
{
    if (deflate == 0)
        return 0;
    return H5Pset_shuffle(dcpl) >= 0 && H5Pset_deflate(dcpl, (unsigned)deflate) >= 0 ? 0 : -1;
}

static hid_t create_field(hid_t group, const char *name, const ms_grid *g, int deflate)
{
    hsize_t dims[3] = {0, (hsize_t)g->ny, (hsize_t)g->nx};
    hsize_t maxdims[3] = {H5S_UNLIMITED, (hsize_t)g->ny, (hsize_t)g->nx};
    hsize_t chunk[3] = {1, (hsize_t)g->ny, (hsize_t)g->nx};
    hid_t space = H5Screate_simple(3, dims, maxdims);
    hid_t dcpl = H5Pcreate(H5P_DATASET_CREATE);
    hid_t dapl = H5Pcreate(H5P_DATASET_ACCESS);
    hid_t d = -1;
    float fill = NAN; /* a frame without data reads as NaN, never as a flat 0 */
    if (space >= 0 && dcpl >= 0 && dapl >= 0 && H5Pset_chunk(dcpl, 3, chunk) >= 0 &&
        set_filters(dcpl, deflate) >= 0 && H5Pset_fill_value(dcpl, H5T_NATIVE_FLOAT, &fill) >= 0 &&
        H5Pset_chunk_cache(dapl, 0, 0, 1.0) >= 0) {
        d = H5Dcreate2(group, name, H5T_IEEE_F32LE, space, H5P_DEFAULT, dcpl, dapl);
        double dx[2] = {g->dx, g->dy};
        double origin[2] = {g->origin[0], g->origin[1]};
        if (d >= 0 && (ms_h5_attr_double(d, "dx", dx, 2) < 0 ||
                       ms_h5_attr_double(d, "origin", origin, 2) < 0 ||
                       ms_h5_attr_string(d, "units", "m") < 0 ||
                       ms_h5_attr_string(d, "axes", "frame,y,x") < 0)) {
            H5Dclose(d);
            d = -1;
        }
    }
    if (space >= 0)
        H5Sclose(space);
    if (dcpl >= 0)
        H5Pclose(dcpl);
    if (dapl >= 0)
        H5Pclose(dapl);
    return d;
}

/* An extendible dataset `name` below file of `rank` dimensions, the first
 * (frames) growing from 0, chunked as chunk, with a `units` attribute and
 * an optional fill value (of type `mtype`). */
static hid_t create_extendible(hid_t file, const char *name, hid_t ftype, int rank,
                               const hsize_t *chunk, const char *units, hid_t mtype,
                               const void *fill)
{
    hsize_t dims[3] = {0, 0, 0}, maxdims[3] = {H5S_UNLIMITED, 0, 0};
    for (int i = 1; i < rank; ++i)
        dims[i] = maxdims[i] = chunk[i];
    hid_t space = H5Screate_simple(rank, dims, maxdims);
    hid_t dcpl = H5Pcreate(H5P_DATASET_CREATE);
    hid_t d = -1;
    if (space >= 0 && dcpl >= 0 && H5Pset_chunk(dcpl, rank, chunk) >= 0 &&
        (!fill || H5Pset_fill_value(dcpl, mtype, fill) >= 0)) {
        d = H5Dcreate2(file, name, ftype, space, H5P_DEFAULT, dcpl, H5P_DEFAULT);
        if (d >= 0 && ms_h5_attr_string(d, "units", units) < 0) {
            H5Dclose(d);
            d = -1;
        }
    }
    if (space >= 0)
        H5Sclose(space);
    if (dcpl >= 0)
        H5Pclose(dcpl);
    return d;
}

static hid_t create_time(hid_t file)
{
    const hsize_t chunk[1] = {TIME_CHUNK};
    const double fill = NAN;
    return create_extendible(file, "time", H5T_IEEE_F64LE, 1, chunk, "s", H5T_NATIVE_DOUBLE, &fill);
}

/* /floaters: float32 [frame][n][3] (m), the floating objects (fig10's
 * leaves) as the sim moved them, 16 frames a chunk, no filters. */
static hid_t create_floaters(hid_t file, int n)
{
    const hsize_t chunk[3] = {16, (hsize_t)n, 3};
    return create_extendible(file, "floaters", H5T_IEEE_F32LE, 3, chunk, "m", -1, NULL);
}

/* Spray: /spray float32 [frame][budget][3] (m), the droplets in flight
 * in their first /spray_count[frame] rows and NaN past them (shuffle +
 * deflate take the NaN away), and the foam cover /foam float32
 * [frame][y][x] on its grid (attributes dx, origin as /fields). */
static int create_spray(ms_writer *w, const ms_writer_layout *l)
{
    const hsize_t chunk[3] = {1, (hsize_t)l->spray, 3}, nchunk[1] = {TIME_CHUNK};
    const float nan = NAN;
    const int zero = 0;
    hid_t dcpl = H5Pcreate(H5P_DATASET_CREATE);
    hsize_t dims[3] = {0, chunk[1], 3}, maxdims[3] = {H5S_UNLIMITED, chunk[1], 3};
    hid_t space = H5Screate_simple(3, dims, maxdims);
    if (dcpl >= 0 && space >= 0 && H5Pset_chunk(dcpl, 3, chunk) >= 0 &&
        set_filters(dcpl, MS_MAX(l->deflate, 1)) >= 0 &&
        H5Pset_fill_value(dcpl, H5T_NATIVE_FLOAT, &nan) >= 0) {
        w->spray_dset =
            H5Dcreate2(w->file, "spray", H5T_IEEE_F32LE, space, H5P_DEFAULT, dcpl, H5P_DEFAULT);
        if (w->spray_dset >= 0 && ms_h5_attr_string(w->spray_dset, "units", "m") < 0) {
            H5Dclose(w->spray_dset);
            w->spray_dset = -1;
        }
    }
    if (dcpl >= 0)
        H5Pclose(dcpl);
    if (space >= 0)
        H5Sclose(space);
    if (w->spray_dset < 0)
        return -1;
    w->spray_n_dset = create_extendible(w->file, "spray_count", H5T_STD_I32LE, 1, nchunk, "",
                                        H5T_NATIVE_INT, &zero);
    w->foam_dset = create_field(w->file, "foam", &l->foam, l->deflate);
    if (w->spray_n_dset < 0 || w->foam_dset < 0 ||
        ms_h5_attr_string(w->foam_dset, "meaning", "foam cover in [0, 1]") < 0)
        return -1;
    /* /spray_id: 0 .. budget-1, the vertex cells of the spray (xdmf.c) */
    int *ids = ms_alloc_array((size_t)l->spray, sizeof *ids);
    hsize_t n[1] = {(hsize_t)l->spray};
    hid_t s1 = ids ? H5Screate_simple(1, n, NULL) : -1;
    hid_t d = s1 >= 0 ? H5Dcreate2(w->file, "spray_id", H5T_STD_I32LE, s1, H5P_DEFAULT, H5P_DEFAULT,
                                   H5P_DEFAULT)
                      : -1;
    for (int i = 0; ids && i < l->spray; ++i)
        ids[i] = i;
    herr_t e = d >= 0 ? H5Dwrite(d, H5T_NATIVE_INT, H5S_ALL, H5S_ALL, H5P_DEFAULT, ids) : -1;
    if (d >= 0)
        H5Dclose(d);
    if (s1 >= 0)
        H5Sclose(s1);
    ms_free(ids);
    return e < 0 ? -1 : 0;
}

/* Root attributes, datasets and the `frames` attribute of a new file. */
static int create_checkpoints(ms_writer *w);

static int write_layout(ms_writer *w, const ms_writer_layout *l)
{
    hid_t f = w->file;
    double frame_dt = l->frame_dt;
    if (ms_h5_attr_string(f, "format", MS_FILE_FORMAT) < 0 ||
        ms_h5_attr_int64(f, "format_version", MS_FILE_FORMAT_VERSION) < 0 ||
        ms_h5_attr_string(f, "library_version", ms_version()) < 0 ||
        ms_h5_attr_string(f, "scene", l->scene_text ? l->scene_text : "") < 0 ||
        ms_h5_attr_string(f, "scene_name", l->scene_name ? l->scene_name : "") < 0 ||
        ms_h5_attr_double(f, "frame_dt", &frame_dt, 1) < 0 ||
        ms_h5_attr_int64(f, "output_every", l->output_every) < 0 ||
        ms_h5_attr_int64(f, "frames", 0) < 0)
        return -1;
    if (l->fields & MS_IO_HEIGHT_FIELDS) {
        hid_t g = H5Gcreate2(f, "fields", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
        if (g < 0)
            return -1;
        for (int i = 0; i < MS_IO_NFIELDS; ++i) {
            if (!(l->fields & (1u << i)))
                continue;
            w->dset[i] = create_field(g, ms_io_field_names[i], &l->grid[i], l->deflate);
            if (w->dset[i] < 0) {
                H5Gclose(g);
                return -1;
            }
        }
        if (H5Gclose(g) < 0)
            return -1;
    }
    if (l->fields & MS_FIELD_PARTICLES) {
        hid_t g = H5Gcreate2(f, "particles", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
        if (g < 0 || H5Gclose(g) < 0)
            return -1;
    }
    w->time_dset = create_time(f);
    if (w->time_dset < 0)
        return -1;
    if (l->floaters > 0 && (w->floater_dset = create_floaters(f, l->floaters)) < 0)
        return -1;
    if (l->spray > 0 && create_spray(w, l) < 0)
        return -1;
    if (l->checkpoint_every > 0 && !create_checkpoints(w))
        return -1;
    w->frames_attr = H5Aopen(f, "frames", H5P_DEFAULT);
    if (w->frames_attr < 0)
        return -1;
    return H5Fflush(f, H5F_SCOPE_GLOBAL) < 0 ? -1 : 0;
}

/* Before HDF5 sees the path: create it and make sure it takes a write.
 * HDF5 cannot close a file whose very first flush fails (it keeps it open
 * inside and prints when the program exits), so an unwritable path, a
 * device that refuses writes (/dev/full) or a full disk is caught here,
 * with the system's reason; sentences name `shown` (the run's path, when
 * path is its "<path>.part"). */
static ms_status probe_path(const char *path, const char *shown, const ms_writer_layout *l)
{
    int fd = open(path, O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0666);
    if (fd < 0)
        return ms_fail(MS_ERR_IO, "io: cannot create %s: %s", shown, strerror(errno));
    static const char zeros[4096];
    struct stat sb;
    int regular = fstat(fd, &sb) == 0 && S_ISREG(sb.st_mode);
    ms_status st = MS_OK;
    struct statvfs vb;
    if (regular && fstatvfs(fd, &vb) == 0) {
        ms_writer probe = {0};
        probe.layout = *l;
        uint64_t need = frame_bound_bytes(&probe, 0) + META_SLACK_BYTES;
        uint64_t blocks = geteuid() == 0 ? (uint64_t)vb.f_bfree : (uint64_t)vb.f_bavail;
        uint64_t free_bytes = blocks * (uint64_t)vb.f_frsize;
        if (free_bytes < need)
            st = ms_fail(MS_ERR_IO,
                         "io: cannot create %s: its file system has %.2f MB free, the layout "
                         "and a first frame need up to %.2f MB",
                         shown, free_bytes / 1e6, need / 1e6);
    }
    for (int i = 0; i < 16 && st == MS_OK; ++i)
        if (pwrite(fd, zeros, sizeof zeros, (off_t)i * (off_t)sizeof zeros) !=
            (ssize_t)sizeof zeros)
            st = ms_fail(MS_ERR_IO, "io: cannot write %s: %s", shown,
                         errno ? strerror(errno) : "short write");
    if (regular && ftruncate(fd, 0) != 0 && st == MS_OK)
        st = ms_fail(MS_ERR_IO, "io: cannot write %s: %s", shown, strerror(errno));
    close(fd);
    if (st != MS_OK && regular)
        unlink(path);
    return st;
}

/* An output never overwrites an input: none of the names this writer
 * writes (the run file, its two XDMF sidecars, and the temporary names
 * each is made under: ".part", ".before", ".tmp") may be the scene's own
 * file, whatever the spelling (the same device and inode; a name that
 * does not exist yet cannot be it). Checked before anything is created. */
static ms_status check_not_input(const ms_writer *w, const char *scene)
{
    struct stat in, sb;
    if (!scene || !scene[0] || stat(scene, &in) != 0)
        return MS_OK;
    const char *const base[3] = {w->path, w->xmf_path, w->xmf2_path};
    static const char *const what[3] = {"the run file", "the XDMF sidecar of",
                                        "the legacy XDMF sidecar of"};
    static const char *const suffix[] = {"", ".part", ".before", ".part.before", ".tmp"};
    for (int b = 0; b < 3; ++b)
        for (size_t k = 0; k < sizeof suffix / sizeof suffix[0]; ++k) {
            size_t n = strlen(base[b]) + strlen(suffix[k]) + 1;
            char *name = ms_malloc(n);
            if (!name)
                return ms_fail(MS_ERR_OUT_OF_MEMORY, "io: out of memory for the writer");
            snprintf(name, n, "%s%s", base[b], suffix[k]);
            int same = stat(name, &sb) == 0 && sb.st_dev == in.st_dev && sb.st_ino == in.st_ino;
            ms_status st = MS_OK;
            if (same)
                st = ms_fail(MS_ERR_INVALID_ARGUMENT,
                             "io: %s, %s%s%s%s, is the scene file %s: an output never "
                             "overwrites an input; choose another output name",
                             name, what[b], b ? " " : "", b ? w->path : "",
                             k ? " (a temporary name of it)" : "", scene);
            ms_free(name);
            if (st != MS_OK)
                return st;
        }
    return MS_OK;
}

/* One writer per run file: an exclusive advisory lock (flock) on the
 * file's inode, held until the writer is freed. A second writer of the
 * same file (a --resume of a run still going, two resumes at once) is
 * refused before it changes anything, instead of both writing HDF5
 * metadata into one file. `name` is opened without truncating it (with
 * `create`, made if missing); names that are not regular files (a
 * device) are not locked. hold: keep the lock in *fd, else only test it. */
static ms_status lock_file(const char *name, const char *shown, int create, int hold, int *fd)
{
    *fd = -1;
    int f = open(name, (hold ? O_RDWR : O_RDONLY) | O_CLOEXEC | (create ? O_CREAT : 0), 0666);
    struct stat sb;
    if (f < 0 || fstat(f, &sb) != 0 || !S_ISREG(sb.st_mode)) {
        if (f >= 0)
            close(f);
        return MS_OK; /* nothing to lock: opening it reports why, if it matters */
    }
    if (flock(f, LOCK_EX | LOCK_NB) != 0) {
        int e = errno;
        close(f);
        if (e == EWOULDBLOCK)
            return ms_fail(MS_ERR_STATE,
                           "io: %s is being written by another process (it holds the file's "
                           "lock); one writer per run file: wait until it ends, or write "
                           "another file",
                           shown);
        return MS_OK; /* a file system without flock: no lock, as before */
    }
    if (hold)
        *fd = f;
    else
        close(f);
    return MS_OK;
}

/* The run file and its sidecars are regular files or not there yet: a FIFO
 * would block the open for good, a device would take the probe's zeros (a
 * disk's first blocks) and a sidecar's rename would replace a device's
 * node. Refused before anything is opened; a symbolic link to a regular
 * file is written through. */
static ms_status check_regular(const ms_writer *w)
{
    const char *const names[3] = {w->path, w->xmf_path, w->xmf2_path};
    for (int i = 0; i < 3; ++i) {
        struct stat sb;
        if (stat(names[i], &sb) == 0 && !S_ISREG(sb.st_mode))
            return ms_fail(MS_ERR_IO,
                           "io: cannot write %s: it is %s, not a regular file (a run file and its "
                           "XDMF sidecars are written as regular files only)",
                           names[i], ms_file_kind(sb.st_mode));
    }
    return MS_OK;
}

/* The set-up both openers share: the arguments checked (*out = NULL) and
 * a writer of layout l for path with no file open yet (strings of the
 * layout not kept) in *wp. */
static ms_status writer_new(const char *path, const ms_writer_layout *l, ms_writer **out,
                            ms_writer **wp)
{
    ms_status st;
    if ((st = ms_check_not_null("io", "out", out)) != MS_OK)
        return st;
    *out = NULL;
    if ((st = ms_check_not_null("io", "path", path)) != MS_OK ||
        (st = ms_check_not_null("io", "layout", l)) != MS_OK)
        return st;
    if (!path[0])
        return ms_fail(MS_ERR_INVALID_ARGUMENT, "io: the output path is empty");
    if ((st = check_layout(l)) != MS_OK)
        return st;
    ms_writer *w = ms_alloc_array(1, sizeof *w);
    if (!w)
        return ms_fail(MS_ERR_OUT_OF_MEMORY, "io: out of memory for the writer");
    w->file = w->time_dset = w->frames_attr = w->floater_dset = -1;
    w->spray_dset = w->spray_n_dset = w->foam_dset = -1;
    w->lock_fd = -1;
    for (int i = 0; i < MS_IO_NFIELDS; ++i)
        w->dset[i] = -1;
    for (int i = 0; i < MS_IO_CHECKPOINTS; ++i) {
        w->ckpt[i] = -1;
        w->ckpt_frame[i] = -1;
    }
    w->layout = *l;
    w->layout.scene_text = w->layout.scene_name = w->layout.scene_path = NULL;
    w->path = ms_strdup(path);
    w->xmf_path = ms_xdmf_path_for(path);
    w->xmf2_path = ms_xdmf_legacy_path_for(path);
    if (!w->path || !w->xmf_path || !w->xmf2_path) {
        free_writer(w);
        return ms_fail(MS_ERR_OUT_OF_MEMORY, "io: out of memory for the writer");
    }
    if ((st = check_not_input(w, l->scene_path)) != MS_OK || (st = check_regular(w)) != MS_OK) {
        free_writer(w);
        return st;
    }
    *wp = w;
    return MS_OK;
}

ms_status ms_writer_existing_layout(const char *path, const ms_writer_layout *l, char *name,
                                    size_t size, int *exists)
{
    ms_status st;
    if ((st = ms_check_not_null("io", "exists", exists)) != MS_OK)
        return st;
    *exists = 0;
    if ((st = ms_check_not_null("io", "name", name)) != MS_OK)
        return st;
    if (size == 0)
        return ms_fail(MS_ERR_INVALID_ARGUMENT, "io: the name buffer has no room");
    name[0] = '\0';
    /* the opener's own refusals first: an input of the scene or a file
     * that is not regular is never replaced, --force or not */
    ms_writer *w = NULL, *unused;
    if ((st = writer_new(path, l, &unused, &w)) != MS_OK)
        return st;
    const char *const names[3] = {w->path, w->xmf_path, w->xmf2_path};
    for (int i = 0; i < 3 && !*exists; ++i) {
        struct stat sb;
        if (lstat(names[i], &sb) == 0) {
            *exists = 1;
            snprintf(name, size, "%s", names[i]);
        }
    }
    free_writer(w);
    return MS_OK;
}

/* Where a new run file is made: "<path>.part", renamed over path once the
 * layout's first flush is on disk. A kill before that rename leaves path
 * as it was (an older run there stays whole) instead of a file that does
 * not open; HDF5's first flush writes blocks that point into each other,
 * and before it nothing committed could guard them (h5_atomic.c). NULL
 * (write path itself, in place) when path is not a plain file (a symbolic
 * link, which is written through; writer_new refused the rest), is a file this process may
 * not write, or its folder takes no new file: the probe then reports why
 * with path's name. *oom: out of memory. */
static char *part_path_for(const char *path, int *oom)
{
    *oom = 0;
    struct stat sb;
    if (lstat(path, &sb) == 0 && (!S_ISREG(sb.st_mode) || access(path, W_OK) != 0))
        return NULL;
    const char *slash = strrchr(path, '/');
    char *dir =
        slash ? ms_strndup(path, slash == path ? 1 : (size_t)(slash - path)) : ms_strdup(".");
    if (!dir) {
        *oom = 1;
        return NULL;
    }
    int writable = access(dir, W_OK | X_OK) == 0;
    ms_free(dir);
    if (!writable)
        return NULL;
    size_t n = strlen(path);
    char *part = ms_malloc(n + 6);
    if (!part) {
        *oom = 1;
        return NULL;
    }
    memcpy(part, path, n);
    memcpy(part + n, ".part", 6);
    return part;
}

ms_status ms_writer_open_layout(const char *path, const ms_writer_layout *l, ms_writer **out)
{
    ms_writer *w = NULL;
    ms_status st = writer_new(path, l, out, &w);
    if (st != MS_OK)
        return st;

    int oom, unused;
    char *part = part_path_for(path, &oom);
    const char *made = part ? part : path; /* the name HDF5 creates */
    if (oom)
        st = ms_fail(MS_ERR_OUT_OF_MEMORY, "io: out of memory for the writer");
    /* a run file another writer holds is not replaced (the .part renamed
     * over it), nor is a .part another writer is making truncated; the
     * lock taken on `made` moves with it to path at the rename */
    else if (part && (st = lock_file(path, path, 0, 0, &unused)) == MS_OK)
        st = lock_file(made, path, 1, 1, &w->lock_fd);
    else if (!part)
        st = lock_file(made, path, 0, 1, &w->lock_fd);
    if (st == MS_OK)
        st = probe_path(made, path, l);
    if (st != MS_OK) {
        ms_free(part);
        free_writer(w);
        return st;
    }
    ms_h5_quiet q;
    ms_h5_hush(&q);
    hid_t fapl = ms_h5_fapl_atomic();
    hid_t fcpl = H5Pcreate(H5P_FILE_CREATE);
    if (fapl < 0 || fcpl < 0 ||
        H5Pset_file_space_strategy(fcpl, H5F_FSPACE_STRATEGY_NONE, 0, 1) < 0 ||
        H5Pset_istore_k(fcpl, CHUNK_BTREE_K) < 0) {
        st = ms_h5_fail(MS_ERR_IO, "io: cannot set up HDF5 for %s", path);
    } else {
        w->file = H5Fcreate(made, H5F_ACC_TRUNC, fcpl, fapl);
        if (w->file < 0)
            st = ms_h5_fail(MS_ERR_IO, "io: cannot create %s", path);
        else if (write_layout(w, l) < 0)
            st = ms_h5_fail(MS_ERR_IO, "io: cannot write the layout of %s", path);
        else if (part && rename(part, path) != 0)
            st = ms_fail(MS_ERR_IO, "io: cannot rename %s to %s: %s", part, path, strerror(errno));
        else if (part) {
            ms_h5_atomic_renamed(w->file, path);
            made = path;
        }
    }
    if (fapl >= 0)
        H5Pclose(fapl);
    if (fcpl >= 0)
        H5Pclose(fcpl);
    if (st == MS_OK) {
        /* The sidecar names the HDF5 file relative to itself. */
        const char *slash = strrchr(path, '/');
        st = ms_xdmf_open(w->xmf_path, slash ? slash + 1 : path, &w->layout, 0, &w->xdmf);
        if (st == MS_OK)
            st = ms_xdmf_open(w->xmf2_path, slash ? slash + 1 : path, &w->layout, 1, &w->xdmf2);
        if (st != MS_OK) {
            ms_xdmf_close(w->xdmf);
            w->xdmf = NULL;
            unlink(w->xmf_path);
        }
    }
    if (st != MS_OK) {
        close_handles(w);
        if (w->file >= 0) {
            /* a file that holds no frame is no use: remove it, if it is one */
            struct stat sb;
            int *fdp = NULL;
            if (H5Fget_vfd_handle(w->file, H5P_DEFAULT, (void **)&fdp) >= 0 && fdp &&
                fstat(*fdp, &sb) == 0 && S_ISREG(sb.st_mode))
                unlink(made);
            abandon_file(w);
        } else if (part)
            unlink(part); /* the probe's empty file */
        H5Eclear2(H5E_DEFAULT);
        ms_h5_loud(&q);
        ms_free(part);
        free_writer(w);
        return st;
    }
    ms_free(part);
    ms_h5_loud(&q);
    *out = w;
    return MS_OK;
}

static uint64_t frame_bound_bytes(const ms_writer *w, int particles)
{
    uint64_t raw = 0;
    for (int i = 0; i < MS_IO_NFIELDS; ++i)
        if (w->layout.fields & (1u << i))
            raw += (uint64_t)w->layout.grid[i].nx * (uint64_t)w->layout.grid[i].ny * 4u;
    if (w->layout.fields & MS_FIELD_PARTICLES)
        raw += (uint64_t)particles * 13u * 4u; /* H5Part 6 + id + [n][3] twice */
    raw += w->ckpt_pending + (uint64_t)w->layout.floaters * 12u;
    if (w->layout.spray > 0)
        raw += (uint64_t)w->layout.spray * 12u + 4u +
               (uint64_t)w->layout.foam.nx * (uint64_t)w->layout.foam.ny * 4u;
    /* deflate can grow incompressible data a little */
    return raw + raw / 64 + META_SLACK_BYTES;
}

/* Refuse a frame that cannot fit, before touching the file. */
static ms_status check_space(const ms_writer *w, int particles)
{
    int *fdp = NULL;
    if (H5Fget_vfd_handle(w->file, H5P_DEFAULT, (void **)&fdp) < 0 || !fdp) {
        H5Eclear2(H5E_DEFAULT);
        return MS_OK; /* not a plain file: let the write report */
    }
    uint64_t need = frame_bound_bytes(w, particles);
    struct stat sb;
    struct statvfs vb;
    if (fstat(*fdp, &sb) != 0 || !S_ISREG(sb.st_mode))
        return MS_OK;
    char holds[64];
    if (w->frames > 0)
        snprintf(holds, sizeof holds, "frames 0-%ld", w->frames - 1);
    else
        snprintf(holds, sizeof holds, "no frame yet");
    if (fstatvfs(*fdp, &vb) == 0) {
        uint64_t blocks = geteuid() == 0 ? (uint64_t)vb.f_bfree : (uint64_t)vb.f_bavail;
        uint64_t free_bytes = blocks * (uint64_t)vb.f_frsize;
        /* and the copy of run.xmf (xdmf.c: ms_xdmf_prepare), assumed on
         * the same file system */
        uint64_t copy = ms_xdmf_copy_bytes(w->xdmf);
        if (free_bytes < need + copy)
            return ms_fail(MS_ERR_IO,
                           "io: frame %ld needs up to %.2f MB but only %.2f MB are free on the "
                           "file system of %s; stopped before writing it (the file holds %s)",
                           w->frames, (need + copy) / 1e6, free_bytes / 1e6, w->path, holds);
    }
    struct rlimit rl;
    if (getrlimit(RLIMIT_FSIZE, &rl) == 0 && rl.rlim_cur != RLIM_INFINITY &&
        (uint64_t)sb.st_size + need > (uint64_t)rl.rlim_cur)
        return ms_fail(MS_ERR_IO,
                       "io: frame %ld needs up to %.2f MB but the file size limit (ulimit -f) "
                       "leaves %.2f MB for %s; stopped before writing it (the file holds %s)",
                       w->frames, need / 1e6,
                       ((uint64_t)rl.rlim_cur > (uint64_t)sb.st_size
                            ? (double)((uint64_t)rl.rlim_cur - (uint64_t)sb.st_size)
                            : 0.0) /
                           1e6,
                       w->path, holds);
    return MS_OK;
}

/* Flush with the superblock's EOA moved ahead first (eoa_guard.c). */
static int commit(ms_writer *w)
{
    if (!ms_h5_atomic_active(w->file) && ms_h5_guard_eoa(w->file) != MS_OK)
        return 0;
    return H5Fflush(w->file, H5F_SCOPE_GLOBAL) >= 0;
}

static herr_t append_rows(hid_t d, long frame, const void *buf, hid_t mtype, int rank,
                          const hsize_t *row_dims)
{
    hsize_t dims[3], start[3] = {0, 0, 0}, count[3];
    dims[0] = (hsize_t)frame + 1;
    start[0] = (hsize_t)frame;
    count[0] = 1;
    for (int i = 1; i < rank; ++i)
        dims[i] = count[i] = row_dims[i - 1];
    if (H5Dset_extent(d, dims) < 0)
        return -1;
    hid_t fs = H5Dget_space(d);
    hid_t ms = H5Screate_simple(rank, count, NULL);
    herr_t st = -1;
    if (fs >= 0 && ms >= 0 &&
        H5Sselect_hyperslab(fs, H5S_SELECT_SET, start, NULL, count, NULL) >= 0)
        st = H5Dwrite(d, mtype, ms, fs, H5P_DEFAULT, buf);
    if (fs >= 0)
        H5Sclose(fs);
    if (ms >= 0)
        H5Sclose(ms);
    return st;
}

#define CKPT_CHUNK (256u * 1024u) /* bytes per chunk of a checkpoint blob */

/* Create /checkpoint and its two empty slots (attribute frame = -1).
 * Done with the layout when checkpoints are asked for, so that no frame's
 * flush adds a link to the root group. 0 on an HDF5 error. */
static int create_checkpoints(ms_writer *w)
{
    hid_t f = w->file;
    if (H5Lexists(f, "checkpoint", H5P_DEFAULT) <= 0) {
        hid_t g = H5Gcreate2(f, "checkpoint", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
        if (g < 0 || H5Gclose(g) < 0)
            return 0;
    }
    for (int s = 0; s < MS_IO_CHECKPOINTS; ++s) {
        if (w->ckpt[s] >= 0)
            continue;
        char name[32];
        snprintf(name, sizeof name, "checkpoint/%d", s);
        hsize_t dims[1] = {0}, maxd[1] = {H5S_UNLIMITED}, chunk[1] = {CKPT_CHUNK};
        hid_t sp = H5Screate_simple(1, dims, maxd), dcpl = H5Pcreate(H5P_DATASET_CREATE);
        /* chunks without filters are rewritten in place, and the dataset
         * only grows (attribute bytes says how much of it is the blob), so
         * a checkpoint changes no chunk index once the slots are large
         * enough, and the file does not grow per checkpoint */
        if (sp >= 0 && dcpl >= 0 && H5Pset_chunk(dcpl, 1, chunk) >= 0)
            w->ckpt[s] = H5Dcreate2(f, name, H5T_NATIVE_UCHAR, sp, H5P_DEFAULT, dcpl, H5P_DEFAULT);
        if (sp >= 0)
            H5Sclose(sp);
        if (dcpl >= 0)
            H5Pclose(dcpl);
        if (w->ckpt[s] < 0 || ms_h5_attr_int64(w->ckpt[s], "frame", -1) < 0 ||
            ms_h5_attr_int64(w->ckpt[s], "bytes", 0) < 0)
            return 0;
    }
    return 1;
}

static int set_int64(hid_t obj, const char *name, int64_t v)
{
    hid_t a = H5Aopen(obj, name, H5P_DEFAULT);
    int ok = a >= 0 && H5Awrite(a, H5T_NATIVE_INT64, &v) >= 0;
    if (a >= 0)
        H5Aclose(a);
    return ok;
}

/* Write blob into the older checkpoint slot, marked as frame k; not yet
 * flushed (the frame's first commit takes it). 0 on an HDF5 error. */
static int write_checkpoint(ms_writer *w, long k, const void *blob, size_t bytes)
{
    int s = w->ckpt_frame[0] <= w->ckpt_frame[1] ? 0 : 1;
    if (w->ckpt[s] < 0 && !create_checkpoints(w))
        return 0;
    hsize_t dims[1] = {bytes}, have = 0;
    hid_t sp = H5Dget_space(w->ckpt[s]);
    int ok = sp >= 0 && H5Sget_simple_extent_dims(sp, &have, NULL) == 1;
    if (sp >= 0)
        H5Sclose(sp);
    if (ok && have < bytes)
        ok = H5Dset_extent(w->ckpt[s], dims) >= 0;
    hid_t ms = ok ? H5Screate_simple(1, dims, NULL) : -1, fs = ok ? H5Dget_space(w->ckpt[s]) : -1;
    hsize_t start[1] = {0};
    ok = ok && ms >= 0 && fs >= 0 &&
         H5Sselect_hyperslab(fs, H5S_SELECT_SET, start, NULL, dims, NULL) >= 0 &&
         H5Dwrite(w->ckpt[s], H5T_NATIVE_UCHAR, ms, fs, H5P_DEFAULT, blob) >= 0 &&
         set_int64(w->ckpt[s], "bytes", (int64_t)bytes) && set_int64(w->ckpt[s], "frame", k);
    if (ms >= 0)
        H5Sclose(ms);
    if (fs >= 0)
        H5Sclose(fs);
    if (ok)
        w->ckpt_frame[s] = k;
    return ok;
}

ms_status ms_writer_set_checkpoint_every(ms_writer *w, int every)
{
    ms_status st = ms_check_not_null("io", "writer", w);
    if (st != MS_OK)
        return st;
    if (every < 0 || every > 1000000)
        return ms_fail(MS_ERR_INVALID_ARGUMENT,
                       "io: checkpoint_every %d is outside [0, 1000000] (0 = no checkpoints)",
                       every);
    w->layout.checkpoint_every = every;
    return MS_OK;
}

void *ms_writer_checkpoint_buffer(ms_writer *w, size_t bytes)
{
    if (bytes > w->ckpt_cap) {
        void *p = ms_malloc(bytes + bytes / 8);
        if (!p)
            return NULL;
        ms_free(w->ckpt_buf);
        w->ckpt_buf = p;
        w->ckpt_cap = bytes + bytes / 8;
    }
    return w->ckpt_buf;
}

static ms_status check_data(const ms_writer *w, const ms_writer_data *d)
{
    if (!isfinite(d->time))
        return ms_fail(MS_ERR_INVALID_ARGUMENT, "io: frame time %g s is not finite", d->time);
    for (int i = 0; i < MS_IO_NFIELDS; ++i)
        if ((w->layout.fields & (1u << i)) && !d->field[i])
            return ms_fail(MS_ERR_INVALID_ARGUMENT, "io: field %s has no data for frame %ld",
                           ms_io_field_names[i], w->frames);
    if (w->layout.fields & MS_FIELD_PARTICLES) {
        if (d->particles < 0 || d->particles > MS_IO_MAX_PARTICLES)
            return ms_fail(MS_ERR_INVALID_ARGUMENT, "io: particle count %d is outside [0, %ld]",
                           d->particles, MS_IO_MAX_PARTICLES);
        for (int k = 0; k < 3 && d->particles > 0; ++k)
            if (!d->pos[k] || !d->vel[k])
                return ms_fail(MS_ERR_INVALID_ARGUMENT,
                               "io: %d particles but a position or velocity array is NULL",
                               d->particles);
    }
    if (w->layout.floaters > 0 && !d->floaters)
        return ms_fail(MS_ERR_INVALID_ARGUMENT, "io: %d floaters but no positions for frame %ld",
                       w->layout.floaters, w->frames);
    if (w->layout.spray > 0) {
        if (d->spray < 0 || d->spray > w->layout.spray)
            return ms_fail(MS_ERR_INVALID_ARGUMENT,
                           "io: %d spray droplets in frame %ld, outside [0, %d] (the budget)",
                           d->spray, w->frames, w->layout.spray);
        if ((d->spray > 0 && !d->spray_xyz) || !d->foam)
            return ms_fail(MS_ERR_INVALID_ARGUMENT,
                           "io: frame %ld has no spray positions or no foam", w->frames);
    }
    return MS_OK;
}

ms_status ms_writer_write(ms_writer *w, const ms_writer_data *d)
{
    ms_status st;
    if ((st = ms_check_not_null("io", "writer", w)) != MS_OK ||
        (st = ms_check_not_null("io", "frame data", d)) != MS_OK)
        return st;
    if (w->failed)
        return ms_fail(MS_ERR_STATE,
                       "io: the writer of %s stopped after a write error; close it (the file "
                       "keeps its %ld frames)",
                       w->path, w->frames);
    if ((st = check_data(w, d)) != MS_OK)
        return st;
    ms_h5_quiet q;
    ms_h5_hush(&q);
    w->ckpt_pending = d->checkpoint ? d->checkpoint_bytes : 0;
    st = w->no_space_check ? MS_OK : check_space(w, d->particles);
    if (st != MS_OK) {
        ms_h5_loud(&q);
        return st;
    }
    long k = w->frames;
    int particles = (w->layout.fields & MS_FIELD_PARTICLES) ? d->particles : 0;
    /* 0: run.xmf's next state, renamed in after the commit (xdmf.c) */
    ms_xdmf_set_spray(w->xdmf, w->layout.spray > 0 ? d->spray : 0);
    ms_xdmf_set_spray(w->xdmf2, w->layout.spray > 0 ? d->spray : 0);
    if ((st = ms_xdmf_prepare(w->xdmf, k, d->time, particles)) != MS_OK) {
        ms_h5_loud(&q);
        return st;
    }
    int ok = 1;
    hid_t step = -1, xyz = -1;
    for (int i = 0; i < MS_IO_NFIELDS && ok; ++i) {
        if (!(w->layout.fields & (1u << i)))
            continue;
        hsize_t row[2] = {(hsize_t)w->layout.grid[i].ny, (hsize_t)w->layout.grid[i].nx};
        ok = append_rows(w->dset[i], k, d->field[i], H5T_NATIVE_FLOAT, 3, row) >= 0;
    }
    if (ok && (w->layout.fields & MS_FIELD_PARTICLES))
        ok = ms_h5part_write_step(w->file, d->time, particles, d->pos, d->vel, &step) == MS_OK &&
             ms_h5part_write_xyz(w->file, particles, d->pos, d->vel, &xyz) == MS_OK;
    if (ok)
        ok = append_rows(w->time_dset, k, &d->time, H5T_NATIVE_DOUBLE, 1, NULL) >= 0;
    if (ok && w->floater_dset >= 0) {
        hsize_t row[2] = {(hsize_t)w->layout.floaters, 3};
        ok = append_rows(w->floater_dset, k, d->floaters, H5T_NATIVE_FLOAT, 3, row) >= 0;
    }
    if (ok && w->spray_dset >= 0) {
        const size_t used = 3 * (size_t)d->spray, all = 3 * (size_t)w->layout.spray;
        if (!w->spray_rows && !(w->spray_rows = ms_alloc_array(all, sizeof(float))))
            ok = 0;
        if (ok) {
            if (used)
                memcpy(w->spray_rows, d->spray_xyz, used * sizeof(float));
            for (size_t i = used; i < all; ++i)
                w->spray_rows[i] = NAN;
        }
        hsize_t row[2] = {(hsize_t)w->layout.spray, 3};
        hsize_t frow[2] = {(hsize_t)w->layout.foam.ny, (hsize_t)w->layout.foam.nx};
        ok = ok && append_rows(w->spray_dset, k, w->spray_rows, H5T_NATIVE_FLOAT, 3, row) >= 0 &&
             append_rows(w->spray_n_dset, k, &d->spray, H5T_NATIVE_INT, 1, NULL) >= 0 &&
             append_rows(w->foam_dset, k, d->foam, H5T_NATIVE_FLOAT, 3, frow) >= 0;
    }
    if (ok && d->checkpoint && d->checkpoint_bytes > 0)
        ok = write_checkpoint(w, k, d->checkpoint, d->checkpoint_bytes);
    /* 1: the frame's data, its checkpoint and its (still unlinked) particle step */
    if (ok)
        ok = commit(w);
    /* 2: link the step and raise `frames` */
    int64_t committed = k + 1;
    if (ok && step >= 0)
        ok = ms_h5part_link_step(w->file, step, k) == MS_OK;
    if (ok && xyz >= 0)
        ok = ms_h5part_link_xyz(w->file, xyz, k) == MS_OK;
    /* The links reach the disk in a flush of their own before `frames` is
     * raised: inside one flush HDF5 writes its dirty metadata in no set
     * order, so a kill there could leave `frames` counting a step whose
     * link never landed (seen under load: particle_count -> MS_ERR_PARSE). */
    if (ok && (step >= 0 || xyz >= 0))
        ok = commit(w);
    if (ok)
        ok = H5Awrite(w->frames_attr, H5T_NATIVE_INT64, &committed) >= 0 && commit(w);
    if (step >= 0 && H5Gclose(step) < 0)
        ok = 0;
    if (xyz >= 0 && H5Gclose(xyz) < 0)
        ok = 0;
    if (!ok) {
        w->failed = 1;
        st = ms_h5_fail(MS_ERR_IO, "io: writing frame %ld to %s failed", k, w->path);
        ms_h5_loud(&q);
        return st;
    }
    ms_h5_loud(&q);
    w->frames = k + 1;
    st = ms_xdmf_frame(w->xdmf, k, d->time, particles);
    if (st == MS_OK)
        st = ms_xdmf_frame(w->xdmf2, k, d->time, particles);
    if (st != MS_OK)
        w->failed = 1;
    return st;
}

ms_status ms_writer_close(ms_writer *w)
{
    if (!w)
        return MS_OK;
    ms_status st = MS_OK;
    ms_h5_quiet q;
    ms_h5_hush(&q);
    close_handles(w);
    if (w->failed)
        abandon_file(w); /* the frames committed before stay as they are */
    else if (w->file >= 0 && H5Fclose(w->file) < 0)
        st = ms_h5_fail(MS_ERR_IO, "io: closing %s failed", w->path);
    w->file = -1;
    H5Eclear2(H5E_DEFAULT);
    ms_h5_loud(&q);
    ms_status xs = ms_xdmf_close(w->xdmf);
    if (st == MS_OK)
        st = xs;
    xs = ms_xdmf_close(w->xdmf2);
    if (st == MS_OK)
        st = xs;
    free_writer(w);
    return st;
}

long ms_writer_frames(const ms_writer *w)
{
    return w ? w->frames : 0;
}

const char *ms_writer_xdmf_path(const ms_writer *w)
{
    return w ? w->xmf_path : "";
}

const char *ms_writer_xdmf_legacy_path(const ms_writer *w)
{
    return w ? w->xmf2_path : "";
}

void ms_writer_skip_space_check(ms_writer *w)
{
    w->no_space_check = 1;
}

const ms_writer_layout *ms_writer_get_layout(const ms_writer *w)
{
    return &w->layout;
}

/* ---- reopening a run file to append to it (resume) ------------------- */

/* Line `line` (1-based) of s, at most n bytes, into buf. */
static void text_line(const char *s, int line, char *buf, size_t n)
{
    for (int l = 1; l < line && s; ++l) {
        s = strchr(s, '\n');
        if (s)
            ++s;
    }
    size_t len = 0;
    if (s)
        while (s[len] && s[len] != '\n')
            ++len;
    if (len >= n)
        len = n - 1;
    if (s)
        memcpy(buf, s, len);
    buf[len] = '\0';
}

/* The file's scene and this one differ as text: name the keys whose
 * values differ (scene_diff.c), or the first line that differs when the
 * values are the same (then the texts differ in keys' order or spacing,
 * which is no difference to the simulation, but the stored scene must be
 * the one the frames came from). */
static ms_status refuse_scene(const char *path, const char *have, const char *want)
{
    char keys[768];
    if (ms_io_scene_diff(have, want, keys, sizeof keys) > 0)
        return ms_fail(MS_ERR_INVALID_ARGUMENT,
                       "io: %s was written from another scene: %s; resuming would not "
                       "continue that run",
                       path, keys);
    int line = 1;
    size_t i = 0;
    for (; have[i] && have[i] == want[i]; ++i)
        if (have[i] == '\n')
            ++line;
    char a[96], b[96];
    text_line(have, line, a, sizeof a);
    text_line(want, line, b, sizeof b);
    return ms_fail(MS_ERR_INVALID_ARGUMENT,
                   "io: %s was written from another scene text: line %d of its scene is "
                   "\"%s\", this scene's is \"%s\"",
                   path, line, a, b);
}

/* Length of a 1-D or 3-D dataset's first dimension, -1 on error. */
static long first_dim(hid_t d)
{
    hsize_t dims[3] = {0, 0, 0};
    hid_t s = H5Dget_space(d);
    int rank = s >= 0 ? H5Sget_simple_extent_ndims(s) : -1;
    if (rank < 1 || rank > 3 || H5Sget_simple_extent_dims(s, dims, NULL) < 0) {
        if (s >= 0)
            H5Sclose(s);
        return -1;
    }
    H5Sclose(s);
    return (long)dims[0];
}

/* A dataset whose values are kept in another file (external storage, a
 * virtual dataset): the append would write there. */
static ms_status refuse_foreign(const char *path, const char *name)
{
    return ms_fail(MS_ERR_PARSE,
                   "io: %s: /%s keeps its values in another file (external storage or a virtual "
                   "dataset); a run file holds all its data itself, so it is not resumed",
                   path, name);
}

/* Check the file's identity against the layout: format, build, scene, the
 * fields and their grids. Opens w->dset[], w->time_dset, w->frames_attr
 * and sets w->frames to the complete frames. */
static ms_status check_resumable(ms_writer *w, const ms_writer_layout *l)
{
    hid_t f = w->file;
    const char *p = w->path;
    char *s = NULL;
    int64_t version = 0;
    if (ms_h5_read_string(f, "format", 64, &s) < 0 || strcmp(s, MS_FILE_FORMAT) != 0) {
        ms_free(s);
        return ms_fail(MS_ERR_PARSE, "io: %s is not a modesplit run file (no format \"%s\")", p,
                       MS_FILE_FORMAT);
    }
    ms_free(s);
    s = NULL;
    /* the reader's check: nothing below may name another file, which the
     * append would otherwise extend and write */
    ms_status lst = ms_h5_check_links(f, p);
    if (lst != MS_OK)
        return lst;
    if (ms_h5_read_int64(f, "format_version", &version) < 0 || version != MS_FILE_FORMAT_VERSION)
        return ms_fail(MS_ERR_UNSUPPORTED,
                       "io: %s has format_version %lld; only version %d files can be resumed", p,
                       (long long)version, MS_FILE_FORMAT_VERSION);
    if (ms_h5_read_string(f, "library_version", 256, &s) < 0 || strcmp(s, ms_version()) != 0) {
        ms_status st = ms_fail(MS_ERR_INVALID_ARGUMENT,
                               "io: %s was written by library version %s, this is %s: another "
                               "build may give other bytes, so it cannot continue that run",
                               p, s ? s : "(none)", ms_version());
        ms_free(s);
        return st;
    }
    ms_free(s);
    s = NULL;
    const char *want = l->scene_text ? l->scene_text : "";
    if (ms_h5_read_string(f, "scene", 64u << 20, &s) < 0) {
        ms_free(s);
        return ms_fail(MS_ERR_PARSE, "io: %s has no scene attribute", p);
    }
    if (strcmp(s, want) != 0) {
        ms_status st = refuse_scene(p, s, want);
        ms_free(s);
        return st;
    }
    ms_free(s);

    int64_t frames = 0;
    if (ms_h5_read_int64(f, "frames", &frames) < 0 || frames < 0)
        return ms_fail(MS_ERR_PARSE, "io: %s has no frames attribute", p);
    long k = (long)frames;
    for (int i = 0; i < MS_IO_NFIELDS; ++i) {
        char name[64];
        snprintf(name, sizeof name, "fields/%s", ms_io_field_names[i]);
        int want_it = (l->fields & (1u << i)) != 0;
        htri_t has = H5Lexists(f, "fields", H5P_DEFAULT) > 0 ? H5Lexists(f, name, H5P_DEFAULT) : 0;
        if ((has > 0) != want_it)
            return ms_fail(MS_ERR_INVALID_ARGUMENT,
                           "io: %s %s the field %s and this run %s it: not the same output", p,
                           has > 0 ? "holds" : "lacks", ms_io_field_names[i],
                           want_it ? "writes" : "does not write");
        if (!want_it)
            continue;
        w->dset[i] = H5Dopen2(f, name, H5P_DEFAULT);
        if (w->dset[i] >= 0 && !ms_h5_dataset_own(w->dset[i]))
            return refuse_foreign(p, name);
        hsize_t dims[3] = {0, 0, 0};
        hid_t sp = w->dset[i] >= 0 ? H5Dget_space(w->dset[i]) : -1;
        int rank = sp >= 0 ? H5Sget_simple_extent_ndims(sp) : -1;
        if (rank == 3)
            H5Sget_simple_extent_dims(sp, dims, NULL);
        if (sp >= 0)
            H5Sclose(sp);
        if (rank != 3 || dims[1] != (hsize_t)l->grid[i].ny || dims[2] != (hsize_t)l->grid[i].nx)
            return ms_fail(MS_ERR_INVALID_ARGUMENT,
                           "io: %s's field %s is not a [frame][%d][%d] dataset as this run "
                           "writes",
                           p, ms_io_field_names[i], l->grid[i].ny, l->grid[i].nx);
        if ((long)dims[0] < k)
            k = (long)dims[0];
    }
    htri_t has_particles = H5Lexists(f, "particles", H5P_DEFAULT);
    if ((has_particles > 0) != ((l->fields & MS_FIELD_PARTICLES) != 0))
        return ms_fail(MS_ERR_INVALID_ARGUMENT,
                       "io: %s %s particles and this run %s them: not the same output", p,
                       has_particles > 0 ? "holds" : "lacks",
                       (l->fields & MS_FIELD_PARTICLES) ? "writes" : "does not write");
    w->time_dset = H5Dopen2(f, "time", H5P_DEFAULT);
    if (w->time_dset >= 0 && !ms_h5_dataset_own(w->time_dset))
        return refuse_foreign(p, "time");
    long nt = w->time_dset >= 0 ? first_dim(w->time_dset) : -1;
    if (nt < 0)
        return ms_fail(MS_ERR_PARSE, "io: %s has no readable /time", p);
    if (nt < k)
        k = nt;
    htri_t has_floaters = H5Lexists(f, "floaters", H5P_DEFAULT);
    if ((has_floaters > 0) != (l->floaters > 0))
        return ms_fail(MS_ERR_INVALID_ARGUMENT,
                       "io: %s %s floaters and this run %s them: not the same output", p,
                       has_floaters > 0 ? "holds" : "lacks", l->floaters > 0 ? "has" : "lacks");
    if (l->floaters > 0) {
        w->floater_dset = H5Dopen2(f, "floaters", H5P_DEFAULT);
        if (w->floater_dset >= 0 && !ms_h5_dataset_own(w->floater_dset))
            return refuse_foreign(p, "floaters");
        long nf = w->floater_dset >= 0 ? first_dim(w->floater_dset) : -1;
        if (nf < 0)
            return ms_fail(MS_ERR_PARSE, "io: %s has no readable /floaters", p);
        if (nf < k)
            k = nf;
    }
    htri_t has_spray = H5Lexists(f, "spray", H5P_DEFAULT);
    if ((has_spray > 0) != (l->spray > 0))
        return ms_fail(MS_ERR_INVALID_ARGUMENT,
                       "io: %s %s spray and this run %s it: not the same output", p,
                       has_spray > 0 ? "holds" : "lacks", l->spray > 0 ? "throws" : "lacks");
    if (l->spray > 0) {
        static const char *const names[3] = {"spray", "spray_count", "foam"};
        hid_t *d[3] = {&w->spray_dset, &w->spray_n_dset, &w->foam_dset};
        for (int i = 0; i < 3; ++i) {
            *d[i] =
                H5Lexists(f, names[i], H5P_DEFAULT) > 0 ? H5Dopen2(f, names[i], H5P_DEFAULT) : -1;
            long nf = *d[i] >= 0 ? first_dim(*d[i]) : -1;
            if (nf < 0)
                return ms_fail(MS_ERR_PARSE, "io: %s has no readable /%s", p, names[i]);
            if (nf < k)
                k = nf;
        }
    }
    w->frames_attr = H5Aopen(f, "frames", H5P_DEFAULT);
    if (w->frames_attr < 0)
        return ms_fail(MS_ERR_PARSE, "io: %s has no frames attribute", p);
    w->frames = k;
    /* the checkpoints: one of a frame past those kept (cut by the kill) is
     * stale and overwritten first */
    for (int i = 0; i < MS_IO_CHECKPOINTS; ++i) {
        char name[32];
        snprintf(name, sizeof name, "checkpoint/%d", i);
        if (H5Lexists(f, "checkpoint", H5P_DEFAULT) <= 0 || H5Lexists(f, name, H5P_DEFAULT) <= 0)
            continue;
        int64_t at = -1;
        w->ckpt[i] = H5Dopen2(f, name, H5P_DEFAULT);
        if (w->ckpt[i] >= 0 && !ms_h5_dataset_own(w->ckpt[i]))
            return refuse_foreign(p, name);
        if (w->ckpt[i] < 0 || ms_h5_read_int64(w->ckpt[i], "frame", &at) < 0)
            return ms_fail(MS_ERR_PARSE, "io: %s has an unreadable /%s", p, name);
        w->ckpt_frame[i] = at >= 0 && at < k ? (long)at : -1;
    }
    H5Eclear2(H5E_DEFAULT);
    return MS_OK;
}

/* Particles of committed frame k (the H5Part step's x), -1 on error. */
static int step_count(hid_t f, long k)
{
    char name[64];
    ms_h5part_step_name(name, sizeof name, k);
    strncat(name, "/x", sizeof name - strlen(name) - 1);
    hid_t d = H5Dopen2(f, name, H5P_DEFAULT);
    if (d < 0)
        return -1;
    hid_t sp = H5Dget_space(d), t = H5Dget_type(d);
    int rank1 = sp >= 0 && H5Sget_simple_extent_ndims(sp) == 1;
    int flt = t >= 0 && H5Tget_class(t) == H5T_FLOAT;
    if (sp >= 0)
        H5Sclose(sp);
    if (t >= 0)
        H5Tclose(t);
    long n = rank1 && flt ? first_dim(d) : -1;
    H5Dclose(d);
    return n > MS_IO_MAX_PARTICLES ? -1 : (int)n;
}

/* Drop what lies past the complete frames (a frame cut by a kill), then
 * write the sidecars again for the frames kept. */
static ms_status trim_and_relist(ms_writer *w)
{
    hid_t f = w->file;
    long k = w->frames;
    for (int i = 0; i < MS_IO_NFIELDS; ++i) {
        if (w->dset[i] < 0)
            continue;
        hsize_t dims[3] = {(hsize_t)k, (hsize_t)w->layout.grid[i].ny,
                           (hsize_t)w->layout.grid[i].nx};
        if (H5Dset_extent(w->dset[i], dims) < 0)
            return MS_ERR_IO;
    }
    hsize_t tdims[1] = {(hsize_t)k};
    if (H5Dset_extent(w->time_dset, tdims) < 0)
        return MS_ERR_IO;
    hsize_t fdims[3] = {(hsize_t)k, (hsize_t)w->layout.floaters, 3};
    if (w->floater_dset >= 0 && H5Dset_extent(w->floater_dset, fdims) < 0)
        return MS_ERR_IO;
    if (w->spray_dset >= 0) {
        hsize_t sdims[3] = {(hsize_t)k, (hsize_t)w->layout.spray, 3};
        hsize_t gdims[3] = {(hsize_t)k, (hsize_t)w->layout.foam.ny, (hsize_t)w->layout.foam.nx};
        if (H5Dset_extent(w->spray_dset, sdims) < 0 || H5Dset_extent(w->spray_n_dset, tdims) < 0 ||
            H5Dset_extent(w->foam_dset, gdims) < 0)
            return MS_ERR_IO;
    }
    if (w->layout.fields & MS_FIELD_PARTICLES) {
        /* links of later frames, if the kill came between link and `frames` */
        for (long j = k;; ++j) {
            char a[64], b[64];
            ms_h5part_step_name(a, sizeof a, j);
            snprintf(b, sizeof b, "particles/%ld", j);
            int ha = H5Lexists(f, a, H5P_DEFAULT) > 0, hb = H5Lexists(f, b, H5P_DEFAULT) > 0;
            if (!ha && !hb)
                break;
            if ((ha && H5Ldelete(f, a, H5P_DEFAULT) < 0) ||
                (hb && H5Ldelete(f, b, H5P_DEFAULT) < 0))
                return MS_ERR_IO;
        }
    }
    /* a checkpoint of a dropped frame must not count once frames pass it */
    for (int i = 0; i < MS_IO_CHECKPOINTS; ++i) {
        int64_t none = -1;
        hid_t a = w->ckpt[i] >= 0 && w->ckpt_frame[i] < 0
                      ? H5Aopen(w->ckpt[i], "frame", H5P_DEFAULT)
                      : -1;
        herr_t e = a >= 0 ? H5Awrite(a, H5T_NATIVE_INT64, &none) : 0;
        if (a >= 0)
            H5Aclose(a);
        if ((w->ckpt[i] >= 0 && w->ckpt_frame[i] < 0 && a < 0) || e < 0)
            return MS_ERR_IO;
    }
    int64_t committed = k;
    if (H5Awrite(w->frames_attr, H5T_NATIVE_INT64, &committed) < 0 || !commit(w))
        return MS_ERR_IO;
    return MS_OK;
}

static ms_status relist_sidecars(ms_writer *w)
{
    const char *slash = strrchr(w->path, '/');
    const char *h5 = slash ? slash + 1 : w->path;
    ms_status st = ms_xdmf_open(w->xmf_path, h5, &w->layout, 0, &w->xdmf);
    if (st == MS_OK)
        st = ms_xdmf_open(w->xmf2_path, h5, &w->layout, 1, &w->xdmf2);
    for (long j = 0; j < w->frames && st == MS_OK; ++j) {
        double t = 0;
        hsize_t start[1] = {(hsize_t)j}, count[1] = {1};
        hid_t fs = H5Dget_space(w->time_dset);
        hid_t ms = H5Screate_simple(1, count, NULL);
        int ok = fs >= 0 && ms >= 0 &&
                 H5Sselect_hyperslab(fs, H5S_SELECT_SET, start, NULL, count, NULL) >= 0 &&
                 H5Dread(w->time_dset, H5T_NATIVE_DOUBLE, ms, fs, H5P_DEFAULT, &t) >= 0;
        if (fs >= 0)
            H5Sclose(fs);
        if (ms >= 0)
            H5Sclose(ms);
        if (!ok)
            return ms_h5_fail(MS_ERR_PARSE, "io: frame %ld of %s cannot be read back", j, w->path);
        int n = 0;
        if ((w->layout.fields & MS_FIELD_PARTICLES) && (n = step_count(w->file, j)) < 0) {
            /* HDF5 may have said nothing (a scalar opens fine): no stale
             * reason from its stack or errno */
            H5Eclear2(H5E_DEFAULT);
            return ms_fail(MS_ERR_PARSE,
                           "io: frame %ld of %s cannot be read back: its /Step#%ld/x is missing "
                           "or not a 1D float array",
                           j, w->path, j);
        }
        int ns = 0;
        if (w->spray_n_dset >= 0) {
            fs = H5Dget_space(w->spray_n_dset);
            ms = H5Screate_simple(1, count, NULL);
            ok = fs >= 0 && ms >= 0 &&
                 H5Sselect_hyperslab(fs, H5S_SELECT_SET, start, NULL, count, NULL) >= 0 &&
                 H5Dread(w->spray_n_dset, H5T_NATIVE_INT, ms, fs, H5P_DEFAULT, &ns) >= 0 &&
                 ns >= 0 && ns <= w->layout.spray;
            if (fs >= 0)
                H5Sclose(fs);
            if (ms >= 0)
                H5Sclose(ms);
            if (!ok)
                return ms_h5_fail(MS_ERR_PARSE,
                                  "io: frame %ld of %s: its spray count cannot be read back", j,
                                  w->path);
        }
        ms_xdmf_set_spray(w->xdmf, ns);
        ms_xdmf_set_spray(w->xdmf2, ns);
        st = ms_xdmf_frame(w->xdmf, j, t, n);
        if (st == MS_OK)
            st = ms_xdmf_frame(w->xdmf2, j, t, n);
    }
    return st;
}

ms_status ms_writer_open_append_layout(const char *path, const ms_writer_layout *l, ms_writer **out)
{
    ms_writer *w = NULL;
    ms_status st = writer_new(path, l, out, &w);
    if (st != MS_OK)
        return st;
    if (access(path, R_OK | W_OK) != 0) {
        st = ms_fail(MS_ERR_IO, "io: cannot resume %s: %s", path, strerror(errno));
        free_writer(w);
        return st;
    }
    if ((st = lock_file(path, path, 0, 1, &w->lock_fd)) != MS_OK) {
        free_writer(w);
        return st;
    }
    ms_h5_quiet q;
    ms_h5_hush(&q);
    /* Checked first on a read-only open: HDF5 rewrites the superblock when
     * a file opened for writing is closed, even with nothing written, and
     * truncates it to its end of allocation (a killed run's file shrank by
     * its unreferenced tail), so a refused file must never be opened for
     * writing. The checks run again on the writable open below, which is
     * the one that counts if the file changed in between. */
    hid_t rapl = ms_h5_fapl();
    w->file = rapl >= 0 ? H5Fopen(path, H5F_ACC_RDONLY, rapl) : -1;
    if (rapl >= 0)
        H5Pclose(rapl);
    if (w->file < 0)
        st = ms_h5_fail(MS_ERR_IO, "io: cannot open %s to resume it", path);
    if (st == MS_OK)
        st = check_resumable(w, l);
    close_handles(w);
    if (w->file >= 0)
        H5Fclose(w->file);
    w->file = -1;
    if (st != MS_OK) {
        H5Eclear2(H5E_DEFAULT);
        ms_h5_loud(&q);
        free_writer(w);
        return st;
    }
    hid_t fapl = ms_h5_fapl_atomic();
    w->file = fapl >= 0 ? H5Fopen(path, H5F_ACC_RDWR, fapl) : -1;
    if (fapl >= 0)
        H5Pclose(fapl);
    if (w->file < 0)
        st = ms_h5_fail(MS_ERR_IO, "io: cannot open %s to resume it", path);
    if (st == MS_OK)
        st = check_resumable(w, l);
    /* Nothing has been written to the file before this point. */
    if (st == MS_OK && trim_and_relist(w) != MS_OK)
        st = ms_h5_fail(MS_ERR_IO, "io: cannot drop the cut frame of %s", path);
    if (st == MS_OK)
        st = relist_sidecars(w);
    if (st != MS_OK) {
        ms_xdmf_close(w->xdmf);
        ms_xdmf_close(w->xdmf2);
        close_handles(w);
        if (w->file >= 0)
            H5Fclose(w->file);
        H5Eclear2(H5E_DEFAULT);
        ms_h5_loud(&q);
        free_writer(w);
        return st;
    }
    ms_h5_loud(&q);
    *out = w;
    return MS_OK;
}
