/* Status names and the thread-local error sentence (libuv's X-macro name
 * table, SQLite's errmsg). */
#include <stdarg.h>
#include <stdio.h>

#include "core/core_internal.h"

static _Thread_local char last_error[1024];
/* The desc field the last refusal was about ("" when none): a scene that
 * filled the desc maps it back to the key it read (lib/scene). */
static _Thread_local char last_key[64];

const char *ms_status_name(ms_status s)
{
    switch (s) {
#define NAME_CASE(name, value, text) \
    case MS_##name:                  \
        return "MS_" #name;
        MS_STATUS_MAP(NAME_CASE)
#undef NAME_CASE
    default:
        return "MS_UNKNOWN_STATUS";
    }
}

const char *ms_status_text(ms_status s)
{
    switch (s) {
#define TEXT_CASE(name, value, text) \
    case MS_##name:                  \
        return text;
        MS_STATUS_MAP(TEXT_CASE)
#undef TEXT_CASE
    default:
        return "unknown status";
    }
}

const char *ms_last_error(void)
{
    return last_error;
}

const char *ms_last_error_key(void)
{
    return last_key;
}

static void set_key(const char *key)
{
    snprintf(last_key, sizeof last_key, "%s", key ? key : "");
}

ms_status ms_fail(ms_status s, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(last_error, sizeof last_error, fmt, ap);
    va_end(ap);
    last_key[0] = '\0';
    return s;
}

ms_status ms_fail_key(ms_status s, const char *key, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(last_error, sizeof last_error, fmt, ap);
    va_end(ap);
    set_key(key);
    return s;
}

ms_status ms_check_finite(const char *part, const char *key, double v)
{
    if (!isfinite(v))
        return ms_fail_key(MS_ERR_INVALID_ARGUMENT, key, "%s: %s is %g; it must be a finite number",
                           part, key, v);
    return MS_OK;
}

ms_status ms_check_range(const char *part, const char *key, double v, double lo, double hi,
                         const char *unit)
{
    if (!isfinite(v) || v < lo || v > hi)
        return ms_fail_key(MS_ERR_INVALID_ARGUMENT, key, "%s: %s %g%s%s is outside [%g, %g]", part,
                           key, v, *unit ? " " : "", unit, lo, hi);
    return MS_OK;
}

ms_status ms_check_positive(const char *part, const char *key, double v, const char *unit)
{
    if (!isfinite(v) || !(v > 0))
        return ms_fail_key(MS_ERR_INVALID_ARGUMENT, key, "%s: %s %g%s%s must be finite and > 0",
                           part, key, v, *unit ? " " : "", unit);
    return MS_OK;
}

ms_status ms_check_int_range(const char *part, const char *key, long v, long lo, long hi)
{
    if (v < lo || v > hi)
        return ms_fail_key(MS_ERR_INVALID_ARGUMENT, key, "%s: %s %ld is outside [%ld, %ld]", part,
                           key, v, lo, hi);
    return MS_OK;
}

ms_status ms_check_not_null(const char *part, const char *key, const void *p)
{
    if (!p)
        return ms_fail_key(MS_ERR_INVALID_ARGUMENT, key, "%s: %s is NULL", part, key);
    return MS_OK;
}
