/* lib/io: the XDMF sidecars that let ParaView and VisIt open a run file as
 * a time series.
 *
 * Two sidecars, one per reader family, written side by side (format_version 2):
 *   run.xmf    for ParaView's default reader of .xmf (Xdmf3ReaderS). Xdmf3
 *              reads neither HyperSlab items nor X_Y_Z geometry (it skips
 *              them, "unrecognized array type"), so a frame of a field is
 *              an HDF item with Xdmf3's own selection suffix
 *              "file:/fields/name|start:stride:count:dataspace", and the
 *              particles' geometry and velocity are the [n][3] arrays of
 *              /particles/<frame> (see h5part.c).
 *   run.xdmf2  for the legacy XDMF reader ("XDMF Reader", Xdmf2, which
 *              ParaView picks for .xdmf2) and VisIt: fields as HyperSlab
 *              items, which that reader reads and Xdmf3 does not.
 * run.xmf is one temporal collection; each written frame is a spatial
 * collection with its <Time>, one uniform grid per distinct field grid
 * (combined and surface share the wave grid, volume has the SPH grid) and,
 * when the frame has particles, a poly-vertex grid of them with `velocity`
 * (3-vector) and `id`, one vertex cell per particle, and with spray a
 * grid "foam" (the cover, point data on its grid) and, when droplets fly,
 * a poly-vertex grid "spray" (the legacy sidecar: the grid files
 * foam.xml and spray.xml, spray.xml listing the frames in which droplets
 * fly). The grids are named
 * after what they hold, but ParaView 5.11's Xdmf3ReaderS (what File > Open
 * picks) flattens every file into one unnamed multipiece, whatever its
 * nesting: named blocks come from the legacy sidecar. The legacy reader
 * names a block of such a file after the grid *and the frame*
 * ("volume[89]"), so a selected block does not animate; it names blocks
 * cleanly only for a spatial collection of temporal collections, one per
 * grid. run.xdmf2 is that: a spatial
 * collection that XIncludes one file per grid, run.xdmf2.d/<grid>.xml,
 * each a temporal collection of that grid's frames. Grid names are the
 * fields they hold ("combined surface", "volume", "particles"), the same in
 * every frame. A height field is point data on a 3DCoRectMesh of
 * 1 x ny x nx points placed at the cell centres; XDMF lists dimensions
 * slowest first (z y x), and so its origin and spacing.
 *
 * The files are kept valid after every frame: the closing tags are written
 * after the last frame, and the next frame is written over them together
 * with a fresh copy, so a run killed at any moment leaves well-formed XML
 * that lists the frames written so far. run.xmf gets it in a copy of the
 * file made before the HDF5 frame (ms_xdmf_prepare: a full disk refuses
 * the frame before anything is written) and renamed over it once the frame
 * is committed; the legacy grid files in one pwrite each. A run of no
 * frame has an empty <Domain> (an empty temporal collection crashes the
 * legacy reader): run.xmf's temporal collection opens with the first frame,
 * and run.xdmf2 (rewritten whole, by rename) includes a grid's file once it
 * holds a frame.
 */
#include <errno.h>
#include <fcntl.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "io/io_internal.h"

static const char TAIL[] = "  </Grid>\n </Domain>\n</Xdmf>\n";
static const char EMPTY_TAIL[] = " </Domain>\n</Xdmf>\n";
static const char COLLECTION[] =
    "  <Grid Name=\"run\" GridType=\"Collection\" CollectionType=\"Temporal\">\n";

struct ms_xdmf {
    int fd;
    char *path;
    char *h5;      /* the HDF5 file's name, XML-escaped */
    off_t tail_at; /* where the closing tags start */
    int legacy;    /* 1: Xdmf2 HyperSlab items; 0: Xdmf3 selections */
    long frames;   /* frames listed */
    ms_writer_layout layout;
    int group_of[MS_IO_NFIELDS]; /* first field slot with the same grid */
    /* legacy: one XIncluded file per grid (field slots, then particles) */
    char *dir;                  /* run.xdmf2.d */
    char *dir_name;             /* its last component, for the hrefs */
    int gfd[MS_IO_NFIELDS + 3]; /* field slots, particles, foam, spray */
    off_t gtail[MS_IO_NFIELDS + 3];
    long gcount[MS_IO_NFIELDS + 3];
    /* run.xmf's next state, made by ms_xdmf_prepare: a copy under
     * pending_path, renamed over path by ms_xdmf_frame */
    int pending_fd;     /* -1: none */
    char *pending_path; /* path.tmp */
    off_t pending_body; /* bytes the frame adds before the closing tags */
    int spray;          /* the next frame's spray droplets (ms_xdmf_set_spray) */
};

#define PARTICLE_GROUP MS_IO_NFIELDS
#define FOAM_GROUP (MS_IO_NFIELDS + 1)
#define SPRAY_GROUP (MS_IO_NFIELDS + 2)
#define NGROUPS (MS_IO_NFIELDS + 3)
static const char GROUP_TAIL[] = "</Grid>\n";

static ms_status write_legacy_main(const ms_xdmf *x);

/* A growing string. */
typedef struct sbuf {
    char *p;
    size_t len, cap;
    int oom;
} sbuf;

static void sb_printf(sbuf *b, const char *fmt, ...) MS_PRINTF(2, 3);
static void sb_printf(sbuf *b, const char *fmt, ...)
{
    if (b->oom)
        return;
    for (;;) {
        va_list ap;
        va_start(ap, fmt);
        size_t room = b->cap - b->len;
        int n = vsnprintf(b->p ? b->p + b->len : NULL, b->p ? room : 0, fmt, ap);
        va_end(ap);
        if (n < 0) {
            b->oom = 1;
            return;
        }
        if (b->p && (size_t)n < room) {
            b->len += (size_t)n;
            return;
        }
        size_t cap = b->cap ? b->cap : 4096;
        while (cap - b->len <= (size_t)n)
            cap *= 2;
        char *q = ms_realloc(b->p, cap);
        if (!q) {
            b->oom = 1;
            return;
        }
        b->p = q;
        b->cap = cap;
    }
}

static char *xml_escape(const char *s)
{
    sbuf b = {0};
    for (; *s; ++s) {
        switch (*s) {
        case '&':
            sb_printf(&b, "&amp;");
            break;
        case '<':
            sb_printf(&b, "&lt;");
            break;
        case '>':
            sb_printf(&b, "&gt;");
            break;
        case '"':
            sb_printf(&b, "&quot;");
            break;
        case '\'':
            sb_printf(&b, "&apos;");
            break;
        default:
            sb_printf(&b, "%c", *s);
            break;
        }
    }
    if (!b.p && !b.oom)
        sb_printf(&b, "%s", "");
    if (b.oom) {
        ms_free(b.p);
        return NULL;
    }
    return b.p;
}

char *ms_xdmf_path_for(const char *h5_path)
{
    size_t n = strlen(h5_path);
    char *p = ms_malloc(n + 5);
    if (!p)
        return NULL;
    memcpy(p, h5_path, n + 1);
    if (n > 3 && strcmp(h5_path + n - 3, ".h5") == 0)
        strcpy(p + n - 3, ".xmf");
    else if (n > 5 && strcmp(h5_path + n - 5, ".hdf5") == 0)
        strcpy(p + n - 5, ".xmf");
    else
        strcat(p, ".xmf");
    return p;
}

static int write_all_at(int fd, const char *buf, size_t len, off_t at)
{
    while (len > 0) {
        ssize_t n = pwrite(fd, buf, len, at);
        if (n < 0) {
            if (errno == EINTR)
                continue;
            return -1;
        }
        if (n == 0) {
            errno = ENOSPC;
            return -1;
        }
        buf += n;
        len -= (size_t)n;
        at += n;
    }
    return 0;
}

char *ms_xdmf_legacy_path_for(const char *h5_path)
{
    char *p = ms_xdmf_path_for(h5_path);
    char *q = p ? ms_realloc(p, strlen(p) + 3) : NULL;
    if (!q) {
        ms_free(p);
        return NULL;
    }
    strcpy(q + strlen(q) - 4, ".xdmf2"); /* ".xmf" -> ".xdmf2" */
    return q;
}

ms_status ms_xdmf_open(const char *xmf_path, const char *h5_name, const ms_writer_layout *l,
                       int legacy, ms_xdmf **out)
{
    *out = NULL;
    ms_xdmf *x = ms_alloc_array(1, sizeof *x);
    if (!x)
        return ms_fail(MS_ERR_OUT_OF_MEMORY, "io: out of memory for the XDMF sidecar");
    x->fd = -1;
    x->pending_fd = -1;
    for (int i = 0; i < NGROUPS; ++i)
        x->gfd[i] = -1;
    x->layout = *l;
    x->legacy = legacy;
    x->path = ms_strdup(xmf_path);
    x->h5 = xml_escape(h5_name);
    if (legacy && x->path) {
        size_t n = strlen(xmf_path);
        x->dir = ms_malloc(n + 3);
        if (x->dir) {
            memcpy(x->dir, xmf_path, n);
            memcpy(x->dir + n, ".d", 3);
            const char *slash = strrchr(x->dir, '/');
            x->dir_name = xml_escape(slash ? slash + 1 : x->dir);
        }
    }
    if (!x->path || !x->h5 || (legacy && (!x->dir || !x->dir_name))) {
        ms_xdmf_close(x);
        return ms_fail(MS_ERR_OUT_OF_MEMORY, "io: out of memory for the XDMF sidecar");
    }
    for (int i = 0; i < MS_IO_NFIELDS; ++i) {
        x->group_of[i] = i;
        for (int j = 0; j < i; ++j) {
            const ms_grid *a = &l->grid[i], *b = &l->grid[j];
            if ((l->fields & (1u << j)) && a->nx == b->nx && a->ny == b->ny && a->dx == b->dx &&
                a->dy == b->dy && a->origin[0] == b->origin[0] && a->origin[1] == b->origin[1]) {
                x->group_of[i] = j;
                break;
            }
        }
    }
    if (legacy) {
        ms_status st = MS_OK;
        if (mkdir(x->dir, 0777) != 0 && errno != EEXIST)
            st = ms_fail(MS_ERR_IO, "io: cannot create the directory %s: %s", x->dir,
                         strerror(errno));
        else
            st = write_legacy_main(x);
        if (st != MS_OK) {
            ms_xdmf_close(x);
            return st;
        }
        *out = x;
        return MS_OK;
    }
    x->fd = open(xmf_path, O_RDWR | O_CREAT | O_TRUNC | O_CLOEXEC, 0666);
    if (x->fd < 0) {
        int e = errno;
        ms_xdmf_close(x);
        return ms_fail(MS_ERR_IO, "io: cannot create the XDMF sidecar %s: %s", xmf_path,
                       strerror(e));
    }
    sbuf b = {0};
    sb_printf(&b,
              "<?xml version=\"1.0\" ?>\n"
              "<!DOCTYPE Xdmf SYSTEM \"Xdmf.dtd\" []>\n"
              "<!-- modesplit %s: the frames of %s as a time series (open this file in "
              "ParaView) -->\n"
              "<Xdmf Version=\"%s\">\n"
              " <Domain>\n",
              ms_version(), x->h5, legacy ? "2.0" : "3.0");
    x->tail_at = (off_t)b.len;
    sb_printf(&b, "%s", EMPTY_TAIL);
    int bad = b.oom || write_all_at(x->fd, b.p, b.len, 0) < 0;
    int e = errno;
    ms_free(b.p);
    if (bad) {
        ms_xdmf_close(x);
        return ms_fail(MS_ERR_IO, "io: cannot write the XDMF sidecar %s: %s", xmf_path,
                       strerror(e));
    }
    *out = x;
    return MS_OK;
}

/* "combined surface": the fields on this grid, the block's name. */
static void grid_name(sbuf *b, const ms_xdmf *x, int slot)
{
    const char *sep = "";
    for (int i = 0; i < MS_IO_NFIELDS; ++i)
        if ((x->layout.fields & (1u << i)) && x->group_of[i] == slot) {
            sb_printf(b, "%s%s", sep, ms_io_field_names[i]);
            sep = " ";
        }
}

/* A 2D grid's opening after its name (the caller prints `<Grid Name="`
 * and the name): the time, and its points at the cell centres. */
static void grid2d_open(sbuf *b, const ms_grid *g, const char *time_xml)
{
    double ox = (double)g->origin[0] + 0.5 * g->dx, oy = (double)g->origin[1] + 0.5 * g->dy;
    sb_printf(b,
              "\" GridType=\"Uniform\">\n%s"
              "     <Topology TopologyType=\"3DCoRectMesh\" Dimensions=\"1 %d %d\"/>\n"
              "     <Geometry GeometryType=\"ORIGIN_DXDYDZ\">\n"
              "      <DataItem Dimensions=\"3\" NumberType=\"Float\" Precision=\"8\" "
              "Format=\"XML\">0 %.17g %.17g</DataItem>\n"
              "      <DataItem Dimensions=\"3\" NumberType=\"Float\" Precision=\"8\" "
              "Format=\"XML\">1 %.9g %.9g</DataItem>\n"
              "     </Geometry>\n",
              time_xml, g->ny, g->nx, oy, ox, (double)g->dy, (double)g->dx);
}

/* The attribute NAME of a 2D grid: frame's plane of the [frame][y][x]
 * dataset DSET, as a HyperSlab item (legacy) or with Xdmf3's
 * path|start:stride:count:dataspace suffix (the dataset holds >= frame+1). */
static void frame_attribute(sbuf *b, const ms_xdmf *x, const ms_grid *g, const char *name,
                            const char *dset, long frame)
{
    sb_printf(b, "     <Attribute Name=\"%s\" AttributeType=\"Scalar\" Center=\"Node\">\n", name);
    if (x->legacy)
        sb_printf(b,
                  "      <DataItem ItemType=\"HyperSlab\" Dimensions=\"1 %d %d\" "
                  "Type=\"HyperSlab\">\n"
                  "       <DataItem Dimensions=\"3 3\" Format=\"XML\">%ld 0 0 1 1 1 1 %d %d"
                  "</DataItem>\n"
                  "       <DataItem Dimensions=\"%ld %d %d\" NumberType=\"Float\" "
                  "Precision=\"4\" Format=\"HDF\">%s:%s</DataItem>\n"
                  "      </DataItem>\n",
                  g->ny, g->nx, frame, g->ny, g->nx, frame + 1, g->ny, g->nx, x->h5, dset);
    else
        sb_printf(b,
                  "      <DataItem Dimensions=\"1 %d %d\" NumberType=\"Float\" "
                  "Precision=\"4\" Format=\"HDF\">%s:%s|%ld 0 0:1 1 1:1 %d %d:"
                  "%ld %d %d</DataItem>\n",
                  g->ny, g->nx, x->h5, dset, frame, g->ny, g->nx, frame + 1, g->ny, g->nx);
    sb_printf(b, "     </Attribute>\n");
}

static void field_grid_xml(sbuf *b, const ms_xdmf *x, int slot, long frame, const char *time_xml)
{
    const ms_grid *g = &x->layout.grid[slot];
    sb_printf(b, "    <Grid Name=\"");
    grid_name(b, x, slot);
    grid2d_open(b, g, time_xml);
    for (int i = 0; i < MS_IO_NFIELDS && frame >= 0; ++i) {
        if (!(x->layout.fields & (1u << i)) || x->group_of[i] != slot)
            continue;
        char dset[64];
        snprintf(dset, sizeof dset, "/fields/%s", ms_io_field_names[i]);
        frame_attribute(b, x, g, ms_io_field_names[i], dset, frame);
    }
    sb_printf(b, "    </Grid>\n");
}

/* The foam cover of a frame as point data on its grid, as a height field
 * is (both files). */
static void foam_xml(sbuf *b, const ms_xdmf *x, long frame, const char *time_xml)
{
    sb_printf(b, "    <Grid Name=\"foam");
    grid2d_open(b, &x->layout.foam, time_xml);
    frame_attribute(b, x, &x->layout.foam, "foam", "/foam", frame);
    sb_printf(b, "    </Grid>\n");
}

/* The particles as one vertex cell each. Xdmf3 makes no cells of a
 * Polyvertex topology without connectivity (ParaView's default reader then
 * shows the points but draws nothing), so the connectivity is given: the
 * step's `id` dataset, which holds 0 .. n-1 in array order (h5part.c,
 * write_ids), so cell i is point i. The legacy reader reads the same. */
static void particles_xml(sbuf *b, const ms_xdmf *x, long frame, int n, const char *time_xml)
{
    char step[48];
    ms_h5part_step_name(step, sizeof step, frame);
    sb_printf(b,
              "    <Grid Name=\"particles\" GridType=\"Uniform\">\n%s"
              "     <Topology TopologyType=\"Polyvertex\" NumberOfElements=\"%d\" "
              "NodesPerElement=\"1\">\n"
              "      <DataItem Dimensions=\"%d\" NumberType=\"Int\" Precision=\"4\" "
              "Format=\"HDF\">%s:/%s/id</DataItem>\n"
              "     </Topology>\n"
              "     <Geometry GeometryType=\"XYZ\">\n"
              "      <DataItem Dimensions=\"%d 3\" NumberType=\"Float\" Precision=\"4\" "
              "Format=\"HDF\">%s:/particles/%ld/position</DataItem>\n"
              "     </Geometry>\n"
              "     <Attribute Name=\"velocity\" AttributeType=\"Vector\" Center=\"Node\">\n"
              "      <DataItem Dimensions=\"%d 3\" NumberType=\"Float\" Precision=\"4\" "
              "Format=\"HDF\">%s:/particles/%ld/velocity</DataItem>\n"
              "     </Attribute>\n"
              "     <Attribute Name=\"id\" AttributeType=\"Scalar\" Center=\"Node\">\n"
              "      <DataItem Dimensions=\"%d\" NumberType=\"Int\" Precision=\"4\" "
              "Format=\"HDF\">%s:/%s/id</DataItem>\n"
              "     </Attribute>\n"
              "    </Grid>\n",
              time_xml, n, n, x->h5, step, n, x->h5, frame, n, x->h5, frame, n, x->h5, step);
}

void ms_xdmf_set_spray(ms_xdmf *x, int n)
{
    if (x)
        x->spray = n;
}

/* The spray of a frame (run.xmf only): the foam cover, and the first n
 * rows of /spray's frame as vertex cells (connectivity: the first n of
 * /spray_id, which holds 0 .. budget-1). */
static void spray_xml(sbuf *b, const ms_xdmf *x, long frame, int n)
{
    const int budget = x->layout.spray;
    foam_xml(b, x, frame, "");
    if (n <= 0)
        return;
    sb_printf(b,
              "    <Grid Name=\"spray\" GridType=\"Uniform\">\n"
              "     <Topology TopologyType=\"Polyvertex\" NumberOfElements=\"%d\" "
              "NodesPerElement=\"1\">\n"
              "      <DataItem Dimensions=\"%d\" NumberType=\"Int\" Precision=\"4\" "
              "Format=\"HDF\">%s:/spray_id|0:1:%d:%d</DataItem>\n"
              "     </Topology>\n"
              "     <Geometry GeometryType=\"XYZ\">\n"
              "      <DataItem Dimensions=\"%d 3\" NumberType=\"Float\" Precision=\"4\" "
              "Format=\"HDF\">%s:/spray|%ld 0 0:1 1 1:1 %d 3:%ld %d 3</DataItem>\n"
              "     </Geometry>\n"
              "    </Grid>\n",
              n, n, x->h5, n, budget, n, x->h5, frame, n, frame + 1, budget);
}

/* ---- legacy: run.xdmf2 + run.xdmf2.d/<grid>.xml ---- */

static const char *group_file(int g)
{
    return g == PARTICLE_GROUP ? "particles"
           : g == FOAM_GROUP   ? "foam"
           : g == SPRAY_GROUP  ? "spray"
                               : ms_io_field_names[g];
}

static void group_name(sbuf *b, const ms_xdmf *x, int g)
{
    if (g >= PARTICLE_GROUP)
        sb_printf(b, "%s", group_file(g));
    else
        grid_name(b, x, g);
}

/* The legacy sidecar's droplets of a frame: HyperSlab items of /spray
 * [frame][budget][3] and /spray_id [budget], the selections run.xmf makes
 * with Xdmf3's suffix (its foam: foam_xml). */
static void legacy_spray_xml(sbuf *b, const ms_xdmf *x, long frame, int n, const char *time_xml)
{
    const int budget = x->layout.spray;
    sb_printf(b,
              "    <Grid Name=\"spray\" GridType=\"Uniform\">\n%s"
              "     <Topology TopologyType=\"Polyvertex\" NumberOfElements=\"%d\" "
              "NodesPerElement=\"1\">\n"
              "      <DataItem ItemType=\"HyperSlab\" Dimensions=\"%d\" Type=\"HyperSlab\">\n"
              "       <DataItem Dimensions=\"3 1\" Format=\"XML\">0 1 %d</DataItem>\n"
              "       <DataItem Dimensions=\"%d\" NumberType=\"Int\" Precision=\"4\" "
              "Format=\"HDF\">%s:/spray_id</DataItem>\n"
              "      </DataItem>\n"
              "     </Topology>\n"
              "     <Geometry GeometryType=\"XYZ\">\n"
              "      <DataItem ItemType=\"HyperSlab\" Dimensions=\"%d 3\" "
              "Type=\"HyperSlab\">\n"
              "       <DataItem Dimensions=\"3 3\" Format=\"XML\">%ld 0 0 1 1 1 1 %d 3"
              "</DataItem>\n"
              "       <DataItem Dimensions=\"%ld %d 3\" NumberType=\"Float\" "
              "Precision=\"4\" Format=\"HDF\">%s:/spray</DataItem>\n"
              "      </DataItem>\n"
              "     </Geometry>\n"
              "    </Grid>\n",
              time_xml, n, n, n, budget, x->h5, n, frame, n, frame + 1, budget, x->h5);
}

/* The main file, listing the grids that hold a frame: written to a
 * temporary name and renamed over, so a reader sees the old or the new. */
static ms_status write_legacy_main(const ms_xdmf *x)
{
    sbuf b = {0};
    int any = 0;
    for (int g = 0; g < NGROUPS; ++g)
        any |= x->gcount[g] > 0;
    sb_printf(&b,
              "<?xml version=\"1.0\" ?>\n"
              "<!-- modesplit %s: the frames of %s as a time series, for the legacy XDMF "
              "reader and VisIt (ParaView's default reader: the .xmf file) -->\n"
              "<Xdmf Version=\"2.0\" xmlns:xi=\"http://www.w3.org/2001/XInclude\">\n"
              " <Domain>\n",
              ms_version(), x->h5);
    sb_printf(&b, "  <Grid Name=\"run\" GridType=\"Collection\" CollectionType=\"Spatial\">\n");
    for (int g = 0; g < NGROUPS; ++g)
        if (x->gcount[g] > 0)
            sb_printf(&b, "   <xi:include href=\"%s/%s.xml\"/>\n", x->dir_name, group_file(g));
    if (!any) {
        /* No frame yet: the legacy reader crashes on a Domain without a
         * grid, so list the field grids without data (or, for a run of
         * particles only, an empty point set). */
        int fields = 0;
        for (int i = 0; i < MS_IO_NFIELDS; ++i)
            if ((x->layout.fields & (1u << i)) && x->group_of[i] == i) {
                field_grid_xml(&b, x, i, -1, "");
                fields = 1;
            }
        if (!fields)
            sb_printf(&b, "    <Grid Name=\"particles\" GridType=\"Uniform\">\n"
                          "     <Topology TopologyType=\"Polyvertex\" NumberOfElements=\"0\"/>\n"
                          "     <Geometry GeometryType=\"XYZ\">\n"
                          "      <DataItem Dimensions=\"0 3\" Format=\"XML\"></DataItem>\n"
                          "     </Geometry>\n"
                          "    </Grid>\n");
    }
    sb_printf(&b, "  </Grid>\n");
    sb_printf(&b, "%s", EMPTY_TAIL);
    size_t n = strlen(x->path);
    char *tmp = ms_malloc(n + 5);
    if (b.oom || !tmp) {
        ms_free(b.p);
        ms_free(tmp);
        return ms_fail(MS_ERR_OUT_OF_MEMORY, "io: out of memory for the XDMF sidecar");
    }
    memcpy(tmp, x->path, n);
    memcpy(tmp + n, ".tmp", 5);
    ms_status st = MS_OK;
    int fd = open(tmp, O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0666);
    if (fd < 0 || write_all_at(fd, b.p, b.len, 0) < 0 || close(fd) != 0 ||
        rename(tmp, x->path) != 0) {
        st = ms_fail(MS_ERR_IO, "io: cannot write the XDMF sidecar %s: %s", x->path,
                     strerror(errno));
        unlink(tmp);
    }
    ms_free(tmp);
    ms_free(b.p);
    return st;
}

/* Append one entry to grid g's file (created with its first entry). */
static ms_status legacy_append(ms_xdmf *x, int g, const sbuf *entry)
{
    sbuf b = {0};
    if (x->gcount[g] == 0) {
        size_t n = strlen(x->dir) + strlen(group_file(g)) + 6;
        char *p = ms_malloc(n);
        if (!p)
            return ms_fail(MS_ERR_OUT_OF_MEMORY, "io: out of memory for the XDMF sidecar");
        snprintf(p, n, "%s/%s.xml", x->dir, group_file(g));
        x->gfd[g] = open(p, O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0666);
        if (x->gfd[g] < 0) {
            ms_status st = ms_fail(MS_ERR_IO, "io: cannot create %s: %s", p, strerror(errno));
            ms_free(p);
            return st;
        }
        ms_free(p);
        sb_printf(&b, "<Grid Name=\"");
        group_name(&b, x, g);
        sb_printf(&b, "\" GridType=\"Collection\" CollectionType=\"Temporal\">\n");
    }
    sb_printf(&b, "%s", entry->p ? entry->p : "");
    size_t body = b.len;
    sb_printf(&b, "%s", GROUP_TAIL);
    if (b.oom || entry->oom) {
        ms_free(b.p);
        return ms_fail(MS_ERR_OUT_OF_MEMORY, "io: out of memory for the XDMF sidecar");
    }
    int bad = write_all_at(x->gfd[g], b.p, b.len, x->gtail[g]) < 0;
    int e = errno;
    ms_free(b.p);
    if (bad)
        return ms_fail(MS_ERR_IO, "io: writing to the XDMF grid files in %s failed: %s", x->dir,
                       strerror(e));
    x->gtail[g] += (off_t)body;
    x->gcount[g]++;
    return MS_OK;
}

static ms_status legacy_frame(ms_xdmf *x, long frame, double t, int particles)
{
    char time_xml[64];
    snprintf(time_xml, sizeof time_xml, "     <Time Value=\"%.17g\"/>\n", t);
    int grew = 0;
    ms_status st = MS_OK;
    for (int g = 0; g < NGROUPS && st == MS_OK; ++g) {
        int field = g < MS_IO_NFIELDS && (x->layout.fields & (1u << g)) && x->group_of[g] == g;
        if (!field && !(g == PARTICLE_GROUP && particles > 0) &&
            !(g == FOAM_GROUP && x->layout.spray > 0) &&
            !(g == SPRAY_GROUP && x->layout.spray > 0 && x->spray > 0))
            continue;
        sbuf e = {0};
        if (field)
            field_grid_xml(&e, x, g, frame, time_xml);
        else if (g == PARTICLE_GROUP)
            particles_xml(&e, x, frame, particles, time_xml);
        else if (g == FOAM_GROUP)
            foam_xml(&e, x, frame, time_xml);
        else
            legacy_spray_xml(&e, x, frame, x->spray, time_xml);
        grew |= x->gcount[g] == 0;
        st = legacy_append(x, g, &e);
        ms_free(e.p);
    }
    if (st == MS_OK && grew)
        st = write_legacy_main(x);
    if (st == MS_OK)
        x->frames++;
    return st;
}

/* Write run.xmf's next state, with frame's entry, to path.tmp (a copy of
 * the listed frames, then the entry and the closing tags); ms_xdmf_frame
 * renames it over run.xmf. Why not one pwrite over the closing tags: a
 * buffered write spanning pages stops between two pages when SIGKILL
 * arrives (the kernel checks for a fatal signal per page), and that left
 * run.xmf cut at a page boundary without its closing tags (seen under
 * load: a killed.xmf of 12288 bytes, 3 pages). The copy costs O(file) a
 * frame (about 2 kB a frame listed). The legacy sidecar: nothing here. */
ms_status ms_xdmf_prepare(ms_xdmf *x, long frame, double t, int particles)
{
    if (x->legacy)
        return MS_OK;
    ms_xdmf_drop_pending(x);
    sbuf b = {0};
    if (x->frames == 0)
        sb_printf(&b, "%s", COLLECTION);
    sb_printf(&b,
              "   <Grid Name=\"frame %ld\" GridType=\"Collection\" CollectionType=\"Spatial\">\n"
              "    <Time Value=\"%.17g\"/>\n",
              frame, t);
    for (int i = 0; i < MS_IO_NFIELDS; ++i)
        if ((x->layout.fields & (1u << i)) && x->group_of[i] == i)
            field_grid_xml(&b, x, i, frame, "");
    if (particles > 0)
        particles_xml(&b, x, frame, particles, "");
    if (x->layout.spray > 0)
        spray_xml(&b, x, frame, x->spray);
    sb_printf(&b, "   </Grid>\n");
    size_t body = b.len;
    sb_printf(&b, "%s", TAIL);
    size_t n = strlen(x->path);
    char *tmp = ms_malloc(n + 5);
    if (b.oom || !tmp) {
        ms_free(b.p);
        ms_free(tmp);
        return ms_fail(MS_ERR_OUT_OF_MEMORY, "io: out of memory for the XDMF sidecar");
    }
    memcpy(tmp, x->path, n);
    memcpy(tmp + n, ".tmp", 5);
    int fd = open(tmp, O_RDWR | O_CREAT | O_TRUNC | O_CLOEXEC, 0666);
    int bad = fd < 0;
    char chunk[16384];
    for (off_t at = 0; !bad && at < x->tail_at;) {
        size_t want =
            (size_t)(x->tail_at - at) < sizeof chunk ? (size_t)(x->tail_at - at) : sizeof chunk;
        ssize_t got = pread(x->fd, chunk, want, at);
        if (got < 0 && errno == EINTR)
            continue;
        if (got <= 0) {
            if (got == 0)
                errno = EIO; /* the sidecar shrank under us */
            bad = 1;
            break;
        }
        bad = write_all_at(fd, chunk, (size_t)got, at) < 0;
        at += got;
    }
    if (!bad)
        bad = write_all_at(fd, b.p, b.len, x->tail_at) < 0;
    int e = errno;
    ms_free(b.p);
    if (bad) {
        if (fd >= 0)
            close(fd);
        unlink(tmp);
        ms_free(tmp);
        return ms_fail(MS_ERR_IO, "io: writing frame %ld to the XDMF sidecar %s failed: %s", frame,
                       x->path, strerror(e));
    }
    x->pending_fd = fd;
    x->pending_path = tmp;
    x->pending_body = (off_t)body;
    return MS_OK;
}

void ms_xdmf_drop_pending(ms_xdmf *x)
{
    if (!x || x->pending_fd < 0)
        return;
    close(x->pending_fd);
    unlink(x->pending_path);
    ms_free(x->pending_path);
    x->pending_fd = -1;
    x->pending_path = NULL;
}

uint64_t ms_xdmf_copy_bytes(const ms_xdmf *x)
{
    return x && !x->legacy ? (uint64_t)x->tail_at + 65536u : 0;
}

ms_status ms_xdmf_frame(ms_xdmf *x, long frame, double t, int particles)
{
    if (x->legacy)
        return legacy_frame(x, frame, t, particles);
    ms_status st = x->pending_fd >= 0 ? MS_OK : ms_xdmf_prepare(x, frame, t, particles);
    if (st != MS_OK)
        return st;
    if (rename(x->pending_path, x->path) != 0) {
        int e = errno;
        ms_xdmf_drop_pending(x);
        return ms_fail(MS_ERR_IO, "io: writing frame %ld to the XDMF sidecar %s failed: %s", frame,
                       x->path, strerror(e));
    }
    close(x->fd);
    x->fd = x->pending_fd;
    ms_free(x->pending_path);
    x->pending_fd = -1;
    x->pending_path = NULL;
    x->tail_at += x->pending_body;
    x->frames++;
    return MS_OK;
}

ms_status ms_xdmf_close(ms_xdmf *x)
{
    if (!x)
        return MS_OK;
    ms_status st = MS_OK;
    ms_xdmf_drop_pending(x);
    if (x->fd >= 0 && close(x->fd) != 0)
        st = ms_fail(MS_ERR_IO, "io: closing the XDMF sidecar %s failed: %s", x->path,
                     strerror(errno));
    for (int i = 0; i < NGROUPS; ++i)
        if (x->gfd[i] >= 0 && close(x->gfd[i]) != 0 && st == MS_OK)
            st = ms_fail(MS_ERR_IO, "io: closing a grid file of %s failed: %s", x->path,
                         strerror(errno));
    ms_free(x->dir);
    ms_free(x->dir_name);
    ms_free(x->path);
    ms_free(x->h5);
    ms_free(x);
    return st;
}
