/*
** offset_standin.h: TEMPORARY declaration of the engine's offset API
** (wk_offset, wk_offset_set) for building the Python module before the
** engine's own implementation (engine/offset.c) is merged.  The Makefile
** compiles python/wskel/offset_standin.c into the module, and defines
** WKS_OFFSET_STANDIN, only while engine/offset.c does not exist; with the
** real one in place neither this header nor the stand-in is used.
**
** The declarations are exactly the engine's agreed API (issue 15).
*/
#ifndef WKS_OFFSET_STANDIN_H
#define WKS_OFFSET_STANDIN_H

#include "wskel.h"

typedef struct wk_offset_set {
    double t;
    uint32_t n_polygons;     /* components; polygon_start: n_polygons + 1 offsets into the rings:
                                a component's first ring is its outer ring (CCW), then its holes (CW) */
    uint32_t *polygon_start;
    uint32_t n_rings;
    uint32_t *ring_start;    /* n_rings + 1 offsets into p */
    wk_point *p;             /* rings not closed */
} wk_offset_set;

wk_status wk_offset(wk_run *R, const wk_polygon *P, const wk_skeleton *S, double t,
                    wk_offset_set **out);
void wk_offset_set_free(wk_run *R, wk_offset_set *O);

#endif
