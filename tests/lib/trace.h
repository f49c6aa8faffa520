/* SPDX-License-Identifier: MIT */
/* Shared test helper: collects what an fx_ctx trace callback prints, one
 * copy per line, so a test can look for the course's trace rows.
 *   ctx.trace = trace_collect;  ...draw...;  trace_has("steps=5");
 * trace_clear() frees the lines and starts again (call it before a run). */
#ifndef FX_TEST_TRACE_H
#define FX_TEST_TRACE_H

extern char **trace_lines;
extern int trace_n;

void trace_collect(void *user, const char *line);
void trace_clear(void);
/* 1 when some collected line contains needle. */
int trace_has(const char *needle);

#endif
