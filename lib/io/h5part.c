/* lib/io: particles in the H5Part layout, which ParaView's and VisIt's
 * H5Part readers open: one group /Step#<n> per written frame holding the
 * 1D float32 arrays x, y, z (m) and vx, vy, vz (m/s) of equal length, with
 * the step's time as the attribute TimeValue (float64, s), and `id`
 * (int32, the particle's index in insertion order: the volume hands its
 * particles out in that order whatever its internal sort, so a particle
 * keeps its id from frame to frame and ParaView's tracers can follow it).
 *
 * Xdmf3 (ParaView's default XDMF reader) reads neither X_Y_Z geometry nor
 * a JOIN of three arrays, so each frame's particles are also stored as
 * /particles/<frame>/position and velocity, float32 [n][3] (format_version
 * 2): 24 more bytes a particle a frame, next to a wave field of 256 KiB.
 *
 * A step is built as an anonymous group, flushed, and only then linked
 * (and flushed again): a kill in between leaves an unreachable group,
 * never a link to a half-written one.
 */
#include <stdio.h>
#include <stdlib.h>

#include "io/io_internal.h"

void ms_h5part_step_name(char *buf, size_t size, long frame)
{
    snprintf(buf, size, "Step#%ld", frame);
}

static herr_t write_array(hid_t group, const char *name, int n, const float *v)
{
    hsize_t dims[1] = {(hsize_t)n};
    hid_t space = H5Screate_simple(1, dims, NULL);
    if (space < 0)
        return -1;
    hid_t d = H5Dcreate2(group, name, H5T_IEEE_F32LE, space, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
    herr_t st = -1;
    if (d >= 0) {
        st = n > 0 ? H5Dwrite(d, H5T_NATIVE_FLOAT, H5S_ALL, H5S_ALL, H5P_DEFAULT, v) : 0;
        if (H5Dclose(d) < 0)
            st = -1;
    }
    H5Sclose(space);
    return st;
}

static herr_t write_ids(hid_t group, int n)
{
    int *id = ms_malloc((size_t)(n > 0 ? n : 1) * sizeof *id);
    if (!id)
        return -1;
    for (int i = 0; i < n; ++i)
        id[i] = i;
    hsize_t dims[1] = {(hsize_t)n};
    hid_t space = H5Screate_simple(1, dims, NULL);
    herr_t st = -1;
    if (space >= 0) {
        hid_t d =
            H5Dcreate2(group, "id", H5T_STD_I32LE, space, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
        if (d >= 0) {
            st = n > 0 ? H5Dwrite(d, H5T_NATIVE_INT, H5S_ALL, H5S_ALL, H5P_DEFAULT, id) : 0;
            if (H5Dclose(d) < 0)
                st = -1;
        }
        H5Sclose(space);
    }
    ms_free(id);
    return st;
}

/* x, y, z interleaved into an [n][3] dataset. */
static herr_t write_vec3(hid_t group, const char *name, int n, const float *const v[3], float *buf)
{
    for (int i = 0; i < n; ++i)
        for (int k = 0; k < 3; ++k)
            buf[3 * i + k] = v[k][i];
    hsize_t dims[2] = {(hsize_t)n, 3};
    hid_t space = H5Screate_simple(2, dims, NULL);
    if (space < 0)
        return -1;
    hid_t d = H5Dcreate2(group, name, H5T_IEEE_F32LE, space, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
    herr_t st = -1;
    if (d >= 0) {
        st = n > 0 ? H5Dwrite(d, H5T_NATIVE_FLOAT, H5S_ALL, H5S_ALL, H5P_DEFAULT, buf) : 0;
        if (H5Dclose(d) < 0)
            st = -1;
    }
    H5Sclose(space);
    return st;
}

ms_status ms_h5part_write_xyz(hid_t file, int n, const float *const pos[3],
                              const float *const vel[3], hid_t *group)
{
    *group = H5Gcreate_anon(file, H5P_DEFAULT, H5P_DEFAULT);
    if (*group < 0)
        return MS_ERR_IO;
    float *buf = ms_malloc((size_t)(n > 0 ? n : 1) * 3 * sizeof *buf);
    if (!buf)
        return MS_ERR_OUT_OF_MEMORY;
    herr_t st = write_vec3(*group, "position", n, pos, buf);
    if (st >= 0)
        st = write_vec3(*group, "velocity", n, vel, buf);
    ms_free(buf);
    return st < 0 ? MS_ERR_IO : MS_OK;
}

ms_status ms_h5part_link_xyz(hid_t file, hid_t group, long frame)
{
    char name[64];
    snprintf(name, sizeof name, "particles/%ld", frame);
    return H5Olink(group, file, name, H5P_DEFAULT, H5P_DEFAULT) < 0 ? MS_ERR_IO : MS_OK;
}

ms_status ms_h5part_write_step(hid_t file, double t, int n, const float *const pos[3],
                               const float *const vel[3], hid_t *group)
{
    static const char *const names[6] = {"x", "y", "z", "vx", "vy", "vz"};
    *group = H5Gcreate_anon(file, H5P_DEFAULT, H5P_DEFAULT);
    if (*group < 0)
        return MS_ERR_IO;
    herr_t st = ms_h5_attr_double(*group, "TimeValue", &t, 1);
    for (int k = 0; k < 6 && st >= 0; ++k)
        st = write_array(*group, names[k], n, k < 3 ? pos[k] : vel[k - 3]);
    if (st >= 0)
        st = write_ids(*group, n);
    return st < 0 ? MS_ERR_IO : MS_OK;
}

ms_status ms_h5part_link_step(hid_t file, hid_t group, long frame)
{
    char name[48];
    ms_h5part_step_name(name, sizeof name, frame);
    return H5Olink(group, file, name, H5P_DEFAULT, H5P_DEFAULT) < 0 ? MS_ERR_IO : MS_OK;
}
