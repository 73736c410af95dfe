/* The input log of `modesplit view`: one event a line with the frame it
 * happened in, so a session can be replayed exactly (--script) and an
 * interaction re-simulated in batch. */
#include <errno.h>
#include <fcntl.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "tool.h"
#include "view.h"

static const char *const type_names[] = {"key-down",  "key-up", "button-down",
                                         "button-up", "motion", "wheel",
                                         "quit",      "resize", "lose-context"};

int view_log_write(FILE *f, const view_event *e)
{
    const char *t = type_names[e->type];
    switch (e->type) {
    case VIEW_KEY_DOWN:
    case VIEW_KEY_UP:
        return fprintf(f, "%ld %s %s\n", e->frame, t, e->key) < 0 ? -1 : 0;
    case VIEW_BUTTON_DOWN:
        return fprintf(f, "%ld %s %d %.6f %.6f %d\n", e->frame, t, e->button, (double)e->x,
                       (double)e->y, e->shift) < 0
                   ? -1
                   : 0;
    case VIEW_BUTTON_UP:
        return fprintf(f, "%ld %s %d %.6f %.6f\n", e->frame, t, e->button, (double)e->x,
                       (double)e->y) < 0
                   ? -1
                   : 0;
    case VIEW_MOTION:
        return fprintf(f, "%ld %s %.6f %.6f\n", e->frame, t, (double)e->x, (double)e->y) < 0 ? -1
                                                                                             : 0;
    case VIEW_WHEEL:
        return fprintf(f, "%ld %s %.3f\n", e->frame, t, (double)e->wheel) < 0 ? -1 : 0;
    case VIEW_RESIZE:
        return fprintf(f, "%ld %s %d %d\n", e->frame, t, e->w, e->h) < 0 ? -1 : 0;
    default:
        return fprintf(f, "%ld %s\n", e->frame, t) < 0 ? -1 : 0;
    }
}

static int in01(float v)
{
    return v >= 0.0f && v <= 1.0f;
}

/* One line (without its newline) into e; 0 or -1 with err set. */
static int parse_line(char *line, view_event *e, char *err, size_t errlen)
{
    memset(e, 0, sizeof *e);
    char type[32];
    int used = 0;
    if (sscanf(line, "%ld %31s %n", &e->frame, type, &used) < 2 || e->frame < 0) {
        snprintf(err, errlen, "expected \"FRAME EVENT ...\" with FRAME >= 0");
        return -1;
    }
    const char *rest = line + used;
    int t = -1;
    for (int k = 0; k < (int)(sizeof type_names / sizeof *type_names); ++k)
        if (!strcmp(type, type_names[k]))
            t = k;
    if (t < 0) {
        snprintf(err, errlen,
                 "unknown event \"%s\" (key-down, key-up, button-down, button-up, "
                 "motion, wheel, quit, resize, lose-context)",
                 type);
        return -1;
    }
    e->type = (view_event_type)t;
    char extra;
    int ok = 1;
    switch (e->type) {
    case VIEW_KEY_DOWN:
    case VIEW_KEY_UP: {
        size_t n = strlen(rest);
        ok = n > 0 && n < sizeof e->key;
        /* a key's name is printable text: it reaches the terminal */
        for (size_t k = 0; k < n && ok; ++k)
            ok = (unsigned char)rest[k] >= 0x20 && rest[k] != 0x7f;
        if (ok)
            memcpy(e->key, rest, n + 1);
        break;
    }
    case VIEW_BUTTON_DOWN:
        ok = sscanf(rest, "%d %f %f %d %c", &e->button, &e->x, &e->y, &e->shift, &extra) == 4 &&
             e->button >= 1 && e->button <= 3 && in01(e->x) && in01(e->y) &&
             (e->shift == 0 || e->shift == 1);
        break;
    case VIEW_BUTTON_UP:
        ok = sscanf(rest, "%d %f %f %c", &e->button, &e->x, &e->y, &extra) == 3 && e->button >= 1 &&
             e->button <= 3 && in01(e->x) && in01(e->y);
        break;
    case VIEW_MOTION:
        ok = sscanf(rest, "%f %f %c", &e->x, &e->y, &extra) == 2 && in01(e->x) && in01(e->y);
        break;
    case VIEW_WHEEL:
        ok = sscanf(rest, "%f %c", &e->wheel, &extra) == 1 && e->wheel >= -100 && e->wheel <= 100;
        break;
    case VIEW_RESIZE:
        ok = sscanf(rest, "%d %d %c", &e->w, &e->h, &extra) == 2 && e->w >= 16 &&
             e->w <= MS_RENDER_MAX_SIDE && e->h >= 16 && e->h <= MS_RENDER_MAX_SIDE &&
             (long)e->w * e->h <= MS_RENDER_MAX_PIXELS; /* what the renderer takes */
        break;
    default:
        ok = *rest == '\0';
        break;
    }
    if (!ok) {
        snprintf(err, errlen,
                 "bad arguments for \"%s\": \"%s\" (a key name; button 1-3 and x, "
                 "y in [0, 1]; wheel in [-100, 100]; size in [16, %d] a side and at most %ld "
                 "pixels)",
                 type, rest, MS_RENDER_MAX_SIDE, MS_RENDER_MAX_PIXELS);
        return -1;
    }
    return 0;
}

int view_script_load(const char *path, view_script *s, char *err, size_t errlen)
{
    memset(s, 0, sizeof *s);
    /* a regular file of bounded size: /dev/zero would be read forever (its
     * NUL "lines" are empty), a FIFO would block the open */
    const char *why_not;
    FILE *f = tool_fopen_regular(path, &why_not);
    struct stat sb;
    if (!f || fstat(fileno(f), &sb) != 0 || sb.st_size > VIEW_LOG_MAX_BYTES) {
        if (!f && errno == 0)
            snprintf(err, errlen,
                     "%s: the input log must be a regular file (not a FIFO or a device)", path);
        else if (!f)
            snprintf(err, errlen, "%s: cannot open the input log: %s", path, why_not);
        else
            snprintf(err, errlen,
                     "%s: the input log is %lld bytes, over the %d bytes a log may have", path,
                     (long long)sb.st_size, VIEW_LOG_MAX_BYTES);
        if (f)
            fclose(f);
        return -1;
    }
    char line[256], why[200];
    int lineno = 0, cap = 0;
    long last = 0;
    while (fgets(line, sizeof line, f)) {
        ++lineno;
        size_t n = strlen(line);
        if (n == sizeof line - 1 && line[n - 1] != '\n') {
            snprintf(err, errlen, "%s:%d: line longer than %d characters", path, lineno,
                     (int)sizeof line - 2);
            goto fail;
        }
        while (n > 0 && (line[n - 1] == '\n' || line[n - 1] == '\r'))
            line[--n] = '\0';
        if (n == 0 || line[0] == '#')
            continue;
        if (s->n == cap) {
            cap = cap ? 2 * cap : 64;
            view_event *p = realloc(s->ev, (size_t)cap * sizeof *p);
            if (!p) {
                snprintf(err, errlen, "%s: out of memory for %d events", path, cap);
                goto fail;
            }
            s->ev = p;
        }
        view_event *e = &s->ev[s->n];
        if (parse_line(line, e, why, sizeof why) != 0) {
            snprintf(err, errlen, "%s:%d: %s", path, lineno, why);
            goto fail;
        }
        if (e->frame < last) {
            snprintf(err, errlen,
                     "%s:%d: frame %ld comes after frame %ld; frames must not "
                     "decrease",
                     path, lineno, e->frame, last);
            goto fail;
        }
        last = e->frame;
        s->n++;
    }
    fclose(f);
    return 0;
fail:
    fclose(f);
    view_script_free(s);
    return -1;
}

void view_script_free(view_script *s)
{
    free(s->ev);
    memset(s, 0, sizeof *s);
}
