/* SPDX-License-Identifier: MIT */
/* fixel — the run-time version (fixel/version.h). */
#include "fixel/version.h"

const char *fx_version(void)
{
    return FX_VERSION_STRING;
}

int fx_version_number(void)
{
    return FX_VERSION_NUMBER;
}
