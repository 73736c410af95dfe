/* The library version, from the one definition in core.h. */
#include "core/core_internal.h"

const char *ms_version(void)
{
    return MS_VERSION_STRING;
}
