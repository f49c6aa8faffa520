/* libFuzzer target: fixel-kiosk's config and data-line parsers. The input
 * is split at the first NUL: config before it, data lines after. */
#include <stddef.h>
#include <stdint.h>
#include <string.h>

#include "../../tools/fixel-kiosk/kiosk.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    static kiosk_config k;
    char err[128];
    const char *p = (const char *)data;
    const char *nul = memchr(p, 0, size);
    size_t clen = nul ? (size_t)(nul - p) : size;
    if (kiosk_config_parse(&k, p, clen, err, sizeof err) < 0) return 0;
    if (!nul) return 0;
    const char *q = nul + 1, *end = p + size;
    int64_t t = 0;
    while (q < end) {
        const char *eol = memchr(q, '\n', (size_t)(end - q));
        if (!eol) eol = end;
        int s = -1;
        if (kiosk_data_line(&k, q, (size_t)(eol - q), t++, &s) == KIOSK_LINE_OK &&
            (s < 0 || s >= k.nsources))
            __builtin_trap();
        for (int i = 0; i < k.nsources; i++)
            if (k.sources[i].count > KIOSK_HIST_MAX) __builtin_trap();
        q = eol + 1;
    }
    return 0;
}
