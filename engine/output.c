/*
** output.c: an output file that appears whole or not at all.
** A regular path is written to PATH.tmp.PID and renamed over PATH only when
** everything was written, so a failed run leaves no partial file and an
** existing PATH untouched.  A path that exists and is not a regular file (a
** device such as /dev/null, a FIFO) is written in place: renaming over it
** would replace the device (seen once as root).  No path means stdout.
*/
#define _POSIX_C_SOURCE 200809L
#include "wskel.h"

#include <errno.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

wk_status wk_output_open(wk_run *R, wk_output *o, const char *path) {
    o->f = NULL;
    o->path = path;
    o->atomic = false;
    o->tmp[0] = '\0';
    if (!path) {
        o->f = stdout;
        return WK_OK;
    }
    struct stat sb;
    o->atomic = !(stat(path, &sb) == 0 && !S_ISREG(sb.st_mode));
    if (o->atomic &&
        (size_t)snprintf(o->tmp, sizeof o->tmp, "%s.tmp.%ld", path, (long)getpid()) >= sizeof o->tmp)
        return WK_FAIL(R, WK_EUSAGE, path, 0, "output path too long");
    o->f = fopen(o->atomic ? o->tmp : path, "w");
    if (!o->f) return WK_FAIL(R, WK_EALGO, path, 0, "cannot write: %s", strerror(errno));
    return WK_OK;
}

wk_status wk_output_close(wk_run *R, wk_output *o, wk_status st) {
    if (!o->f) return st;
    const char *name = o->path ? o->path : "stdout";
    if (st == WK_OK && (fflush(o->f) != 0 || ferror(o->f)))
        st = WK_FAIL(R, WK_EALGO, name, 0, "write failed: %s", strerror(errno));
    if (o->f != stdout) {
        if (fclose(o->f) != 0 && st == WK_OK)
            st = WK_FAIL(R, WK_EALGO, name, 0, "write failed: %s", strerror(errno));
        if (o->atomic) {
            if (st == WK_OK && rename(o->tmp, o->path) != 0)
                st = WK_FAIL(R, WK_EALGO, name, 0, "cannot rename output: %s", strerror(errno));
            if (st != WK_OK) remove(o->tmp);
        }
    }
    o->f = NULL;
    return st;
}
