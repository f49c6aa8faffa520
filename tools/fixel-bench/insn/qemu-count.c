/* SPDX-License-Identifier: MIT */
/* qemu-count — guest instructions executed between insn_begin and insn_end,
 * from qemu-user's log with -d in_asm,exec,nochain on standard input.
 *
 * Debian's qemu-user-static has no plugin support (it is static; plugins are
 * shared objects), so the instruction-counting plugin is not available.
 * The log has what it needs: in_asm prints each translation block once,
 * its guest instructions one per line, when it is translated; exec (with
 * nochain, every block is entered through the main loop and logged) prints
 * "Trace N: HOST [CSBASE/PC/FLAGS/CFLAGS] SYMBOL" each time a block runs.
 * The sum, over executed blocks, of their instruction counts is the count.
 * A block that faults midway would be over-counted; the drawing code does
 * not fault. Prints "COUNT" (instructions between the markers). */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define HBITS 20
#define HSIZE (1u << HBITS)

static uint64_t key[HSIZE];
static uint32_t val[HSIZE];

static uint32_t *slot(uint64_t pc)
{
    uint32_t h = (uint32_t)((pc * 0x9E3779B97F4A7C15ull) >> (64 - HBITS));
    while (key[h] && key[h] != pc + 1)
        h = (h + 1) & (HSIZE - 1);
    key[h] = pc + 1;
    return &val[h];
}

int main(void)
{
    static char line[4096];
    uint64_t tb_pc = 0, count = 0;
    uint32_t tb_n = 0;
    int in_tb = 0, on = 0, seen_end = 0;
    while (fgets(line, sizeof line, stdin)) {
        if (!strncmp(line, "Trace ", 6)) {
            if (in_tb) {
                *slot(tb_pc) = tb_n;
                in_tb = 0;
            }
            char *b = strchr(line, '[');
            if (!b)
                continue;
            char *s1 = strchr(b, '/');
            if (!s1)
                continue;
            uint64_t pc = strtoull(s1 + 1, NULL, 16);
            char *sym = strchr(s1, ']');
            sym = sym ? sym + 1 : line;
            while (*sym == ' ')
                sym++;
            sym[strcspn(sym, "\n")] = 0;
            if (!strcmp(sym, "insn_begin")) {
                on = 1;
                continue;
            }
            if (!strcmp(sym, "insn_end")) {
                on = 0;
                seen_end = 1;
                continue;
            }
            if (on)
                count += *slot(pc);
        } else if (!strncmp(line, "IN:", 3)) {
            if (in_tb)
                *slot(tb_pc) = tb_n;
            in_tb = 1;
            tb_n = 0;
            tb_pc = 0;
        } else if (in_tb && line[0] == '0' && line[1] == 'x') {
            /* "0x00400580:  d10083ff  sub sp, sp, #0x20" */
            if (!tb_n)
                tb_pc = strtoull(line, NULL, 16);
            tb_n++;
        } else if (in_tb && (line[0] == '\n' || line[0] == '-')) {
            *slot(tb_pc) = tb_n;
            in_tb = 0;
        }
    }
    if (!seen_end) {
        fprintf(stderr, "qemu-count: no insn_end in the trace\n");
        return 1;
    }
    printf("%llu\n", (unsigned long long)count);
    return 0;
}
