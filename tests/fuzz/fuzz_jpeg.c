/* SPDX-License-Identifier: MIT */
/* libFuzzer target (issue #41): the jpeg decoder of boards/image/ (the body
 * is fuzz_image.h's, shared by the three image targets). */
#include "fuzz_image.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    static const char magic[] = "\xff\xd8\xff";
    return fuzz_image(magic, sizeof magic - 1, data, size);
}
