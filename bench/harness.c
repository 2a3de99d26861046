/*
** harness.c: the usage error and the checked allocators of bin/wskel-bench
** (harness.h).
**
** Invariant: none of x* returns NULL.  Out of memory ends the process with
** _exit (not exit): another thread may be between two fputs of a row, and
** exit would flush its half of the row; rows are flushed as they are
** written, so _exit loses nothing that was complete.
*/
#define _GNU_SOURCE
#include "harness.h"

#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

void die_usage(const char *fmt, ...) {
    va_list ap;
    va_start(ap, fmt);
    fputs("wskel-bench: ", stderr);
    vfprintf(stderr, fmt, ap);
    fputs(" (see --help)\n", stderr);
    va_end(ap);
    exit(EXIT_USAGE);
}

void die_nomem(void) {
    static const char msg[] = "wskel-bench: out of memory\n";
    ssize_t w = write(2, msg, sizeof msg - 1); /* stderr, without stdio (it may allocate) */
    (void)w;
    _exit(EXIT_NOMEM);
}

void *xmalloc(size_t size) {
    void *p = malloc(size ? size : 1);
    if (!p) die_nomem();
    return p;
}

void *xcalloc(size_t count, size_t size) {
    void *p = calloc(count ? count : 1, size ? size : 1);
    if (!p) die_nomem();
    return p;
}

void *xrealloc(void *p, size_t size) {
    void *q = realloc(p, size ? size : 1);
    if (!q) die_nomem();
    return q;
}

void *xreallocarray(void *p, size_t count, size_t size) {
    if (size && count > SIZE_MAX / size) die_nomem();
    return xrealloc(p, count * size);
}

char *xstrdup(const char *s) {
    char *d = strdup(s);
    if (!d) die_nomem();
    return d;
}

char *xstrndup(const char *s, size_t n) {
    char *d = strndup(s, n);
    if (!d) die_nomem();
    return d;
}
