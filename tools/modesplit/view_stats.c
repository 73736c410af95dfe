/* The overlay's text: what the window shows in its top left corner. The
 * ms per stage are exactly the sim's own statistics (ms_sim_stats) of the
 * last frame: the difference of the totals before and after its step. */
#include <stdio.h>

#include "view.h"

const char view_help_text[] = "left-drag  drag the water       shift-click  a drop\n"
                              "right-drag orbit   wheel zoom   middle-drag  pan\n"
                              "R rain   C caustics   1-4 water/milk/oil/honey\n"
                              "arrows   steer the boat         W A S D  move the container\n"
                              "Q E      tilt the container     F  paced / as fast as it can\n"
                              "Space    pause   N one frame    F12 screenshot\n"
                              "H        help    Esc quit";

static const char *onoff(int v)
{
    return v < 0 ? "-" : v ? "on" : "off";
}

int view_overlay_text(const view_overlay_info *in, const ms_stats *before, const ms_stats *after,
                      char *buf, size_t size)
{
    int n = snprintf(buf, size,
                     "%s  frame %ld  t %.2f s  %.1f frames/s%s\n"
                     "volume %.2f  extract %.2f  waves %.2f  combine %.2f  render %.2f ms\n"
                     "particles %d  N_time %d  threads %d\n"
                     "%s  caustics %s  rain %s  (H help)",
                     in->scene, in->frame, in->time, in->fps,
                     in->paused  ? "  PAUSED"
                     : in->paced ? ""
                                 : "  (fast)",
                     after->volume_ms - before->volume_ms, after->extract_ms - before->extract_ms,
                     after->surface_ms - before->surface_ms, after->combine_ms - before->combine_ms,
                     in->render_ms, in->particles, after->n_time, in->threads, in->shader,
                     onoff(in->caustics), onoff(in->rain));
    (void)n;
    return 4;
}
