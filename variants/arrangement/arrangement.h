/*
** arrangement.h: what the files of the arrangement variant (paper 000)
** share: its counters.  See README.md for the algorithm, its invariants and
** its deviations from the paper.
*/
#ifndef WK_ARRANGEMENT_H
#define WK_ARRANGEMENT_H
#include "variant.h"

#define AR_COUNTER_LIST(X)                                                                      \
    X(switch_events, "a moving Steiner vertex F passed a wavefront vertex onto the next piece") \
    X(start_events, "F or a reflex vertex reached a crossing of A(P) (000's start events)")      \
    X(brute_force_split_scans, "splits searched over a whole cycle (F unknown or no segment yet)") \
    X(arrangement_inserts, "segments inserted into the dynamic arrangement")                    \
    X(arrangement_removes, "segments removed from the dynamic arrangement")                     \
    X(arrangement_crossings_initial, "proper crossings among the segments of A(P)")             \
    X(intersection_queries, "next-crossing queries answered by a scan")                         \
    X(segments_scanned, "segments tested by those scans")                                       \
    X(cache_hits, "next-crossing queries answered from a segment's k cache")                    \
    X(cache_misses, "queries the cache could not answer")                                       \
    X(cache_refills, "caches filled again by a scan (k crossings kept)")                        \
    X(cache_invalidations, "caches cut by an inserted or widened segment")

WK_VARIANT_COUNTER_ENUM(AR_COUNTER_LIST)

#endif
