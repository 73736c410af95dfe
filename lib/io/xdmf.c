/* lib/io: the XDMF (v2) sidecar that lets ParaView and VisIt open a run
 * file as a time series.
 *
 * One temporal collection; each written frame is a spatial collection with
 * its <Time>, one uniform grid per distinct field grid (combined and
 * surface share the wave grid, volume has the SPH grid) and, when the frame
 * has particles, a poly-vertex grid of them. A height field is point data
 * on a 3DCoRectMesh of 1 x ny x nx points placed at the cell centres;
 * XDMF lists dimensions slowest first (z y x), and so its origin and
 * spacing. Each field attribute is a hyperslab [frame][0..ny)[0..nx) of the
 * /fields/<name> dataset.
 *
 * The file is kept valid after every frame: the closing tags are written
 * after the last frame, and the next frame is written over them together
 * with a fresh copy, in a single pwrite, so a run killed at any moment
 * leaves well-formed XML that lists the frames written so far.
 */
#include <errno.h>
#include <fcntl.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "io/io_internal.h"

static const char TAIL[] = "  </Grid>\n </Domain>\n</Xdmf>\n";

struct ms_xdmf {
    int fd;
    char *path;
    char *h5;          /* the HDF5 file's name, XML-escaped */
    off_t tail_at;     /* where the closing tags start */
    ms_writer_layout layout;
    int group_of[MS_IO_NFIELDS]; /* first field slot with the same grid */
};

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
        case '&': sb_printf(&b, "&amp;"); break;
        case '<': sb_printf(&b, "&lt;"); break;
        case '>': sb_printf(&b, "&gt;"); break;
        case '"': sb_printf(&b, "&quot;"); break;
        case '\'': sb_printf(&b, "&apos;"); break;
        default: sb_printf(&b, "%c", *s); break;
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

ms_status ms_xdmf_open(const char *xmf_path, const char *h5_name, const ms_writer_layout *l,
                       ms_xdmf **out)
{
    *out = NULL;
    ms_xdmf *x = ms_alloc_array(1, sizeof *x);
    if (!x)
        return ms_fail(MS_ERR_OUT_OF_MEMORY, "io: out of memory for the XDMF sidecar");
    x->fd = -1;
    x->layout = *l;
    x->path = ms_strdup(xmf_path);
    x->h5 = xml_escape(h5_name);
    if (!x->path || !x->h5) {
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
    x->fd = open(xmf_path, O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0666);
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
              "<Xdmf Version=\"2.0\">\n"
              " <Domain>\n"
              "  <Grid Name=\"run\" GridType=\"Collection\" CollectionType=\"Temporal\">\n",
              ms_version(), x->h5);
    x->tail_at = (off_t)b.len;
    sb_printf(&b, "%s", TAIL);
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

static void field_grid_xml(sbuf *b, const ms_xdmf *x, int slot, long frame)
{
    const ms_grid *g = &x->layout.grid[slot];
    /* points at the cell centres */
    double ox = (double)g->origin[0] + 0.5 * g->dx, oy = (double)g->origin[1] + 0.5 * g->dy;
    sb_printf(b,
              "    <Grid Name=\"height %dx%d\" GridType=\"Uniform\">\n"
              "     <Topology TopologyType=\"3DCoRectMesh\" Dimensions=\"1 %d %d\"/>\n"
              "     <Geometry GeometryType=\"ORIGIN_DXDYDZ\">\n"
              "      <DataItem Dimensions=\"3\" NumberType=\"Float\" Precision=\"8\" "
              "Format=\"XML\">0 %.17g %.17g</DataItem>\n"
              "      <DataItem Dimensions=\"3\" NumberType=\"Float\" Precision=\"8\" "
              "Format=\"XML\">1 %.9g %.9g</DataItem>\n"
              "     </Geometry>\n",
              g->nx, g->ny, g->ny, g->nx, oy, ox, (double)g->dy, (double)g->dx);
    for (int i = 0; i < MS_IO_NFIELDS; ++i) {
        if (!(x->layout.fields & (1u << i)) || x->group_of[i] != slot)
            continue;
        sb_printf(b,
                  "     <Attribute Name=\"%s\" AttributeType=\"Scalar\" Center=\"Node\">\n"
                  "      <DataItem ItemType=\"HyperSlab\" Dimensions=\"1 %d %d\" "
                  "Type=\"HyperSlab\">\n"
                  "       <DataItem Dimensions=\"3 3\" Format=\"XML\">%ld 0 0 1 1 1 1 %d %d"
                  "</DataItem>\n"
                  "       <DataItem Dimensions=\"%ld %d %d\" NumberType=\"Float\" "
                  "Precision=\"4\" Format=\"HDF\">%s:/fields/%s</DataItem>\n"
                  "      </DataItem>\n"
                  "     </Attribute>\n",
                  ms_io_field_names[i], g->ny, g->nx, frame, g->ny, g->nx, frame + 1, g->ny,
                  g->nx, x->h5, ms_io_field_names[i]);
    }
    sb_printf(b, "    </Grid>\n");
}

static void particles_xml(sbuf *b, const ms_xdmf *x, long frame, int n)
{
    char step[48];
    ms_h5part_step_name(step, sizeof step, frame);
    sb_printf(b,
              "    <Grid Name=\"particles\" GridType=\"Uniform\">\n"
              "     <Topology TopologyType=\"Polyvertex\" NumberOfElements=\"%d\" "
              "NodesPerElement=\"1\"/>\n"
              "     <Geometry GeometryType=\"X_Y_Z\">\n",
              n);
    static const char *const axes[3] = {"x", "y", "z"};
    for (int k = 0; k < 3; ++k)
        sb_printf(b,
                  "      <DataItem Dimensions=\"%d\" NumberType=\"Float\" Precision=\"4\" "
                  "Format=\"HDF\">%s:/%s/%s</DataItem>\n",
                  n, x->h5, step, axes[k]);
    sb_printf(b,
              "     </Geometry>\n"
              "     <Attribute Name=\"velocity\" AttributeType=\"Vector\" Center=\"Node\">\n"
              "      <DataItem ItemType=\"Function\" Function=\"JOIN($0, $1, $2)\" "
              "Dimensions=\"%d 3\">\n",
              n);
    for (int k = 0; k < 3; ++k)
        sb_printf(b,
                  "       <DataItem Dimensions=\"%d\" NumberType=\"Float\" Precision=\"4\" "
                  "Format=\"HDF\">%s:/%s/v%s</DataItem>\n",
                  n, x->h5, step, axes[k]);
    sb_printf(b, "      </DataItem>\n     </Attribute>\n    </Grid>\n");
}

ms_status ms_xdmf_frame(ms_xdmf *x, long frame, double t, int particles)
{
    sbuf b = {0};
    sb_printf(&b,
              "   <Grid Name=\"frame %ld\" GridType=\"Collection\" CollectionType=\"Spatial\">\n"
              "    <Time Value=\"%.17g\"/>\n",
              frame, t);
    for (int i = 0; i < MS_IO_NFIELDS; ++i)
        if ((x->layout.fields & (1u << i)) && x->group_of[i] == i)
            field_grid_xml(&b, x, i, frame);
    if (particles > 0)
        particles_xml(&b, x, frame, particles);
    sb_printf(&b, "   </Grid>\n");
    size_t body = b.len;
    sb_printf(&b, "%s", TAIL);
    if (b.oom) {
        ms_free(b.p);
        return ms_fail(MS_ERR_OUT_OF_MEMORY, "io: out of memory for the XDMF sidecar");
    }
    int bad = write_all_at(x->fd, b.p, b.len, x->tail_at) < 0;
    int e = errno;
    ms_free(b.p);
    if (bad)
        return ms_fail(MS_ERR_IO, "io: writing frame %ld to the XDMF sidecar %s failed: %s",
                       frame, x->path, strerror(e));
    x->tail_at += (off_t)body;
    return MS_OK;
}

ms_status ms_xdmf_close(ms_xdmf *x)
{
    if (!x)
        return MS_OK;
    ms_status st = MS_OK;
    if (x->fd >= 0 && close(x->fd) != 0)
        st = ms_fail(MS_ERR_IO, "io: closing the XDMF sidecar %s failed: %s", x->path,
                     strerror(errno));
    ms_free(x->path);
    ms_free(x->h5);
    ms_free(x);
    return st;
}
