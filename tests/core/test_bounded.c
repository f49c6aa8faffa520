/* SPDX-License-Identifier: MIT */
/* Bounded work: every primitive's cost follows the visible area and the size
 * of its input, not how far it reaches off-screen. Each case draws a huge
 * primitive onto a 16x16 surface in a child process limited to 1 s of CPU
 * time (RLIMIT_CPU): a loop over the invisible part of a line 2^32 pixels
 * long, or of a circle of radius 2^30, runs for many seconds and is killed
 * by SIGXCPU. The limit is a termination budget with a wide margin (the
 * cases take microseconds), not a speed measurement: speed is make bench's.
 * make test-bounded (tests/bounded/) counts the same cases' instructions. */
#include <signal.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include "bounded_cases.h"
#include "fx_test.h"

FX_TEST(primitives_do_work_bounded_by_what_is_visible)
{
    for (int k = 0; k < NCASES; k++) {
        pid_t pid = fork();
        if (pid == 0) {
            struct rlimit rl = {1, 2};
            setrlimit(RLIMIT_CPU, &rl);
            static uint32_t mem[W * H];
            fx_surface s;
            fx_surface_init(&s, mem, W, H, W * 4, FX_FMT_XRGB8888);
            fx_ctx c;
            fx_ctx_init(&c, &s);
            run_case(k, &c);
            _exit(0);
        }
        int st = 0;
        waitpid(pid, &st, 0);
        FX_CHECK_MSG(WIFEXITED(st) && WEXITSTATUS(st) == 0, "case %d: %s %d", k,
                     WIFSIGNALED(st) ? "killed by signal" : "exit", WIFSIGNALED(st) ? WTERMSIG(st) : WEXITSTATUS(st));
    }
}
