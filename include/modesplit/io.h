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

/* `fields` is a set of MS_FIELD_* bits (core.h). */

MS_API ms_status ms_writer_open(const char *path, const ms_sim *sim, unsigned fields,
                                ms_writer **out);
MS_API ms_status ms_writer_frame(ms_writer *w, const ms_sim *sim);
MS_API ms_status ms_writer_close(ms_writer *w);

#ifdef __cplusplus
}
#endif

#endif /* MODESPLIT_IO_H */
