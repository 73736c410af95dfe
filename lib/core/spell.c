/* "Did you mean": the known name closest to a misspelt one, by edit
 * distance (Levenshtein with adjacent transpositions, the optimal string
 * alignment distance), for the sentences of unknown keys and values. */
#include <string.h>

#include "core/core_internal.h"

/* Names longer than this are never suggested for (nor compared): keys and
 * enum values are short, and the rows below live on the stack. */
#define MAX_LEN 64

static size_t osa_distance(const char *a, size_t na, const char *b, size_t nb)
{
    /* three rows of the dynamic programme: i-2, i-1, i */
    size_t r0[MAX_LEN + 1], r1[MAX_LEN + 1], r2[MAX_LEN + 1];
    size_t *pp = r0, *p = r1, *c = r2;
    for (size_t j = 0; j <= nb; ++j)
        p[j] = j;
    for (size_t i = 1; i <= na; ++i) {
        c[0] = i;
        for (size_t j = 1; j <= nb; ++j) {
            size_t cost = a[i - 1] == b[j - 1] ? 0 : 1;
            size_t d = MS_MIN(p[j] + 1, c[j - 1] + 1);
            d = MS_MIN(d, p[j - 1] + cost);
            if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1])
                d = MS_MIN(d, pp[j - 2] + 1);
            c[j] = d;
        }
        size_t *t = pp;
        pp = p;
        p = c;
        c = t;
    }
    return p[nb];
}

const char *ms_closest_name(const char *s, const char *const *names)
{
    if (!s || !names)
        return NULL;
    size_t ns = strlen(s);
    if (ns == 0 || ns > MAX_LEN)
        return NULL;
    /* at most one edit for names of up to 4 characters (with two, any
     * two-letter key would "mean" any other), two beyond; a tie keeps the
     * first name of the list */
    size_t limit = ns <= 4 ? 1 : 2;
    const char *best = NULL;
    size_t best_d = limit + 1;
    for (const char *const *n = names; *n; ++n) {
        size_t nn = strlen(*n);
        if (nn > MAX_LEN || (nn > ns ? nn - ns : ns - nn) > limit)
            continue;
        size_t d = osa_distance(s, ns, *n, nn);
        if (d < best_d) {
            best_d = d;
            best = *n;
        }
    }
    return best_d > 0 && best_d <= limit ? best : NULL;
}
