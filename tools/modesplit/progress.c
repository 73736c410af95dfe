/* Progress of `modesplit run`: on a terminal one line redrawn at most ten
 * times a second (bar, frame, frames/s, ETA, per-stage split); otherwise a
 * plain line at every 10 % and at least every 10 s, for logs. All on
 * stderr, so stdout keeps only the summary.
 *
 * The terminal line fits the terminal's width (asked at each redraw, so a
 * resized window is followed): a line that wraps cannot be redrawn by \r
 * and scrolls instead. What does not fit is dropped in this order: the
 * per-stage split, the bar, then the end of the line. */
#include <stdlib.h>
#include <string.h>
#include <sys/ioctl.h>
#include <unistd.h>

#include "tool.h"

#define BAR_WIDTH 24

/* Columns of the terminal on stderr: the tty's size, else $COLUMNS, else 80. */
static int terminal_width(void)
{
    struct winsize ws;
    if (ioctl(STDERR_FILENO, TIOCGWINSZ, &ws) == 0 && ws.ws_col > 0)
        return ws.ws_col;
    const char *c = getenv("COLUMNS");
    long n = c ? strtol(c, NULL, 10) : 0;
    return n > 0 && n < 10000 ? (int)n : 80;
}

/* The line for `width` columns (the last column stays empty: some
 * terminals wrap when it is written). */
void progress_fit(char *out, size_t size, int width, const char *bar, const char *core,
                  const char *stages)
{
    size_t room = width > 1 ? (size_t)width - 1 : 0;
    if (room >= size)
        room = size - 1;
    snprintf(out, size, "[%s] %s | %s", bar, core, stages);
    if (strlen(out) <= room)
        return;
    snprintf(out, size, "[%s] %s", bar, core);
    if (strlen(out) <= room)
        return;
    snprintf(out, size, "%s", core);
    out[room] = '\0';
}

void progress_begin(tool_progress *p, long total, int quiet)
{
    p->tty = isatty(STDERR_FILENO);
    p->quiet = quiet;
    p->total = total;
    p->base = 0;
    p->start = tool_now();
    p->last_draw = p->start;
    p->last_decile = 0;
}

static void eta_text(double s, char *buf, size_t size)
{
    if (!(s >= 0) || s > 1e7)
        snprintf(buf, size, "?");
    else if (s >= 3600)
        snprintf(buf, size, "%ld:%02ld:%02ld", (long)s / 3600, ((long)s / 60) % 60, (long)s % 60);
    else
        snprintf(buf, size, "%ld:%02ld", (long)s / 60, (long)s % 60);
}

void progress_update(tool_progress *p, long done, const tool_stages *s)
{
    if (p->quiet || p->total <= 0)
        return;
    double now = tool_now(), el = now - p->start;
    double rate = el > 0 ? (double)(done - p->base) / el : 0.0;
    char eta[32];
    eta_text(rate > 0 ? (double)(p->total - done) / rate : -1, eta, sizeof eta);
    int pct = (int)(100.0 * (double)done / (double)p->total);
    if (p->tty) {
        if (now - p->last_draw < 0.1 && done < p->total)
            return;
        p->last_draw = now;
        char bar[BAR_WIDTH + 1];
        int fill = (int)((double)BAR_WIDTH * (double)done / (double)p->total);
        for (int i = 0; i < BAR_WIDTH; ++i)
            bar[i] = i < fill ? '=' : (i == fill ? '>' : ' ');
        bar[BAR_WIDTH] = '\0';
        char core[160], stages[160], line[400];
        snprintf(core, sizeof core, "%3d%% frame %ld/%ld %6.1f frames/s ETA %s", pct, done,
                 p->total, rate, eta);
        snprintf(stages, sizeof stages, "vol %.2g surf %.2g extr %.2g comb %.2g out %.2g ms",
                 s->volume, s->surface, s->extract, s->combine, s->write + s->png);
        progress_fit(line, sizeof line, terminal_width(), bar, core, stages);
        fprintf(stderr, "\r%s\033[K", line);
        fflush(stderr);
        return;
    }
    int decile = (int)(10.0 * (double)done / (double)p->total);
    if (decile <= p->last_decile && now - p->last_draw < 10.0 && done < p->total)
        return;
    p->last_decile = decile;
    p->last_draw = now;
    fprintf(stderr,
            "modesplit: frame %ld/%ld (%d%%), %.1f frames/s, ETA %s; per frame: volume %.3g ms, "
            "surface %.3g ms, extract %.3g ms, combine %.3g ms, output %.3g ms\n",
            done, p->total, pct, rate, eta, s->volume, s->surface, s->extract, s->combine,
            s->write + s->png);
}

void progress_end(tool_progress *p)
{
    if (!p->quiet && p->tty && p->total > 0) {
        fputs("\r\033[K", stderr);
        fflush(stderr);
    }
}
