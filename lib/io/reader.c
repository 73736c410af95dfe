/* lib/io: reading a run file back (ms_reader, what `modesplit info` shows).
 *
 * Defensive: a file is untrusted input. Every object is checked for
 * existence, type class, rank and size before it is used; grids are bounded
 * (MS_IO_MAX_SIDE, MS_IO_MAX_CELLS), strings by length, and the number of
 * frames is the smallest of the `frames` attribute and the lengths of /time
 * and of every field, so a file cut off by a kill reads as its committed
 * frames. HDF5's own printing is silenced; its errors become sentences.
 */
#include <errno.h>
#include <float.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "io/io_internal.h"

#define MAX_SCENE_BYTES (16u << 20)
#define MAX_NAME_BYTES 4096u

struct ms_reader {
    char *path;
    hid_t file;
    hid_t time_dset;
    hid_t floater_dset; /* -1 without /floaters */
    int nfloaters;
    hid_t spray_dset, spray_n_dset, foam_dset; /* -1 without /spray */
    int spray_budget;
    ms_grid foam;
    hid_t dset[MS_IO_NFIELDS];
    ms_grid grid[MS_IO_NFIELDS];
    long frames;
    unsigned fields;
    int format_version;
    int output_every;
    double frame_dt;
    char *library_version, *scene, *scene_name;
    /* usable checkpoints, newest first */
    int nckpt;
    long ckpt_frame[MS_IO_CHECKPOINTS];
    int ckpt_slot[MS_IO_CHECKPOINTS];
    size_t ckpt_bytes[MS_IO_CHECKPOINTS];
};

static void reader_free(ms_reader *r)
{
    if (!r)
        return;
    for (int i = 0; i < MS_IO_NFIELDS; ++i)
        if (r->dset[i] >= 0)
            H5Dclose(r->dset[i]);
    if (r->time_dset >= 0)
        H5Dclose(r->time_dset);
    if (r->floater_dset >= 0)
        H5Dclose(r->floater_dset);
    hid_t spray[3] = {r->spray_dset, r->spray_n_dset, r->foam_dset};
    for (int i = 0; i < 3; ++i)
        if (spray[i] >= 0)
            H5Dclose(spray[i]);
    if (r->file >= 0)
        H5Fclose(r->file);
    H5Eclear2(H5E_DEFAULT);
    ms_free(r->library_version);
    ms_free(r->scene);
    ms_free(r->scene_name);
    ms_free(r->path);
    ms_free(r);
}

/* Link `name` exists below `loc` (each part of the path checked). */
static int has_link(hid_t loc, const char *name)
{
    char part[256];
    size_t at = 0, len = strlen(name);
    while (at < len) {
        const char *slash = strchr(name + at, '/');
        size_t end = slash ? (size_t)(slash - name) : len;
        if (end >= sizeof part)
            return 0;
        memcpy(part, name, end);
        part[end] = '\0';
        if (H5Lexists(loc, part, H5P_DEFAULT) <= 0)
            return 0;
        at = end + 1;
    }
    return 1;
}

/* Open dataset `name` and check class and rank; dims out. */
static hid_t open_dataset(hid_t loc, const char *name, H5T_class_t cls, int rank, hsize_t *dims)
{
    if (!has_link(loc, name))
        return -1;
    H5O_info_t info;
    if (H5Oget_info_by_name(loc, name, &info, H5P_DEFAULT) < 0 || info.type != H5O_TYPE_DATASET)
        return -1;
    hid_t d = H5Dopen2(loc, name, H5P_DEFAULT);
    if (d < 0)
        return -1;
    /* the data must be in this file (ms_h5_dataset_own) */
    if (!ms_h5_dataset_own(d)) {
        H5Dclose(d);
        return -1;
    }
    hid_t t = H5Dget_type(d);
    hid_t s = H5Dget_space(d);
    int ok = t >= 0 && s >= 0 && H5Tget_class(t) == cls && H5Sget_simple_extent_ndims(s) == rank &&
             H5Sget_simple_extent_dims(s, dims, NULL) == rank;
    if (ok && cls == H5T_FLOAT)
        ok = H5Tget_size(t) == 4 || H5Tget_size(t) == 8;
    if (t >= 0)
        H5Tclose(t);
    if (s >= 0)
        H5Sclose(s);
    if (!ok) {
        H5Dclose(d);
        return -1;
    }
    return d;
}

static ms_status open_field(ms_reader *r, int slot, hid_t fields)
{
    const char *name = ms_io_field_names[slot];
    if (H5Lexists(fields, name, H5P_DEFAULT) <= 0)
        return MS_OK;
    hsize_t dims[3];
    hid_t d = open_dataset(fields, name, H5T_FLOAT, 3, dims);
    if (d < 0)
        return ms_fail(MS_ERR_PARSE, "io: %s: /fields/%s is not a float [frame][y][x] dataset",
                       r->path, name);
    r->dset[slot] = d;
    if (dims[1] < 1 || dims[1] > MS_IO_MAX_SIDE || dims[2] < 1 || dims[2] > MS_IO_MAX_SIDE ||
        dims[1] * dims[2] > (hsize_t)MS_IO_MAX_CELLS)
        return ms_fail(MS_ERR_PARSE,
                       "io: %s: /fields/%s grid %llu x %llu is outside [1, %d] a "
                       "side or over %ld cells",
                       r->path, name, (unsigned long long)dims[2], (unsigned long long)dims[1],
                       MS_IO_MAX_SIDE, MS_IO_MAX_CELLS);
    double dx[2], origin[2];
    /* a normal float both ways: a denormal dx would become a 0 mm grid */
    if (ms_h5_read_doubles(d, "dx", dx, 2) < 0 || !(dx[0] >= FLT_MIN) || !(dx[1] >= FLT_MIN) ||
        !isfinite(dx[0]) || !isfinite(dx[1]) || dx[0] > 3e38 || dx[1] > 3e38)
        return ms_fail(MS_ERR_PARSE,
                       "io: %s: /fields/%s lacks the attribute dx = [dx, dy] (finite, at least "
                       "1.2e-38 m: a normal float)",
                       r->path, name);
    if (ms_h5_read_doubles(d, "origin", origin, 2) < 0 || !isfinite(origin[0]) ||
        !isfinite(origin[1]) || fabs(origin[0]) > 3e38 || fabs(origin[1]) > 3e38)
        return ms_fail(MS_ERR_PARSE,
                       "io: %s: /fields/%s lacks the attribute origin = [x0, y0] (finite, m)",
                       r->path, name);
    ms_grid *g = &r->grid[slot];
    g->nx = (int)dims[2];
    g->ny = (int)dims[1];
    g->dx = (float)dx[0];
    g->dy = (float)dx[1];
    g->origin[0] = (float)origin[0];
    g->origin[1] = (float)origin[1];
    r->fields |= 1u << slot;
    if (dims[0] < (hsize_t)r->frames)
        r->frames = (long)dims[0];
    return MS_OK;
}

/* /spray [frame][budget][3], /spray_count [frame] and /foam [frame][y][x]
 * (with dx and origin, as a field). */
static ms_status open_spray(ms_reader *r)
{
    hsize_t sd[3], nd[1], fd[3];
    r->spray_dset = open_dataset(r->file, "spray", H5T_FLOAT, 3, sd);
    r->spray_n_dset = open_dataset(r->file, "spray_count", H5T_INTEGER, 1, nd);
    r->foam_dset = open_dataset(r->file, "foam", H5T_FLOAT, 3, fd);
    double dx[2], origin[2];
    if (r->spray_dset < 0 || r->spray_n_dset < 0 || r->foam_dset < 0 || sd[1] < 1 ||
        sd[1] > (1u << 20) || sd[2] != 3 || fd[1] < 1 || fd[1] > MS_IO_MAX_SIDE || fd[2] < 1 ||
        fd[2] > MS_IO_MAX_SIDE || fd[1] * fd[2] > (hsize_t)MS_IO_MAX_CELLS ||
        ms_h5_read_doubles(r->foam_dset, "dx", dx, 2) < 0 || !(dx[0] >= FLT_MIN) ||
        !(dx[1] >= FLT_MIN) || !(dx[0] <= 3e38) || !(dx[1] <= 3e38) ||
        ms_h5_read_doubles(r->foam_dset, "origin", origin, 2) < 0 || !(fabs(origin[0]) <= 3e38) ||
        !(fabs(origin[1]) <= 3e38))
        return ms_fail(MS_ERR_PARSE,
                       "io: %s: /spray, /spray_count and /foam are not the [frame][budget][3], "
                       "[frame] and [frame][y][x] datasets (foam with dx and origin) of a spray",
                       r->path);
    r->spray_budget = (int)sd[1];
    r->foam = (ms_grid){.nx = (int)fd[2],
                        .ny = (int)fd[1],
                        .dx = (float)dx[0],
                        .dy = (float)dx[1],
                        .origin = {(float)origin[0], (float)origin[1]}};
    hsize_t least = MS_MIN(sd[0], MS_MIN(nd[0], fd[0]));
    if (least < (hsize_t)r->frames)
        r->frames = (long)least;
    return MS_OK;
}

/* The checkpoints of complete frames (a slot marked with a frame the file
 * does not count yet was cut by a kill), newest first. A slot that cannot
 * be read is left out: a resume then falls back to an older one or to
 * stepping from the start. */
static void read_checkpoints(ms_reader *r)
{
    r->nckpt = 0;
    if (H5Lexists(r->file, "checkpoint", H5P_DEFAULT) <= 0)
        return;
    for (int s = 0; s < MS_IO_CHECKPOINTS; ++s) {
        char name[32];
        snprintf(name, sizeof name, "checkpoint/%d", s);
        hsize_t dims[1];
        hid_t d = open_dataset(r->file, name, H5T_INTEGER, 1, dims);
        int64_t at = -1, bytes = 0;
        /* the blob's bytes must be stored in the file: the writer's slots
         * have no filters, so a slot claiming more than its chunks hold
         * (a sparse or forged file) would only make a reader allocate
         * memory for fill values */
        int ok = d >= 0 && ms_h5_read_int64(d, "frame", &at) >= 0 && at >= 0 && at < r->frames &&
                 ms_h5_read_int64(d, "bytes", &bytes) >= 0 && bytes > 0 &&
                 (hsize_t)bytes <= dims[0] && dims[0] <= (hsize_t)1 << 40 &&
                 (hsize_t)bytes <= H5Dget_storage_size(d);
        if (d >= 0)
            H5Dclose(d);
        if (!ok)
            continue;
        int i = r->nckpt++;
        /* insert, newest first */
        while (i > 0 && r->ckpt_frame[i - 1] < at) {
            r->ckpt_frame[i] = r->ckpt_frame[i - 1];
            r->ckpt_slot[i] = r->ckpt_slot[i - 1];
            r->ckpt_bytes[i] = r->ckpt_bytes[i - 1];
            --i;
        }
        r->ckpt_frame[i] = (long)at;
        r->ckpt_slot[i] = s;
        r->ckpt_bytes[i] = (size_t)bytes;
    }
    H5Eclear2(H5E_DEFAULT);
}

static ms_status read_layout(ms_reader *r)
{
    hid_t f = r->file;
    char *format = NULL;
    if (ms_h5_read_string(f, "format", 64, &format) < 0 || strcmp(format, MS_FILE_FORMAT) != 0) {
        ms_free(format);
        return ms_fail(MS_ERR_PARSE,
                       "io: %s is an HDF5 file but not a modesplit run (no root attribute "
                       "format = \"%s\")",
                       r->path, MS_FILE_FORMAT);
    }
    ms_free(format);
    ms_status lst = ms_h5_check_links(r->file, r->path);
    if (lst != MS_OK)
        return lst;
    int64_t v;
    if (ms_h5_read_int64(f, "format_version", &v) < 0 || v < 1)
        return ms_fail(MS_ERR_PARSE, "io: %s lacks a format_version >= 1", r->path);
    if (v > MS_FILE_FORMAT_VERSION)
        return ms_fail(MS_ERR_UNSUPPORTED,
                       "io: %s has format_version %lld; this library reads up to %d", r->path,
                       (long long)v, MS_FILE_FORMAT_VERSION);
    r->format_version = (int)v;
    if (ms_h5_read_string(f, "library_version", MAX_NAME_BYTES, &r->library_version) < 0)
        r->library_version = NULL;
    if (ms_h5_read_string(f, "scene", MAX_SCENE_BYTES, &r->scene) < 0)
        r->scene = NULL;
    if (ms_h5_read_string(f, "scene_name", MAX_NAME_BYTES, &r->scene_name) < 0)
        r->scene_name = NULL;
    H5Eclear2(H5E_DEFAULT);
    double dt;
    r->frame_dt = ms_h5_read_doubles(f, "frame_dt", &dt, 1) >= 0 && isfinite(dt) ? dt : NAN;
    r->output_every =
        ms_h5_read_int64(f, "output_every", &v) >= 0 && v >= 1 && v <= 1L << 30 ? (int)v : 1;
    H5Eclear2(H5E_DEFAULT);
    if (ms_h5_read_int64(f, "frames", &v) < 0 || v < 0)
        return ms_fail(MS_ERR_PARSE, "io: %s lacks the root attribute frames (an integer >= 0)",
                       r->path);
    r->frames = v > (int64_t)(1L << 40) ? 1L << 40 : (long)v;

    hsize_t tdims[1];
    r->time_dset = open_dataset(f, "time", H5T_FLOAT, 1, tdims);
    if (r->time_dset < 0)
        return ms_fail(MS_ERR_PARSE, "io: %s lacks /time, a 1D float dataset", r->path);
    if (tdims[0] < (hsize_t)r->frames)
        r->frames = (long)tdims[0];
    if (H5Lexists(f, "floaters", H5P_DEFAULT) > 0) {
        hsize_t fd[3];
        r->floater_dset = open_dataset(f, "floaters", H5T_FLOAT, 3, fd);
        if (r->floater_dset < 0 || fd[1] < 1 || fd[1] > (1u << 20) || fd[2] != 3)
            return ms_fail(MS_ERR_PARSE, "io: %s: /floaters is not a [frame][n][3] float dataset",
                           r->path);
        r->nfloaters = (int)fd[1];
        if (fd[0] < (hsize_t)r->frames)
            r->frames = (long)fd[0];
    }

    if (H5Lexists(f, "spray", H5P_DEFAULT) > 0) {
        ms_status st = open_spray(r);
        if (st != MS_OK)
            return st;
    }

    if (H5Lexists(f, "fields", H5P_DEFAULT) > 0) {
        H5O_info_t info;
        if (H5Oget_info_by_name(f, "fields", &info, H5P_DEFAULT) < 0 || info.type != H5O_TYPE_GROUP)
            return ms_fail(MS_ERR_PARSE, "io: %s: /fields is not a group", r->path);
        hid_t g = H5Gopen2(f, "fields", H5P_DEFAULT);
        if (g < 0)
            return ms_fail(MS_ERR_PARSE, "io: %s: cannot open /fields", r->path);
        ms_status st = MS_OK;
        for (int i = 0; i < MS_IO_NFIELDS && st == MS_OK; ++i)
            st = open_field(r, i, g);
        H5Gclose(g);
        if (st != MS_OK)
            return st;
    }
    char step[48];
    ms_h5part_step_name(step, sizeof step, 0);
    if (H5Lexists(f, step, H5P_DEFAULT) > 0)
        r->fields |= MS_FIELD_PARTICLES;
    H5Eclear2(H5E_DEFAULT);
    read_checkpoints(r);
    return MS_OK;
}

ms_status ms_reader_open(const char *path, ms_reader **out)
{
    ms_status st;
    if ((st = ms_check_not_null("io", "out", out)) != MS_OK)
        return st;
    *out = NULL;
    if ((st = ms_check_not_null("io", "path", path)) != MS_OK)
        return st;
    struct stat sb;
    if (stat(path, &sb) != 0)
        return ms_fail(MS_ERR_IO, "io: cannot open %s: %s", path, strerror(errno));
    if (!S_ISREG(sb.st_mode))
        return ms_fail(MS_ERR_IO, "io: cannot open %s: not a regular file", path);
    ms_reader *r = ms_alloc_array(1, sizeof *r);
    if (!r || !(r->path = ms_strdup(path))) {
        ms_free(r);
        return ms_fail(MS_ERR_OUT_OF_MEMORY, "io: out of memory for the reader");
    }
    r->file = r->time_dset = r->floater_dset = -1;
    r->spray_dset = r->spray_n_dset = r->foam_dset = -1;
    for (int i = 0; i < MS_IO_NFIELDS; ++i)
        r->dset[i] = -1;
    ms_h5_quiet q;
    ms_h5_hush(&q);
    hid_t fapl = ms_h5_fapl();
    if (fapl >= 0 && H5Pset_libver_bounds(fapl, H5F_LIBVER_EARLIEST, H5F_LIBVER_LATEST) < 0) {
        H5Pclose(fapl);
        fapl = -1;
    }
    if (fapl < 0) {
        st = ms_h5_fail(MS_ERR_IO, "io: cannot set up HDF5 to read %s", path);
    } else {
        htri_t is = H5Fis_hdf5(path);
        if (is <= 0) {
            H5Eclear2(H5E_DEFAULT);
            st = ms_fail(MS_ERR_IO, "io: %s is not an HDF5 file", path);
        } else {
            r->file = H5Fopen(path, H5F_ACC_RDONLY, fapl);
            if (r->file < 0)
                st = ms_h5_fail(MS_ERR_IO, "io: cannot open %s", path);
            else
                st = read_layout(r);
        }
        H5Pclose(fapl);
    }
    if (st != MS_OK) {
        reader_free(r);
        ms_h5_loud(&q);
        return st;
    }
    ms_h5_loud(&q);
    *out = r;
    return MS_OK;
}

void ms_reader_close(ms_reader *r)
{
    if (!r)
        return;
    ms_h5_quiet q;
    ms_h5_hush(&q);
    reader_free(r);
    ms_h5_loud(&q);
}

long ms_reader_frames(const ms_reader *r)
{
    return r ? r->frames : 0;
}

unsigned ms_reader_fields(const ms_reader *r)
{
    return r ? r->fields : 0;
}

int ms_reader_format_version(const ms_reader *r)
{
    return r ? r->format_version : 0;
}

const char *ms_reader_library_version(const ms_reader *r)
{
    return r && r->library_version ? r->library_version : "";
}

const char *ms_reader_scene(const ms_reader *r)
{
    return r && r->scene ? r->scene : "";
}

const char *ms_reader_scene_name(const ms_reader *r)
{
    return r && r->scene_name ? r->scene_name : "";
}

double ms_reader_frame_dt(const ms_reader *r)
{
    return r ? r->frame_dt : NAN;
}

int ms_reader_output_every(const ms_reader *r)
{
    return r ? r->output_every : 1;
}

static ms_status check_frame(const ms_reader *r, long frame)
{
    ms_status st = ms_check_not_null("io", "reader", r);
    if (st != MS_OK)
        return st;
    if (frame < 0 || frame >= r->frames)
        return ms_fail(MS_ERR_INVALID_ARGUMENT, "io: frame %ld is outside [0, %ld) of %s", frame,
                       r->frames, r->path);
    return MS_OK;
}

static ms_status field_slot(const ms_reader *r, unsigned field, int *slot)
{
    ms_status st = ms_check_not_null("io", "reader", r);
    if (st != MS_OK)
        return st;
    *slot = ms_io_field_slot(field);
    if (*slot < 0)
        return ms_fail(MS_ERR_INVALID_ARGUMENT,
                       "io: field 0x%x is not one of MS_FIELD_COMBINED, _SURFACE, _VOLUME", field);
    if (!(r->fields & field))
        return ms_fail(MS_ERR_INVALID_ARGUMENT, "io: %s has no field %s", r->path,
                       ms_io_field_names[*slot]);
    return MS_OK;
}

ms_status ms_reader_time(const ms_reader *r, long frame, double *t)
{
    ms_status st = check_frame(r, frame);
    if (st != MS_OK || (st = ms_check_not_null("io", "t", t)) != MS_OK)
        return st;
    ms_h5_quiet q;
    ms_h5_hush(&q);
    hsize_t start = (hsize_t)frame, count = 1;
    hid_t fs = H5Dget_space(r->time_dset);
    hid_t ms = H5Screate_simple(1, &count, NULL);
    herr_t h = -1;
    if (fs >= 0 && ms >= 0 &&
        H5Sselect_hyperslab(fs, H5S_SELECT_SET, &start, NULL, &count, NULL) >= 0)
        h = H5Dread(r->time_dset, H5T_NATIVE_DOUBLE, ms, fs, H5P_DEFAULT, t);
    if (h < 0)
        st = ms_h5_fail(MS_ERR_IO, "io: reading /time[%ld] of %s failed", frame, r->path);
    if (fs >= 0)
        H5Sclose(fs);
    if (ms >= 0)
        H5Sclose(ms);
    H5Eclear2(H5E_DEFAULT);
    ms_h5_loud(&q);
    return st;
}

ms_status ms_reader_field_grid(const ms_reader *r, unsigned field, ms_grid *out)
{
    int slot;
    ms_status st = field_slot(r, field, &slot);
    if (st != MS_OK || (st = ms_check_not_null("io", "out", out)) != MS_OK)
        return st;
    *out = r->grid[slot];
    return MS_OK;
}

ms_status ms_reader_field_bytes(const ms_reader *r, unsigned field, uint64_t *stored, uint64_t *raw)
{
    int slot;
    ms_status st = field_slot(r, field, &slot);
    if (st != MS_OK)
        return st;
    ms_h5_quiet q;
    ms_h5_hush(&q);
    if (stored)
        *stored = H5Dget_storage_size(r->dset[slot]);
    H5Eclear2(H5E_DEFAULT);
    ms_h5_loud(&q);
    if (raw)
        *raw = (uint64_t)r->frames * (uint64_t)r->grid[slot].nx * (uint64_t)r->grid[slot].ny * 4u;
    return MS_OK;
}

ms_status ms_reader_read_field(const ms_reader *r, unsigned field, long frame, float *out,
                               size_t count)
{
    int slot;
    ms_status st = field_slot(r, field, &slot);
    if (st != MS_OK || (st = check_frame(r, frame)) != MS_OK ||
        (st = ms_check_not_null("io", "out", out)) != MS_OK)
        return st;
    const ms_grid *g = &r->grid[slot];
    size_t need = (size_t)g->nx * (size_t)g->ny;
    if (count < need)
        return ms_fail(MS_ERR_INVALID_ARGUMENT,
                       "io: field %s needs %zu floats (%d x %d) but out holds %zu",
                       ms_io_field_names[slot], need, g->nx, g->ny, count);
    ms_h5_quiet q;
    ms_h5_hush(&q);
    hsize_t start[3] = {(hsize_t)frame, 0, 0};
    hsize_t cnt[3] = {1, (hsize_t)g->ny, (hsize_t)g->nx};
    hid_t fs = H5Dget_space(r->dset[slot]);
    hid_t ms = H5Screate_simple(3, cnt, NULL);
    herr_t h = -1;
    if (fs >= 0 && ms >= 0 && H5Sselect_hyperslab(fs, H5S_SELECT_SET, start, NULL, cnt, NULL) >= 0)
        h = H5Dread(r->dset[slot], H5T_NATIVE_FLOAT, ms, fs, H5P_DEFAULT, out);
    if (h < 0)
        st = ms_h5_fail(MS_ERR_IO, "io: reading frame %ld of /fields/%s in %s failed", frame,
                        ms_io_field_names[slot], r->path);
    if (fs >= 0)
        H5Sclose(fs);
    if (ms >= 0)
        H5Sclose(ms);
    H5Eclear2(H5E_DEFAULT);
    ms_h5_loud(&q);
    return st;
}

static const char *const particle_names[6] = {"x", "y", "z", "vx", "vy", "vz"};

/* Open the six arrays of a step and check they agree; n out. */
static ms_status open_step(const ms_reader *r, long frame, hid_t d[6], int *n)
{
    char step[48];
    ms_h5part_step_name(step, sizeof step, frame);
    for (int k = 0; k < 6; ++k)
        d[k] = -1;
    *n = 0;
    if (H5Lexists(r->file, step, H5P_DEFAULT) <= 0) {
        H5Eclear2(H5E_DEFAULT);
        if (r->fields & MS_FIELD_PARTICLES)
            return ms_fail(MS_ERR_PARSE, "io: %s has particles but no /%s", r->path, step);
        return MS_OK;
    }
    hsize_t first = 0;
    for (int k = 0; k < 6; ++k) {
        char name[64];
        snprintf(name, sizeof name, "%s/%s", step, particle_names[k]);
        hsize_t dims[1];
        d[k] = open_dataset(r->file, name, H5T_FLOAT, 1, dims);
        /* the arrays are written unfiltered, so their bytes must be in
         * the file: a sparse or forged step claiming 1e8 particles would
         * only make a reader allocate memory for fill values */
        if (d[k] < 0 || (k > 0 && dims[0] != first) || dims[0] > (hsize_t)MS_IO_MAX_PARTICLES ||
            H5Dget_storage_size(d[k]) < dims[0] * sizeof(float)) {
            for (int j = 0; j <= k; ++j)
                if (d[j] >= 0)
                    H5Dclose(d[j]);
            H5Eclear2(H5E_DEFAULT);
            return ms_fail(MS_ERR_PARSE,
                           "io: %s: /%s/%s is missing, not a 1D float array, its length "
                           "differs from /%s/x, or the file does not hold its values",
                           r->path, step, particle_names[k], step);
        }
        if (k == 0)
            first = dims[0];
    }
    *n = (int)first;
    return MS_OK;
}

ms_status ms_reader_particle_count(const ms_reader *r, long frame, int *n)
{
    ms_status st = check_frame(r, frame);
    if (st != MS_OK || (st = ms_check_not_null("io", "n", n)) != MS_OK)
        return st;
    ms_h5_quiet q;
    ms_h5_hush(&q);
    hid_t d[6];
    st = open_step(r, frame, d, n);
    for (int k = 0; k < 6; ++k)
        if (d[k] >= 0)
            H5Dclose(d[k]);
    H5Eclear2(H5E_DEFAULT);
    ms_h5_loud(&q);
    return st;
}

ms_status ms_reader_read_particles(const ms_reader *r, long frame, int capacity,
                                   float *const pos[3], float *const vel[3])
{
    ms_status st = check_frame(r, frame);
    if (st != MS_OK)
        return st;
    ms_h5_quiet q;
    ms_h5_hush(&q);
    hid_t d[6];
    int n;
    st = open_step(r, frame, d, &n);
    if (st == MS_OK && n > capacity)
        st = ms_fail(MS_ERR_INVALID_ARGUMENT,
                     "io: frame %ld has %d particles but the arrays hold %d", frame, n, capacity);
    for (int k = 0; k < 6 && st == MS_OK; ++k) {
        float *dst = k < 3 ? (pos ? pos[k] : NULL) : (vel ? vel[k - 3] : NULL);
        if (!dst || n == 0)
            continue;
        if (H5Dread(d[k], H5T_NATIVE_FLOAT, H5S_ALL, H5S_ALL, H5P_DEFAULT, dst) < 0)
            st = ms_h5_fail(MS_ERR_IO, "io: reading particles %s of frame %ld in %s failed",
                            particle_names[k], frame, r->path);
    }
    for (int k = 0; k < 6; ++k)
        if (d[k] >= 0)
            H5Dclose(d[k]);
    H5Eclear2(H5E_DEFAULT);
    ms_h5_loud(&q);
    return st;
}

int ms_reader_checkpoints(const ms_reader *r, long frames[2])
{
    if (!r)
        return 0;
    for (int i = 0; i < r->nckpt && frames; ++i)
        frames[i] = r->ckpt_frame[i];
    return r->nckpt;
}

static ms_status check_checkpoint(const ms_reader *r, int i)
{
    ms_status st = ms_check_not_null("io", "reader", r);
    if (st == MS_OK && (i < 0 || i >= r->nckpt))
        st = ms_fail(MS_ERR_INVALID_ARGUMENT, "io: checkpoint %d of %s does not exist (it has %d)",
                     i, r->path, r->nckpt);
    return st;
}

ms_status ms_reader_checkpoint_size(const ms_reader *r, int i, size_t *bytes)
{
    ms_status st = check_checkpoint(r, i);
    if (st == MS_OK)
        st = ms_check_not_null("io", "bytes", bytes);
    if (st == MS_OK)
        *bytes = r->ckpt_bytes[i];
    return st;
}

ms_status ms_reader_read_checkpoint(const ms_reader *r, int i, void *buf, size_t capacity)
{
    ms_status st = check_checkpoint(r, i);
    if (st == MS_OK)
        st = ms_check_not_null("io", "buf", buf);
    if (st != MS_OK)
        return st;
    if (capacity < r->ckpt_bytes[i])
        return ms_fail(MS_ERR_INVALID_ARGUMENT,
                       "io: checkpoint %d of %s holds %zu bytes, more than the buffer's %zu", i,
                       r->path, r->ckpt_bytes[i], capacity);
    char name[32];
    snprintf(name, sizeof name, "checkpoint/%d", r->ckpt_slot[i]);
    ms_h5_quiet q;
    ms_h5_hush(&q);
    hsize_t dims[1], start[1] = {0}, count[1] = {(hsize_t)r->ckpt_bytes[i]};
    hid_t d = open_dataset(r->file, name, H5T_INTEGER, 1, dims);
    hid_t fs = d >= 0 ? H5Dget_space(d) : -1, ms = H5Screate_simple(1, count, NULL);
    if (d < 0 || dims[0] < count[0] || fs < 0 || ms < 0 ||
        H5Sselect_hyperslab(fs, H5S_SELECT_SET, start, NULL, count, NULL) < 0 ||
        H5Dread(d, H5T_NATIVE_UCHAR, ms, fs, H5P_DEFAULT, buf) < 0)
        st = ms_h5_fail(MS_ERR_IO, "io: cannot read the checkpoint of frame %ld from %s",
                        r->ckpt_frame[i], r->path);
    if (fs >= 0)
        H5Sclose(fs);
    if (ms >= 0)
        H5Sclose(ms);
    if (d >= 0)
        H5Dclose(d);
    ms_h5_loud(&q);
    return st;
}

int ms_reader_floater_count(const ms_reader *r)
{
    return r ? r->nfloaters : 0;
}

ms_status ms_reader_read_floaters(const ms_reader *r, long frame, float *xyz, int capacity)
{
    ms_status st = check_frame(r, frame);
    if (st == MS_OK)
        st = ms_check_not_null("io", "xyz", xyz);
    if (st != MS_OK)
        return st;
    if (r->nfloaters == 0)
        return ms_fail(MS_ERR_INVALID_ARGUMENT, "io: %s holds no floaters", r->path);
    if (capacity < r->nfloaters)
        return ms_fail(MS_ERR_INVALID_ARGUMENT,
                       "io: %s holds %d floaters a frame, more than the capacity %d", r->path,
                       r->nfloaters, capacity);
    ms_h5_quiet q;
    ms_h5_hush(&q);
    hsize_t start[3] = {(hsize_t)frame, 0, 0}, count[3] = {1, (hsize_t)r->nfloaters, 3};
    hid_t fs = H5Dget_space(r->floater_dset), ms = H5Screate_simple(3, count, NULL);
    if (fs < 0 || ms < 0 || H5Sselect_hyperslab(fs, H5S_SELECT_SET, start, NULL, count, NULL) < 0 ||
        H5Dread(r->floater_dset, H5T_NATIVE_FLOAT, ms, fs, H5P_DEFAULT, xyz) < 0)
        st = ms_h5_fail(MS_ERR_IO, "io: cannot read frame %ld's floaters from %s", frame, r->path);
    if (fs >= 0)
        H5Sclose(fs);
    if (ms >= 0)
        H5Sclose(ms);
    ms_h5_loud(&q);
    return st;
}

int ms_reader_spray_budget(const ms_reader *r)
{
    return r ? r->spray_budget : 0;
}

/* One frame's rows of a [frame][...] dataset d into buf (count: the row's
 * dimensions after the frame's, rank - 1 of them). */
static ms_status read_row(const ms_reader *r, hid_t d, long frame, int rank, const hsize_t *row,
                          hid_t mtype, void *buf, const char *what)
{
    hsize_t start[3] = {(hsize_t)frame, 0, 0}, count[3] = {1, 1, 1};
    for (int i = 1; i < rank; ++i)
        count[i] = row[i - 1];
    ms_h5_quiet q;
    ms_h5_hush(&q);
    ms_status st = MS_OK;
    hid_t fs = H5Dget_space(d), ms = H5Screate_simple(rank, count, NULL);
    if (fs < 0 || ms < 0 || H5Sselect_hyperslab(fs, H5S_SELECT_SET, start, NULL, count, NULL) < 0 ||
        H5Dread(d, mtype, ms, fs, H5P_DEFAULT, buf) < 0)
        st = ms_h5_fail(MS_ERR_IO, "io: cannot read frame %ld's %s from %s", frame, what, r->path);
    if (fs >= 0)
        H5Sclose(fs);
    if (ms >= 0)
        H5Sclose(ms);
    ms_h5_loud(&q);
    return st;
}

ms_status ms_reader_read_spray(const ms_reader *r, long frame, float *xyz, int capacity, int *n)
{
    ms_status st = check_frame(r, frame);
    if (st == MS_OK && (st = ms_check_not_null("io", "n", n)) == MS_OK)
        st = ms_check_not_null("io", "xyz", xyz);
    if (st != MS_OK)
        return st;
    *n = 0;
    if (r->spray_budget == 0)
        return ms_fail(MS_ERR_INVALID_ARGUMENT, "io: %s holds no spray", r->path);
    int count = 0;
    if ((st = read_row(r, r->spray_n_dset, frame, 1, NULL, H5T_NATIVE_INT, &count,
                       "spray count")) != MS_OK)
        return st;
    if (count < 0 || count > r->spray_budget)
        return ms_fail(MS_ERR_PARSE, "io: %s: frame %ld holds %d droplets, outside [0, %d]",
                       r->path, frame, count, r->spray_budget);
    if (capacity < count)
        return ms_fail(MS_ERR_INVALID_ARGUMENT,
                       "io: frame %ld of %s holds %d droplets, more than the capacity %d", frame,
                       r->path, count, capacity);
    if (count > 0) {
        ms_h5_quiet q;
        ms_h5_hush(&q);
        hsize_t start[3] = {(hsize_t)frame, 0, 0}, cnt[3] = {1, (hsize_t)count, 3};
        hid_t fs = H5Dget_space(r->spray_dset), ms = H5Screate_simple(3, cnt, NULL);
        if (fs < 0 || ms < 0 ||
            H5Sselect_hyperslab(fs, H5S_SELECT_SET, start, NULL, cnt, NULL) < 0 ||
            H5Dread(r->spray_dset, H5T_NATIVE_FLOAT, ms, fs, H5P_DEFAULT, xyz) < 0)
            st = ms_h5_fail(MS_ERR_IO, "io: cannot read frame %ld's spray from %s", frame, r->path);
        if (fs >= 0)
            H5Sclose(fs);
        if (ms >= 0)
            H5Sclose(ms);
        ms_h5_loud(&q);
    }
    if (st == MS_OK)
        *n = count;
    return st;
}

ms_status ms_reader_foam_grid(const ms_reader *r, ms_grid *out)
{
    MS_TRY(ms_check_not_null("io", "reader", r));
    MS_TRY(ms_check_not_null("io", "out", out));
    if (r->spray_budget == 0)
        return ms_fail(MS_ERR_INVALID_ARGUMENT, "io: %s holds no foam (no spray)", r->path);
    *out = r->foam;
    return MS_OK;
}

ms_status ms_reader_read_foam(const ms_reader *r, long frame, float *out, size_t count)
{
    ms_status st = check_frame(r, frame);
    if (st == MS_OK)
        st = ms_check_not_null("io", "out", out);
    if (st != MS_OK)
        return st;
    if (r->spray_budget == 0)
        return ms_fail(MS_ERR_INVALID_ARGUMENT, "io: %s holds no foam (no spray)", r->path);
    const size_t need = (size_t)r->foam.nx * (size_t)r->foam.ny;
    if (count < need)
        return ms_fail(MS_ERR_INVALID_ARGUMENT,
                       "io: the foam needs %zu floats (%d x %d) but out holds %zu", need,
                       r->foam.nx, r->foam.ny, count);
    const hsize_t row[2] = {(hsize_t)r->foam.ny, (hsize_t)r->foam.nx};
    return read_row(r, r->foam_dset, frame, 3, row, H5T_NATIVE_FLOAT, out, "foam");
}
