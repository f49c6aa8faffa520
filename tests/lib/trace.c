/* SPDX-License-Identifier: MIT */
/* Shared test helper: the trace collector (tests/lib/trace.h). */
#include "trace.h"

#include <stdlib.h>
#include <string.h>

char **trace_lines;
int trace_n;

void trace_collect(void *user, const char *line)
{
    (void)user;
    trace_lines = realloc(trace_lines, sizeof(char *) * (size_t)(trace_n + 1));
    trace_lines[trace_n++] = strdup(line);
}

void trace_clear(void)
{
    for (int i = 0; i < trace_n; i++)
        free(trace_lines[i]);
    free(trace_lines);
    trace_lines = NULL;
    trace_n = 0;
}

int trace_has(const char *needle)
{
    for (int i = 0; i < trace_n; i++)
        if (strstr(trace_lines[i], needle))
            return 1;
    return 0;
}
