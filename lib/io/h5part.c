/* lib/io: particles in the H5Part layout, which ParaView's and VisIt's
 * H5Part readers open: one group /Step#<n> per written frame holding the
 * 1D float32 arrays x, y, z (m) and vx, vy, vz (m/s) of equal length, with
 * the step's time as the attribute TimeValue (float64, s).
 *
 * A step is built as an anonymous group, flushed, and only then linked
 * (and flushed again): a kill in between leaves an unreachable group,
 * never a link to a half-written one.
 */
#include <stdio.h>

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
    hid_t d = H5Dcreate2(group, name, H5T_IEEE_F32LE, space, H5P_DEFAULT, H5P_DEFAULT,
                         H5P_DEFAULT);
    herr_t st = -1;
    if (d >= 0) {
        st = n > 0 ? H5Dwrite(d, H5T_NATIVE_FLOAT, H5S_ALL, H5S_ALL, H5P_DEFAULT, v) : 0;
        if (H5Dclose(d) < 0)
            st = -1;
    }
    H5Sclose(space);
    return st;
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
    return st < 0 ? MS_ERR_IO : MS_OK;
}

ms_status ms_h5part_link_step(hid_t file, hid_t group, long frame)
{
    char name[48];
    ms_h5part_step_name(name, sizeof name, frame);
    return H5Olink(group, file, name, H5P_DEFAULT, H5P_DEFAULT) < 0 ? MS_ERR_IO : MS_OK;
}
