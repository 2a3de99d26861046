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

/* Text m as one line of UTF-8 text in buf (for messages that quote the
** input, as libxml2's and jansson's do): runs of blanks and control
** characters become one space, bytes that are no UTF-8 (a quote cut inside a
** character) '?', and no blank is left at either end. */
void wk_read_clean_message(char *buf, size_t size, const char *m);

#endif
