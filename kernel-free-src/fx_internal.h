/* Internal helpers shared by core files; not installed. */
#ifndef FIXEL_INTERNAL_H
#define FIXEL_INTERNAL_H

#include <stddef.h>
#include <stdint.h>
#include "fixel/surface.h"

/* The core may call only the mem* functions of libc; the builtins make that
 * explicit and let the compiler inline small constant-size cases. */
#define fx_memset  __builtin_memset
#define fx_memcpy  __builtin_memcpy
#define fx_memmove __builtin_memmove

#define FX_MIN(a, b) ((a) < (b) ? (a) : (b))
#define FX_MAX(a, b) ((a) > (b) ? (a) : (b))
#define FX_ARRAY_LEN(a) (sizeof(a) / sizeof((a)[0]))

static inline uint8_t *fx_row(const struct fx_surface *s, int32_t y)
{
    return s->pixels + (ptrdiff_t)y * s->stride;
}

#endif
