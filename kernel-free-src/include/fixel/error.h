/* SPDX-License-Identifier: MIT */
/* fixel — error codes shared by the core and the boards.
 *
 * Functions that can fail return 0 (or a non-negative count) on success and a
 * negative code on failure. The values are Linux errno numbers so that a
 * backend can pass a failing syscall's -errno straight through, but the core
 * must not include <errno.h> (it is not guaranteed in a freestanding build).
 */
#ifndef FIXEL_ERROR_H
#define FIXEL_ERROR_H

#ifdef __cplusplus
extern "C" {
#endif

enum {
    FX_OK = 0,
    FX_ENOENT = 2,
    FX_EIO = 5,
    FX_E2BIG = 7,
    FX_ENOMEM = 12,
    FX_EACCES = 13,
    FX_EBUSY = 16,
    FX_ENODEV = 19,
    FX_ENOTDIR = 20,
    FX_EISDIR = 21,
    FX_EINVAL = 22,
    FX_EFBIG = 27,
    FX_ENOSPC = 28,
    FX_ESPIPE = 29, /* a FIFO, socket or device where a regular file is needed */
    FX_EDOM = 33,
    FX_ERANGE = 34,
    FX_EBADMSG = 74,
    FX_EOVERFLOW = 75,
    FX_ENOTSUP = 95,
};

/* A short English message for a negative (or positive) error code; never NULL. */
const char *fx_strerror(int err);

#ifdef __cplusplus
}  /* extern "C" */
#endif

#endif
