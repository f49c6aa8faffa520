/* SPDX-License-Identifier: MIT */
/* fixel — unit-test runner: runs every registered test (or those whose name
 * contains one of the arguments) and ends with "N passed, N failed". */
#include <stdarg.h>
#include <stdio.h>
#include <string.h>

#include "fx_test.h"

static int failures;

void fx_test_fail(const char *file, int line, const char *fmt, ...)
{
    if (++failures <= 10) {
        va_list ap;
        va_start(ap, fmt);
        fprintf(stderr, "  %s:%d: check failed: ", file, line);
        vfprintf(stderr, fmt, ap);
        fputc('\n', stderr);
        va_end(ap);
    } else if (failures == 11) {
        fprintf(stderr, "  (further failures of this test not shown)\n");
    }
}

int fx_test_failed(void) { return failures; }

int main(int argc, char **argv)
{
    int passed = 0, failed = 0, skipped = 0;
    for (const fx_test_case *t = fx_tests; t->name; t++) {
        int wanted = argc < 2;
        for (int i = 1; i < argc; i++)
            wanted |= strstr(t->name, argv[i]) != NULL;
        if (!wanted)
            continue;
        if (!t->fn) {
            skipped++;
            printf("skip %s (not built for this target)\n", t->name);
            continue;
        }
        failures = 0;
        t->fn();
        fflush(stdout);
        if (failures) {
            failed++;
            printf("FAIL %s (%d failed checks)\n", t->name, failures);
        } else {
            passed++;
            printf("ok   %s\n", t->name);
        }
    }
    printf("unit: %d passed, %d failed, %d skipped\n", passed, failed, skipped);
    return failed != 0;
}
