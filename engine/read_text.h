/*
** read_text.h: what the text readers (polygon_read.c, polygon_read_gis.c)
** share; engine-private.
*/
#ifndef WK_READ_TEXT_H
#define WK_READ_TEXT_H
#include "wskel.h"

/* The bytes of a text document: strict UTF-8 (no overlong forms, no
** surrogates, nothing above U+10FFFF), no UTF-16 byte order mark, no NUL and
** no control character but tab, LF and CR (nor DEL or the C1 controls).
** WK_OK, or WK_EINPUT naming the line and the column (in bytes) of the first
** fault; format ("GraphML", "GeoJSON", "WKT") names the format in the
** message. */
wk_status wk_read_utf8_bytes(wk_run *R, const char *buf, size_t len, const char *name,
                             const char *format);

#endif
