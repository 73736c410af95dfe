/* Where a key lies in the scene text, for error messages.
 *
 * jansson reports line and column for syntax errors only: once a text is
 * parsed, its values carry no position. To name file:line:col for a value
 * of the wrong type or out of range, we walk the text again along the
 * value's path (keys and array indices) with this small scanner. It runs
 * only on text jansson has accepted with JSON_REJECT_DUPLICATES, so every
 * path names exactly one place and the grammar is known to be valid; the
 * scanner still checks every bound so that it cannot read past the text.
 * Keys are compared after decoding their escapes (\n, \uXXXX, surrogate
 * pairs) to UTF-8, as jansson decodes them.
 */
#include <string.h>

#include "scene/locate.h"

static void skip_ws(const char *t, size_t n, size_t *i)
{
    while (*i < n && (t[*i] == ' ' || t[*i] == '\t' || t[*i] == '\n' || t[*i] == '\r'))
        ++*i;
}

/* Past a string starting at t[*i] == '"'. 0 if it runs off the end. */
static int skip_string(const char *t, size_t n, size_t *i)
{
    ++*i;
    while (*i < n) {
        char c = t[*i];
        if (c == '\\')
            *i += 2;
        else if (c == '"') {
            ++*i;
            return 1;
        } else
            ++*i;
    }
    return 0;
}

/* Past any value; compound values by bracket counting (no recursion, so
 * no depth limit). */
static int skip_value(const char *t, size_t n, size_t *i)
{
    skip_ws(t, n, i);
    if (*i >= n)
        return 0;
    if (t[*i] == '"')
        return skip_string(t, n, i);
    if (t[*i] == '{' || t[*i] == '[') {
        long depth = 0;
        while (*i < n) {
            char c = t[*i];
            if (c == '"') {
                if (!skip_string(t, n, i))
                    return 0;
                continue;
            }
            if (c == '{' || c == '[')
                ++depth;
            else if (c == '}' || c == ']') {
                if (--depth == 0) {
                    ++*i;
                    return 1;
                }
            }
            ++*i;
        }
        return 0;
    }
    /* number or literal */
    while (*i < n && t[*i] != ',' && t[*i] != '}' && t[*i] != ']' && t[*i] != ' ' &&
           t[*i] != '\t' && t[*i] != '\n' && t[*i] != '\r')
        ++*i;
    return 1;
}

static int hex4(const char *t, size_t n, size_t i, unsigned *out)
{
    unsigned v = 0;
    if (i + 4 > n)
        return 0;
    for (size_t k = 0; k < 4; ++k) {
        char c = t[i + k];
        v <<= 4;
        if (c >= '0' && c <= '9')
            v |= (unsigned)(c - '0');
        else if (c >= 'a' && c <= 'f')
            v |= (unsigned)(c - 'a' + 10);
        else if (c >= 'A' && c <= 'F')
            v |= (unsigned)(c - 'A' + 10);
        else
            return 0;
    }
    *out = v;
    return 1;
}

static int utf8_encode(unsigned cp, unsigned char out[4])
{
    if (cp < 0x80) {
        out[0] = (unsigned char)cp;
        return 1;
    }
    if (cp < 0x800) {
        out[0] = (unsigned char)(0xC0 | (cp >> 6));
        out[1] = (unsigned char)(0x80 | (cp & 0x3F));
        return 2;
    }
    if (cp < 0x10000) {
        out[0] = (unsigned char)(0xE0 | (cp >> 12));
        out[1] = (unsigned char)(0x80 | ((cp >> 6) & 0x3F));
        out[2] = (unsigned char)(0x80 | (cp & 0x3F));
        return 3;
    }
    out[0] = (unsigned char)(0xF0 | (cp >> 18));
    out[1] = (unsigned char)(0x80 | ((cp >> 12) & 0x3F));
    out[2] = (unsigned char)(0x80 | ((cp >> 6) & 0x3F));
    out[3] = (unsigned char)(0x80 | (cp & 0x3F));
    return 4;
}

/* Decode the string at t[*i] == '"' and compare it with key (UTF-8);
 * advances past the string. Returns 1 on a match, 0 otherwise, -1 when the
 * text ends inside the string. */
static int match_string(const char *t, size_t n, size_t *i, const char *key)
{
    size_t klen = strlen(key), k = 0;
    int same = 1;
    ++*i;
    while (*i < n) {
        unsigned char buf[4];
        int len;
        char c = t[*i];
        if (c == '"') {
            ++*i;
            return same && k == klen;
        }
        if (c != '\\') {
            buf[0] = (unsigned char)c;
            len = 1;
            ++*i;
        } else {
            if (*i + 1 >= n)
                return -1;
            char e = t[*i + 1];
            *i += 2;
            switch (e) {
            case 'n':
                buf[0] = '\n';
                len = 1;
                break;
            case 't':
                buf[0] = '\t';
                len = 1;
                break;
            case 'r':
                buf[0] = '\r';
                len = 1;
                break;
            case 'b':
                buf[0] = '\b';
                len = 1;
                break;
            case 'f':
                buf[0] = '\f';
                len = 1;
                break;
            case 'u': {
                unsigned cp;
                if (!hex4(t, n, *i, &cp))
                    return -1;
                *i += 4;
                if (cp >= 0xD800 && cp < 0xDC00 && *i + 1 < n && t[*i] == '\\' &&
                    t[*i + 1] == 'u') {
                    unsigned lo;
                    if (hex4(t, n, *i + 2, &lo) && lo >= 0xDC00 && lo < 0xE000) {
                        cp = 0x10000 + ((cp - 0xD800) << 10) + (lo - 0xDC00);
                        *i += 6;
                    }
                }
                len = utf8_encode(cp, buf);
                break;
            }
            default:
                buf[0] = (unsigned char)e;
                len = 1;
                break; /* \" \\ \/ */
            }
        }
        for (int b = 0; b < len; ++b) {
            if (k < klen && (unsigned char)key[k] == buf[b])
                ++k;
            else
                same = 0;
        }
    }
    return -1;
}

int ms_scene_locate(const char *text, size_t len, const ms_scene_pathelem *path, int depth,
                    size_t *pos)
{
    size_t i = 0;
    skip_ws(text, len, &i);
    size_t here = i;
    *pos = here;
    for (int d = 0; d < depth; ++d) {
        skip_ws(text, len, &i);
        if (i >= len)
            return 0;
        if (path[d].key) {
            if (text[i] != '{')
                return 0;
            ++i;
            for (;;) {
                skip_ws(text, len, &i);
                if (i >= len || text[i] != '"')
                    return 0;
                size_t key_at = i;
                int m = match_string(text, len, &i, path[d].key);
                if (m < 0)
                    return 0;
                skip_ws(text, len, &i);
                if (i >= len || text[i] != ':')
                    return 0;
                ++i;
                skip_ws(text, len, &i);
                if (m == 1) {
                    here = key_at;
                    *pos = here;
                    break;
                }
                if (!skip_value(text, len, &i))
                    return 0;
                skip_ws(text, len, &i);
                if (i >= len || text[i] != ',')
                    return 0;
                ++i;
            }
        } else {
            if (text[i] != '[' || path[d].index < 0)
                return 0;
            ++i;
            for (long k = 0;; ++k) {
                skip_ws(text, len, &i);
                if (i >= len || text[i] == ']')
                    return 0;
                if (k == path[d].index) {
                    here = i;
                    *pos = here;
                    break;
                }
                if (!skip_value(text, len, &i))
                    return 0;
                skip_ws(text, len, &i);
                if (i >= len || text[i] != ',')
                    return 0;
                ++i;
            }
        }
    }
    return 1;
}

void ms_scene_line_col(const char *text, size_t len, size_t pos, int *line, int *col)
{
    int l = 1, c = 1;
    for (size_t i = 0; i < pos && i < len; ++i) {
        unsigned char ch = (unsigned char)text[i];
        if (ch == '\n') {
            ++l;
            c = 1;
        } else if ((ch & 0xC0) != 0x80) { /* count characters, not UTF-8 bytes */
            ++c;
        }
    }
    *line = l;
    *col = c;
}
