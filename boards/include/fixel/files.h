/* SPDX-License-Identifier: MIT */
/* fixel — opening the files a user names (issue #40). A program that
 * expects a file must not hang on a FIFO with no writer (open() and read()
 * block), read a directory or a device as data, or replace a FIFO or a
 * device node with a regular file when it writes. These functions are the
 * one rule every tool and the boards side follow:
 *   inputs   opened with O_NONBLOCK, then fstat: only a regular file is
 *            accepted (reads block again afterwards, as on any file)
 *   outputs  an existing target that is not a regular file is refused
 *            before it is opened (a FIFO with no reader blocks; a device
 *            may act on an open) and checked again before a rename; one
 *            swapped in after the check (a race no path-based call can
 *            close) is still refused once opened, but a rename made
 *            right after fx_check_replaceable can replace it
 * Symbolic links are followed (their target is what is checked). Errors
 * set errno: EISDIR for a directory, EOPNOTSUPP for a FIFO, socket or
 * device where a file is needed, else open()'s; and fill why (when not
 * NULL) with a message for "PROGRAM: OPTION PATH: <why>", e.g. "is a FIFO,
 * not a regular file". */
#ifndef FIXEL_FILES_H
#define FIXEL_FILES_H

#include <stddef.h>
#include <stdint.h>
#include <stdio.h>

#ifdef __cplusplus
extern "C" {
#endif

/* "a directory", "a FIFO", "a character device", "a block device",
 * "a socket", "a regular file" or "a special file", for a st_mode. */
const char *fx_file_kind(unsigned mode);

/* Opens a regular file for reading: the descriptor (O_CLOEXEC, blocking)
 * or -1; *size (when not NULL) gets its size in bytes. */
int fx_open_regular(const char *path, int64_t *size, char *why, size_t whylen);
/* The same as a stdio stream ("rb"), or NULL. */
FILE *fx_fopen_regular(const char *path, int64_t *size, char *why, size_t whylen);

/* Opens path for writing, created (mode 0644 less the umask) when missing:
 * append != 0 writes at its end, else it is truncated once it is known to
 * be a regular file. NULL when it exists and is not a regular file. */
FILE *fx_fopen_regular_write(const char *path, int append, char *why, size_t whylen);

/* 0 when path may be created or replaced (by a rename onto it): it does
 * not exist or is a regular file. -1 otherwise, errno and why set. */
int fx_check_replaceable(const char *path, char *why, size_t whylen);

/* mkdir -p: creates every missing directory of path (mode 0777 less the
 * umask). 0, or -1 with errno set: ENOTDIR when a part of it exists and is
 * not a directory, ENAMETOOLONG past 4095 bytes, else mkdir()'s. */
int fx_mkdir_parents(const char *path);

#ifdef __cplusplus
}  /* extern "C" */
#endif

#endif
