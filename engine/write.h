/*
** write.h: what the writers (write_*.c) share; engine-private.
**
** Every writer emits input numbering (wk_polygon_output_node,
** wk_polygon_input_edge), refuses a skeleton whose ids are out of range (a
** finished skeleton never has any), and ends by flushing and checking the
** stream, so a full disk or a closed pipe is a failure (WK_EALGO "write
** failed") rather than a silently truncated file.  Writers never close f.
*/
#ifndef WK_WRITE_H
#define WK_WRITE_H
#include "faces.h"

#include <errno.h>
#include <string.h>

/* The checks every writer runs before writing anything. */
static inline wk_status wk_write_begin(wk_run *R, const wk_polygon *P, const wk_skeleton *S,
                                       const char *what) {
    errno = 0; /* so that wk_write_end reports this stream's error */
    return wk_faces_check_ids(R, P, S, what);
}

/* Flush f and report any error the stream has seen since it was opened. */
static inline wk_status wk_write_end(wk_run *R, FILE *f, const char *format) {
    if (fflush(f) != 0 || ferror(f))
        return WK_FAIL(R, WK_EALGO, NULL, 0, "write failed (%s output): %s", format,
                       errno ? strerror(errno) : "stream error");
    return WK_OK;
}

/* The polygon's name on a comment line: control characters become '?'. */
static inline void wk_write_name(FILE *f, const wk_polygon *P) {
    for (const unsigned char *c = (const unsigned char *)(P->name[0] ? P->name : "polygon"); *c;
         c++)
        fputc(*c < 0x20 ? '?' : *c, f);
}

/* The stored node whose output id is i, given vertex_of from wk_input_order
** (the inverse of wk_polygon_output_node). */
static inline uint32_t wk_stored_node(const wk_polygon *P, const uint32_t *vertex_of, uint32_t i) {
    return i < P->n ? vertex_of[i] : i;
}

#endif
