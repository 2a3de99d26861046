/*
** motorcycle.h: what the files of the motorcycle variant (paper 002)
** share: its counters and the view of the motorcycle graph that the finder
** consumes.  See README.md for the algorithm, its invariants and its
** deviations from the paper.
*/
#ifndef WK_MOTORCYCLE_H
#define WK_MOTORCYCLE_H
#include "variant.h"

#define MC_COUNTER_LIST(X)                                                                       \
    X(motorcycles, "motorcycles launched (reflex vertices of P)")                               \
    X(wall_crashes, "motorcycles that crashed into a wall (an edge of P)")                      \
    X(trace_crashes, "motorcycles that crashed into another motorcycle's trace")                \
    X(simultaneous_crashes, "motorcycles that crashed together with others at one point")      \
    X(crash_candidates, "motorcycle pairs tested for a crossing while building M(P)")           \
    X(switch_events, "a moving Steiner vertex F passed a wavefront vertex onto the next piece") \
    X(start_events, "F or a reflex vertex reached a resting Steiner vertex (a trace's end)")    \
    X(brute_force_split_scans, "splits searched over a whole cycle (F unknown or no trace yet)") \
    X(late_traces, "traces shot for reflex vertices that are not vertices of P")               \
    X(trace_extensions, "traces extended because the trace they crashed into ended early")      \
    X(ghost_traces, "traces that outlived their vertex to guard the traces ending on them")    \
    X(ray_shots, "rays shot against the wavefront (over the piece grid or a cycle)")         \
    X(ray_shot_pieces, "wavefront pieces tested by ray shots (grid cells or cycle walks)")      \
    X(piece_grid_builds, "builds of the grid of swept wavefront pieces for ray shots")         \
    X(crossing_candidates, "traces the trace grid offered for crossings with an added part")   \
    X(piece_grid_entries, "cell entries listed in that grid (builds and updates)")             \
    X(reference_fallbacks, "inputs handed to the reference variant (the trace finder failed)")

WK_VARIANT_COUNTER_ENUM(MC_COUNTER_LIST)

#endif
