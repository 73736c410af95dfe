/* ms_writer: HDF5 dumps of the fields and particles of a run (DESIGN 5),
 * flushed each frame so the file is readable while the run goes on and
 * valid if it is killed, with an XDMF sidecar for ParaView.
 */
#ifndef MODESPLIT_IO_H
#define MODESPLIT_IO_H

#include "core.h"
#include "sim.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Bits of the `fields` argument of ms_writer_open. */
enum {
    MS_FIELD_COMBINED = 1u << 0,  /* /fields/combined */
    MS_FIELD_SURFACE = 1u << 1,   /* /fields/surface  */
    MS_FIELD_VOLUME = 1u << 2,    /* /fields/volume   */
    MS_FIELD_PARTICLES = 1u << 3  /* /Step#n/x,y,z,vx,vy,vz (H5Part) */
};

MS_API ms_status ms_writer_open(const char *path, const ms_sim *sim, unsigned fields,
                                ms_writer **out);
MS_API ms_status ms_writer_frame(ms_writer *w, const ms_sim *sim);
MS_API ms_status ms_writer_close(ms_writer *w);

#ifdef __cplusplus
}
#endif

#endif /* MODESPLIT_IO_H */
