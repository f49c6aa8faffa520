/* SPDX-License-Identifier: MIT */
/* fixel — the unit-test framework: FX_TEST(name) { FX_CHECK(...); } in any
 * file of tests/core, tests/boards or tests/tools is found by
 * tests/lib/gen-registry.sh and run by tests/lib/runner.c (tests/README.md). */
#ifndef FX_TEST_H
#define FX_TEST_H

#include <stdint.h>

typedef struct fx_test_case {
    const char *name;
    void (*fn)(void);
} fx_test_case;

extern const fx_test_case fx_tests[];

void fx_test_fail(const char *file, int line, const char *fmt, ...)
    __attribute__((format(printf, 3, 4)));
/* Number of failed checks in the running test so far. */
int fx_test_failed(void);

#define FX_TEST(name)              \
    void fx_test_##name(void); \
    void fx_test_##name(void)

#define FX_CHECK(cond)                                       \
    do {                                                     \
        if (!(cond))                                         \
            fx_test_fail(__FILE__, __LINE__, "%s", #cond);   \
    } while (0)

#define FX_CHECK_MSG(cond, ...)                              \
    do {                                                     \
        if (!(cond))                                         \
            fx_test_fail(__FILE__, __LINE__, __VA_ARGS__);   \
    } while (0)

#define FX_CHECK_EQ(a, b)                                                                    \
    do {                                                                                     \
        long long a_ = (long long)(a), b_ = (long long)(b);                                  \
        if (a_ != b_)                                                                        \
            fx_test_fail(__FILE__, __LINE__, "%s == %s (%lld != %lld)", #a, #b, a_, b_);     \
    } while (0)

#define FX_CHECK_EQ_HEX(a, b)                                                                \
    do {                                                                                     \
        unsigned long long a_ = (unsigned long long)(a), b_ = (unsigned long long)(b);       \
        if (a_ != b_)                                                                        \
            fx_test_fail(__FILE__, __LINE__, "%s == %s (0x%llx != 0x%llx)", #a, #b, a_, b_); \
    } while (0)

/* A small deterministic PRNG for property tests (xorshift32; never 0). */
static inline uint32_t fx_test_rand(uint32_t *s)
{
    uint32_t x = *s;
    x ^= x << 13;
    x ^= x >> 17;
    x ^= x << 5;
    return *s = x;
}

#endif
