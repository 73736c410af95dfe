/* lib/io: the HDF5 glue shared by the writer and the reader.
 *
 * HDF5 prints its error stack to stderr by default; the library never
 * prints, so every public io call silences it for its own duration
 * (ms_h5_hush / ms_h5_loud, per thread in a thread-safe HDF5) and turns the
 * stack into one sentence: the system's reason when HDF5 met an errno
 * ("No space left on device"), otherwise HDF5's innermost message.
 * Also the attribute read/write helpers, defensive about what a file holds.
 */
#include <errno.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "io/io_internal.h"

const char *const ms_io_field_names[MS_IO_NFIELDS] = {"combined", "surface", "volume"};

int ms_io_field_slot(unsigned field)
{
    switch (field) {
    case MS_FIELD_COMBINED:
        return MS_IO_COMBINED;
    case MS_FIELD_SURFACE:
        return MS_IO_SURFACE;
    case MS_FIELD_VOLUME:
        return MS_IO_VOLUME;
    default:
        return -1;
    }
}

void ms_h5_hush(ms_h5_quiet *q)
{
    q->func = NULL;
    q->data = NULL;
    H5Eget_auto2(H5E_DEFAULT, &q->func, &q->data);
    H5Eset_auto2(H5E_DEFAULT, NULL, NULL);
}

void ms_h5_loud(const ms_h5_quiet *q)
{
    H5Eset_auto2(H5E_DEFAULT, q->func, q->data);
}

typedef struct stack_reason {
    int err;         /* errno found in a message, 0 if none */
    char inner[256]; /* the innermost message */
    int seen;
} stack_reason;

static herr_t walk_one(unsigned n, const H5E_error2_t *e, void *data)
{
    (void)n;
    stack_reason *r = data;
    const char *desc = e->desc ? e->desc : "";
    if (!r->seen) {
        /* The innermost message, cut before its list of details. */
        size_t len = strcspn(desc, ",");
        const char *colon = strstr(desc, ": ");
        if (colon && (size_t)(colon - desc) < len)
            len = (size_t)(colon - desc);
        if (len >= sizeof r->inner)
            len = sizeof r->inner - 1;
        memcpy(r->inner, desc, len);
        r->inner[len] = '\0';
        r->seen = 1;
    }
    if (!r->err) {
        const char *p = strstr(desc, "errno = ");
        if (p) {
            int v = atoi(p + 8);
            if (v > 0)
                r->err = v;
        }
    }
    return 0;
}

ms_status ms_h5_fail(ms_status s, const char *fmt, ...)
{
    stack_reason r = {0, "", 0};
    int saved_errno = errno;
    H5Ewalk2(H5E_DEFAULT, H5E_WALK_UPWARD, walk_one, &r);
    H5Eclear2(H5E_DEFAULT);
    char head[768];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(head, sizeof head, fmt, ap);
    va_end(ap);
    const char *reason;
    if (r.err)
        reason = strerror(r.err);
    else if (r.seen && r.inner[0])
        reason = r.inner;
    else if (saved_errno)
        reason = strerror(saved_errno);
    else
        reason = "HDF5 gave no reason";
    return ms_fail(s, "%s: %s", head, reason);
}

hid_t ms_h5_fapl(void)
{
    hid_t fapl = H5Pcreate(H5P_FILE_ACCESS);
    if (fapl < 0)
        return fapl;
    /* Objects in the 1.8 format (attributes over 64 KiB, the scene text, go
     * to dense storage); the file-space setting needs a 1.10 reader. */
    if (H5Pset_libver_bounds(fapl, H5F_LIBVER_V18, H5F_LIBVER_V110) < 0 ||
        H5Pset_fapl_sec2(fapl) < 0) {
        H5Pclose(fapl);
        return -1;
    }
    /* No flock: a run is read (`modesplit info`, h5dump) while it goes on. */
    H5Pset_file_locking(fapl, 0, 1);
    return fapl;
}

/* ---- attributes ---- */

static herr_t write_attr(hid_t obj, const char *name, hid_t ftype, hid_t mtype, hid_t space,
                         const void *buf)
{
    if (H5Aexists(obj, name) > 0 && H5Adelete(obj, name) < 0)
        return -1;
    hid_t a = H5Acreate2(obj, name, ftype, space, H5P_DEFAULT, H5P_DEFAULT);
    if (a < 0)
        return -1;
    herr_t st = H5Awrite(a, mtype, buf);
    if (H5Aclose(a) < 0)
        st = -1;
    return st;
}

herr_t ms_h5_attr_string(hid_t obj, const char *name, const char *value)
{
    size_t len = strlen(value);
    hid_t t = H5Tcopy(H5T_C_S1);
    hid_t sp = H5Screate(H5S_SCALAR);
    herr_t st = -1;
    if (t >= 0 && sp >= 0 && H5Tset_size(t, len + 1) >= 0 &&
        H5Tset_strpad(t, H5T_STR_NULLTERM) >= 0 && H5Tset_cset(t, H5T_CSET_UTF8) >= 0)
        st = write_attr(obj, name, t, t, sp, value);
    if (t >= 0)
        H5Tclose(t);
    if (sp >= 0)
        H5Sclose(sp);
    return st;
}

herr_t ms_h5_attr_double(hid_t obj, const char *name, const double *v, int n)
{
    hsize_t dim = (hsize_t)n;
    hid_t sp = n == 1 ? H5Screate(H5S_SCALAR) : H5Screate_simple(1, &dim, NULL);
    if (sp < 0)
        return -1;
    herr_t st = write_attr(obj, name, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, sp, v);
    H5Sclose(sp);
    return st;
}

herr_t ms_h5_attr_int64(hid_t obj, const char *name, int64_t v)
{
    hid_t sp = H5Screate(H5S_SCALAR);
    if (sp < 0)
        return -1;
    herr_t st = write_attr(obj, name, H5T_STD_I64LE, H5T_NATIVE_INT64, sp, &v);
    H5Sclose(sp);
    return st;
}

/* Open attribute `name` and check it has `n` elements and type class cls. */
static hid_t open_attr(hid_t obj, const char *name, H5T_class_t cls, hssize_t n, hid_t *type)
{
    if (H5Aexists(obj, name) <= 0)
        return -1;
    hid_t a = H5Aopen(obj, name, H5P_DEFAULT);
    if (a < 0)
        return -1;
    hid_t sp = H5Aget_space(a);
    hssize_t count = sp >= 0 ? H5Sget_simple_extent_npoints(sp) : -1;
    if (sp >= 0)
        H5Sclose(sp);
    hid_t t = H5Aget_type(a);
    if (count != n || t < 0 || H5Tget_class(t) != cls) {
        if (t >= 0)
            H5Tclose(t);
        H5Aclose(a);
        return -1;
    }
    *type = t;
    return a;
}

herr_t ms_h5_read_string(hid_t obj, const char *name, size_t max_len, char **out)
{
    *out = NULL;
    hid_t t;
    hid_t a = open_attr(obj, name, H5T_STRING, 1, &t);
    if (a < 0)
        return -1;
    herr_t st = -1;
    htri_t vlen = H5Tis_variable_str(t);
    hid_t mt = H5Tcopy(H5T_C_S1);
    H5T_cset_t cset = H5Tget_cset(t);
    /* HDF5 does not convert between ASCII and UTF-8: read as the file says */
    if (mt >= 0 && (cset < 0 || H5Tset_cset(mt, cset) < 0)) {
        H5Tclose(mt);
        mt = -1;
    }
    if (vlen > 0) {
        char *p = NULL;
        if (mt >= 0 && H5Tset_size(mt, H5T_VARIABLE) >= 0 && H5Aread(a, mt, &p) >= 0 && p) {
            size_t len = strnlen(p, max_len);
            *out = ms_malloc(len + 1);
            if (*out) {
                memcpy(*out, p, len);
                (*out)[len] = '\0';
                st = 0;
            }
        }
        if (p)
            H5free_memory(p);
    } else if (vlen == 0) {
        size_t size = H5Tget_size(t);
        if (size > 0 && size <= max_len && mt >= 0 && H5Tset_size(mt, size) >= 0 &&
            H5Tset_strpad(mt, H5T_STR_NULLPAD) >= 0) {
            char *buf = ms_alloc_array(size + 1, 1);
            if (buf && H5Aread(a, mt, buf) >= 0) {
                *out = buf;
                st = 0;
            } else {
                ms_free(buf);
            }
        }
    }
    if (mt >= 0)
        H5Tclose(mt);
    H5Tclose(t);
    H5Aclose(a);
    return st;
}

herr_t ms_h5_read_doubles(hid_t obj, const char *name, double *v, int n)
{
    hid_t t;
    hid_t a = open_attr(obj, name, H5T_FLOAT, n, &t);
    if (a < 0) {
        /* Integers are numbers too. */
        a = open_attr(obj, name, H5T_INTEGER, n, &t);
        if (a < 0)
            return -1;
    }
    herr_t st = H5Aread(a, H5T_NATIVE_DOUBLE, v);
    H5Tclose(t);
    H5Aclose(a);
    return st;
}

herr_t ms_h5_read_int64(hid_t obj, const char *name, int64_t *v)
{
    hid_t t;
    hid_t a = open_attr(obj, name, H5T_INTEGER, 1, &t);
    if (a < 0)
        return -1;
    herr_t st = H5Aread(a, H5T_NATIVE_INT64, v);
    H5Tclose(t);
    H5Aclose(a);
    return st;
}

/* The walk of ms_h5_check_links: the first link that is not a hard link goes
 * into name (and stops the walk); groups are walked to a depth. */
typedef struct link_walk {
    char name[256];
    int depth;
} link_walk;

static herr_t foreign_link(hid_t g, const char *name, const H5L_info_t *info, void *data)
{
    link_walk *w = data;
    if (info->type != H5L_TYPE_HARD) {
        snprintf(w->name, sizeof w->name, "%s", name);
        return 1;
    }
    /* An object the file does not hold yet (a live run's frame being
     * written lies past the end of allocation) cannot be opened by the
     * reader either: its links do not matter, so it is passed over. */
    H5O_info_t oi;
    if (w->depth >= 8 || H5Oget_info_by_name(g, name, &oi, H5P_DEFAULT) < 0 ||
        oi.type != H5O_TYPE_GROUP) {
        H5Eclear2(H5E_DEFAULT);
        return 0;
    }
    hid_t sub = H5Gopen2(g, name, H5P_DEFAULT);
    if (sub < 0) {
        H5Eclear2(H5E_DEFAULT);
        return 0;
    }
    w->depth++;
    herr_t e = H5Literate(sub, H5_INDEX_NAME, H5_ITER_NATIVE, NULL, foreign_link, w);
    w->depth--;
    H5Gclose(sub);
    H5Eclear2(H5E_DEFAULT);
    return e > 0 ? 1 : 0;
}

ms_status ms_h5_check_links(hid_t file, const char *path)
{
    link_walk w = {"", 0};
    herr_t e = H5Literate(file, H5_INDEX_NAME, H5_ITER_NATIVE, NULL, foreign_link, &w);
    if (e > 0) {
        /* the name is the link's own; its group is not kept */
        return ms_fail(MS_ERR_PARSE,
                       "io: %s: %.200s is an external or soft link; a run file holds all "
                       "its objects itself, so it is refused",
                       path, w.name);
    }
    if (e < 0)
        return ms_h5_fail(MS_ERR_PARSE, "io: %s: cannot list its objects", path);
    return MS_OK;
}

int ms_h5_dataset_own(hid_t d)
{
    hid_t dcpl = H5Dget_create_plist(d);
    int own = dcpl >= 0 && H5Pget_external_count(dcpl) == 0 && H5Pget_layout(dcpl) != H5D_VIRTUAL;
    if (dcpl >= 0)
        H5Pclose(dcpl);
    H5Eclear2(H5E_DEFAULT);
    return own;
}
