/* SPDX-License-Identifier: MIT */
/* fixel — the version of the headers (compile time) and of the library
 * (run time). The numbers follow the Makefile's VERSION (tests/abi checks
 * that they agree); docs/ABI.md says when each one changes and how the
 * soname follows FX_VERSION_MAJOR. */
#ifndef FIXEL_VERSION_H
#define FIXEL_VERSION_H

#ifdef __cplusplus
extern "C" {
#endif

#define FX_VERSION_MAJOR 0
#define FX_VERSION_MINOR 1
#define FX_VERSION_PATCH 0
#define FX_VERSION_STRING "0.1.0"
/* One number to compare: FX_VERSION_NUMBER >= FX_VERSION_ENCODE(0, 2, 0). */
#define FX_VERSION_ENCODE(major, minor, patch) (((major) << 16) | ((minor) << 8) | (patch))
#define FX_VERSION_NUMBER FX_VERSION_ENCODE(FX_VERSION_MAJOR, FX_VERSION_MINOR, FX_VERSION_PATCH)

/* The version of the library actually linked, "MAJOR.MINOR.PATCH": a program
 * built against newer headers can tell an older libfixel.so.0 at run time. */
const char *fx_version(void);
/* The same as FX_VERSION_NUMBER of the library's own build. */
int fx_version_number(void);

#ifdef __cplusplus
}  /* extern "C" */
#endif

#endif
