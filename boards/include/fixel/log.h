/* SPDX-License-Identifier: MIT */
/* fixel — log priorities and the log function type shared by the boards
 * side (display, console, input): diagnostics go through one function the
 * program may replace (fx_display_options.log). */
#ifndef FIXEL_LOG_H
#define FIXEL_LOG_H

#include <stdarg.h>

#ifdef __cplusplus
extern "C" {
#endif

/* Lower is more important, as in syslog. */
typedef enum fx_log_priority {
    FX_LOG_ERROR = 10,
    FX_LOG_INFO = 20,
    FX_LOG_DEBUG = 30,
} fx_log_priority;

typedef void (*fx_log_func)(fx_log_priority priority, void *user, const char *fmt, va_list args);

#ifdef __cplusplus
}  /* extern "C" */
#endif

#endif
