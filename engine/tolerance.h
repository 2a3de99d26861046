/*
** tolerance.h: the one tolerance policy of wskel.  Every tolerance the
** engine and the variants use is named here with the reason for its value;
** no other file writes a tolerance as a literal.
**
** The policy.
**   - Decisions on input (simplicity, orientation, reflexness, the checks of
**     the readers) are exact: a float filter with an expansion fallback
**     (predicates.c).  They need no tolerance.
**   - Constructions (offset lines, vertex velocities, event times and
**     points) are in double.  Their error is a few ulps of the coordinates
**     relative to the polygon's origin (the bounding-box centre), i.e.
**     about 1e-16 * scale, where scale is the bounding-box diagonal
**     (wk_polygon_scale), times the conditioning of the construction.
**   - The simulation works with one distance tolerance
**     eps_d = WK_TOL_REL * scale and one time tolerance
**     eps_t = WK_TOL_TIME * eps_d / wmax (wmax the largest weight): two event
**     points coincide within eps_d; two events are simultaneous within
**     eps_t (a vertex of speed s moves s * eps_t within it, so "a vertex
**     arrives at a node" is judged within eps_d + s * eps_t).
**   - The validator's default tolerance is WK_VALIDATE_TOL_REL * scale, far
**     above eps_d (what the simulation may leave behind) and far below any
**     feature a user can see.
**
** Features below the tolerance.  A feature shorter than eps_d (an edge of
** 1e-16, a vertex 1e-12 off a line, a small polygon part next to a vertex
** 4e9 away) is resolved at tolerance level: its events happen at t within
** eps_t of the time where the simulation sees them, and it may leave nodes
** at t = 0 (within the time tolerance) next to the boundary.  The
** validator accepts such a node when it lies within its tolerance of the
** boundary and its time is within the validator's time tolerance
** (tol / wmax) of 0, as long as the distances (c), the tree and faces
** (d, e) and planarity (f) hold within tolerance: it is the trace of a
** sub-tolerance feature, not a wrong node.
*/
#ifndef WK_TOLERANCE_H
#define WK_TOLERANCE_H

/* ------------------------------------------------------ the simulation */

/* eps_d = WK_TOL_REL * scale.  Doubles carry ~1e-16 relative error and the
** worst-conditioned construction the engine keeps (a vertex between edges
** meeting at a sine just above WK_PARALLEL_SIN) loses up to 1e-9 of that
** again; 1e-9 leaves room for the error of a constructed event while staying
** 1000 times below the validator's default (WK_VALIDATE_TOL_REL). */
#define WK_TOL_REL 1e-9
/* A variant that steps a moving polygon (004): a vertex within WK_DEFORM_CONTACT_SLACK *
** eps_d of an event point takes part in it, and a penetration counts when
** the vertex meets the piece within that distance of the piece's ends (a
** vertex-on-vertex contact).  1, the wavefront's own bar (its split search
** takes a vertex within eps_d of a piece as on it, and keeps events farther
** apart separate).  It was 16 (as WK_REFINE_DIST_SLACK), and the stepping
** variant then merged what the wavefront keeps apart: a step of 14 eps_d
** left between collinear edges by a collapsing tab (stress case
** s1-c00288-far), events 14 eps_d apart at the centre of a regular 64-gon
** perturbed by 1e-7; both gave valid skeletons that were not the
** reference's.  Its event points come from the input lines or the
** speed-weighted collapse point, within the rounding of eps_d. */
#define WK_DEFORM_CONTACT_SLACK 1.0
/* eps_t = WK_TOL_TIME * eps_d / wmax.  Simultaneous means equal up to the
** rounding of a constructed time (~1e-15 relative); a window as wide as
** eps_d / wmax would merge events that happen in sequence, and fast
** vertices move far in between (a vertex of speed s covers s * eps_t). */
#define WK_TOL_TIME 1e-3
/* Two edges whose unit directions have |sin| below this and the same sense
** are parallel: the vertex between them is straight (equal weights) or
** collinear (different weights: the collinear rule takes it).  Between two
** edges of different weight at sine s the vertex moves at ~1/s; at 1e-12 it
** moved at 10^11 times their speed and broke the wavefront ("unresolved
** spike", cycles of two vertices, nodes off their lines) on 32 of 35 such
** failures of the reference (tests/test_degenerate.py: sweep-direction
** polygons with equal-x chains, turned in random directions). */
#define WK_PARALLEL_SIN 1e-9
/* Opposite senses (antiparallel edges: a zero-width spike) keep the old
** bar: at 1e-9, seven small turned grid polygons that passed before failed
** with "antiparallel wavefront vertex". */
#define WK_ANTIPARALLEL_SIN 1e-12
/* The three-lines system of an event (kinetics.c) is solved exactly only
** when |det| exceeds this times the sum of the weights: below, the lines
** are nearly dependent and the kinematic estimate is better. */
#define WK_MEET_DET_REL 1e-9
/* A refined event replaces the kinematic estimate only when it agrees with
** it within these multiples of eps_t and eps_d (the estimate's own error is
** a few eps at most; beyond that the refinement solved a different event). */
#define WK_REFINE_TIME_SLACK 16.0
#define WK_REFINE_DIST_SLACK 16.0
/* A reflex vertex approaching an offset line slower than this times its
** speed (plus the line's) is moving parallel to it: no split. */
#define WK_APPROACH_REL 1e-12
/* Angles (radians) in the pairing of a group: two directions are equal
** within WK_ANGLE_EQ (unit-vector rounding is ~1e-16; 1e-12 allows the
** atan2 of constructed directions); a clockwise turn wraps at WK_ANGLE_WRAP
** (so an exact 0 turn counts as a full turn); a turn within WK_SPIKE_TURN
** of 2 pi is a zero-width spike. */
#define WK_ANGLE_EQ 1e-12
#define WK_ANGLE_WRAP 1e-13
#define WK_SPIKE_TURN 1e-9
/* Pieces of two different edges may cancel between two nodes (leaving an
** arc) only when the edges are antiparallel to this sine; beyond it the two
** nodes are one point seen at too fine a scale.  Loose on purpose: pieces
** 1e-3 apart in direction that cancel over a length L diverge by 1e-3 L,
** so they are a sub-tolerance picture whenever the nodes could be merged. */
#define WK_CANCEL_SIN 1e-3
/* ... or when they bound a sliver: the nodes at least this many node radii
** (eps_g) apart and the pieces at most 2 eps_g apart along the way (sin L <=
** 2 eps_g, which holds when both lines pass within eps_g of both nodes).
** That is a crack of the wavefront closing along its length, the arc its
** bisector, every point of it within 2 eps_g of both offset lines.  Why it
** is needed: a reflex vertex of a star with 10^5 vertices (speed 8.5e3)
** splits a crack whose sides are 1.2e-3 apart in direction, 300 eps_d from
** the crack's tip and within eps_d of both sides; the two sides then run
** between the split's node and the tip's node and WK_CANCEL_SIN alone
** failed the run (bin/wskel-gen star --n 100000 --seed 1, every variant;
** star --n 50000 --seed 1).  Why 64: nodes 64 radii apart are two points at
** the group's scale, which no widening short of 32 eps_g merges; closer
** nodes of non-parallel pieces keep the retry that merges them. */
#define WK_CANCEL_SLIVER_RADII 64.0
/* A group that cannot be planned consistently with nodes eps_d wide is
** planned again with the radius doubled, up to this many eps_d (256 eps_d
** is still 4 times below the validator's default tolerance). */
#define WK_GROUP_WIDEN_MAX 256.0
/* A group whose plan fails at a node widens that node alone (a wide spot,
** wf_resolve_group) at most this many times before the whole group is
** widened as the last resort: each try is a whole plan of the group, and a
** failure that names another node at every try is not one event seen too
** finely.  16: eight doublings of each of the two nodes one failure names
** (eps_d to WK_GROUP_WIDEN_MAX eps_d) fit. */
#define WK_NODE_WIDEN_SPOTS 16
/* A node of a group lies clearly behind a piece's line (node_behind_piece
** in wavefront_group.c) when it is more than this many ulps of its
** coordinates behind it: a node's place is a constructed point, off by a few
** ulps of its size (more for a fast vertex, which arrives at the node of a
** slow one, not where it is); 1024 ulps is 9e-10 at 4e6 from the centre,
** far below the 1.2e-5 gap of the case that needs it and eps_d (9e-3). */
#define WK_BEHIND_ULPS 1024.0
/* A cycle is flat (collapse_flat_cycle) when all its vertices lie within
** this many eps_d of one line: the group resolution, working with nodes
** eps_d apart, can leave such a cycle up to a few hundred eps_d thin. */
#define WK_FLAT_CYCLE_SLACK 1e3
/* The zipper of a group (wavefront_group.c, zip_overlap) forces the next
** vertex of two antiparallel chains meeting along a line only while the
** chains' next points lie clearly apart, more than this many times the
** arrival radius (or eps_g) from the node before: closer, the next round's
** arrival and pinch tests (radius eps_g, ends within eps_g) could decide
** otherwise than the zipper's simple picture, so the rounds take over
** there.  4 keeps every such test's reach (eps_g and its rounding) out. */
#define WK_ZIP_CLEAR 4.0
/* A split of an input vertex onto a piece of an input edge within eps_d of
** an input vertex x at the piece's end passes x by (x does not arrive at the
** split's node; wavefront_group.c, plan_shields) when the cut lies inside the
** piece by more than this many ulps of the input gap and motion it is
** computed from: rounding, not tolerance, because the skeleton on either
** side of such a gap differs by whole faces (two holes 1e-10 apart,
** tests/data/fuzz/ealgo_holes_vertices_1e-10_apart.wpoly), so the input's
** own side is the answer (CGAL's); 64, as WK_FOLD_ULPS, covers the few
** roundings of that computation.  At the nominal and finer tolerances
** only (tol_scale <= 1): the coarser retries of wk_solve_checked close such
** gaps as the tolerance sees them, where the cascade of sub-tolerance
** events after the first cannot be resolved consistently (constructed
** vertices have no input coordinates to decide by).  The same bar decides
** the other side: a hit of the piece's line beyond x is no split
** (wk_wf_split_test), and an input vertex behind the offset line of
** another ring's edge never reaches it (wavefront.c, behind_offset_line).
** At a node where a split is so resolved, a vertex an earlier group made
** takes part only if it lies at the node's point to this many ulps of the
** points and of its motion (wavefront_group.c, bystander): there the
** input's picture is finer than eps_d (three holes whose apexes lie 2.5e-9
** apart, tests/data/holes/near_touch_three_holes_bystanders.wpoly), and an
** input vertex meeting another ring's piece past an end that a group made
** by more than this many ulps does not split the piece (wavefront.c,
** wf_made_end_passed; near_touch_three_holes_passes_made_end.wpoly). */
#define WK_SPLIT_SIDE_ULPS 64.0
/* ... and only when the stretch of the piece between x and the cut grows
** faster than this times the speeds of its ends: a stretch that shrinks
** collapses at once into what the tolerance picture makes now, and one that
** keeps its length would stay below eps_d for good.  1e-9, the relative
** bar of WK_PARALLEL_SIN: slower is parallel motion at the tolerance.  The
** same bar, and WK_BEHIND_ULPS for the rounding of the node, decide which
** stretch shrinks so slowly that it collapses later than eps_t
** (wk_stretch_collapses_later, plan_slow_stretches in wavefront_group.c):
** "at once" above holds only for stretches that shrink fast. */
#define WK_SPLIT_SIDE_GROWTH_REL 1e-9
/* --check-invariants: a vertex lies on its edges' offset lines within this
** many (eps_d + speed * eps_t), times (1 + t) for the growth of rounding with
** time: generous on purpose, it looks for broken invariants, not rounding. */
#define WK_INVARIANT_SLACK 1e3

/* wk_solve_checked: a run that fails, or whose skeleton the validator
** rejects, is repeated with the simulation's tolerances (eps_d, eps_t)
** WK_TOL_ESCALATE_STEP times coarser, up to WK_TOL_ESCALATE_MAX times: at
** 64 * eps_d = 6.4e-8 * scale the coarsest picture is still 16 times finer
** than the validator's default.  Fuzzed polygons with features a few eps_d
** wide (a vertex 5e8 away from a part of size 1) gave skeletons with a
** double arc at 1 * eps_d and valid ones from 4 * eps_d on. */
#define WK_TOL_ESCALATE_STEP 4.0
#define WK_TOL_ESCALATE_MAX 64.0
/* ... and when no coarser picture helps either, with tolerances
** WK_TOL_ESCALATE_STEP times finer, down to WK_TOL_REFINE_MIN times.  eps_t
** is set by the slowest vertices (eps_d / wmax), but a vertex of speed s
** moves s * eps_t within it: a spike of angle 1e-6 has a vertex of speed
** 2e6, which covers 2000 eps_d in eps_t and merges features of 1e-6 scale
** into one group that cannot be paired (a fuzz finding: an H shape of unit
** arms beside a spike 1e6 long, tests/data/fuzz/
** invalid_naive_translated_h_cycle.wpoly, valid from 1/4 down).  At 1/64,
** eps_t = 1.6e-14 * scale / wmax is still 100 times the rounding of a
** constructed time (~1e-16 * scale / wmax). */
#define WK_TOL_REFINE_MIN (1.0 / 64.0)

/* ------------------------------------------------------- the validator */

/* Default distance tolerance: WK_VALIDATE_TOL_REL * scale (a caller may
** pass another).  1000 times eps_d: what the simulation leaves behind is
** far inside it. */
#define WK_VALIDATE_TOL_REL 1e-6
/* Two valid skeletons of one polygon are the same skeleton (the variants
** fuzz target's oracle, tests/same_skeleton.h) when they agree after nodes
** within WK_SAME_SKELETON_TOL_REL * scale of each other (and within that
** over their faces' weight in time) are merged and the zero-length arcs
** this leaves are dropped.  The validator's tolerance: each skeleton is
** certified to it, so below it two valid skeletons may resolve a feature
** differently; the fuzz finding of a needle 9e6 long beside unit-sized
** parts (features 1.1e-7 of the scale) has valid skeletons from the reference and
** a chain-merging variant that agree at 1e-6 and differ at 1e-7 of the scale. */
#define WK_SAME_SKELETON_TOL_REL WK_VALIDATE_TOL_REL
/* The face areas must sum to the polygon's area within this relative error
** (each face's area is a shoelace sum over nodes constructed to ~eps_d). */
#define WK_VALIDATE_AREA_REL 1e-6
/* Planarity: two sides collinear within WK_FOLD_ULPS ulps of the
** coordinates that overlap are a fold even where exact tests see them only
** touch; the bar is rounding, capped at WK_FOLD_TOL_CAP * tol, not tol:
** legitimate faces can be far thinner than tol (a triangle with weights 1,
** 1000, 0.001: 1e-6 wide at 1000; long faces 1e-3 wide in 10^6-vertex
** polygons; a 2e-3 polygon at 1e6 from the origin: faces 1e-8 wide, where
** 64 ulp is 1.4e-8). */
#define WK_FOLD_ULPS 64.0
#define WK_FOLD_TOL_CAP 1e-3
/* The point-in-polygon grid widens its cells by this fraction of a cell
** (plus the rounding of the coordinates) so that no edge near a cell border
** is missed. */
#define WK_PIP_MARGIN_REL 1e-6

/* ------------------------------------------------- search structures */

/* Two unit directions are parallel below this |cross| in crossing queries
** between bisector segments (the sine of WK_ANTIPARALLEL_SIN: collinear overlaps are
** not crossings). */
#define WK_ARR_PARALLEL 1e-12

/* The graph of reflex-vertex traces of 002, section 2 (traces that stop at
** the walls or at earlier traces).  Two trace directions are parallel below
** this |cross|: then only collinear traces (within eps_d) meet, head-on or
** one behind the other.  The bar of WK_ARR_PARALLEL, for the same reason:
** above it the crossing's position along the lines (rounding ~1e-16 *
** scale / |cross|) stays far below the polygon's size. */
#define WK_MCG_PARALLEL_SIN 1e-12
/* Resting Steiner vertices on one trace within WK_MC_STEINER_SLACK * eps_d
** of each other are one point (a trace that ended at another's end: the
** two places come from different pairs of motorcycles and agree to a few
** eps_d); a cut there passes all of them at once. */
#define WK_MC_STEINER_SLACK 16.0
/* Its candidate grid lists a trace in every cell within this many eps_d of
** the trace's bounding segment (origin to wall hit).  Crossings count up to
** eps_d beyond a segment's ends, and a computed crossing lies within
** rounding (far below eps_d) of both lines, so 2 eps_d would cover them;
** 4 also keeps every listing at least 3 eps_d (along the trace) ahead of
** any crash that the listed cell can matter for, so a trace is always
** listed before it can stop there. */
#define WK_MCG_GRID_DELTA 4.0
/* That grid's cells keep each listed trace's line rounded to floats (in
** the cell's frame), and a scan passes a listed trace that has not stopped
** to the full pair test only when the rounded lines cross within a margin
** of the cell: WK_MCG_SHORTLIST_REL (rho + delta) + delta +
** WK_MCG_SHORTLIST_EXT * (the box's extent), over |det|.  Float rounding
** moves a line by about 2e-7 (rho + delta) in the cell, so REL keeps 5
** times that; EXT covers the rounding of the full test's crossing and of
** its cell lookup (ulps of the box's coordinates); below
** WK_MCG_SHORTLIST_SIN (about 6 float rounding errors of the 2x2
** determinant) the pair always gets the full test.  Not a tolerance of the
** graph: a wider margin only passes more pairs to the full test, which
** decides as before, so the graph and every event are the same. */
#define WK_MCG_SHORTLIST_REL 1e-6
#define WK_MCG_SHORTLIST_EXT 1e-12
#define WK_MCG_SHORTLIST_SIN 1e-6
/* The consistency check of that graph (tests, debug) accepts a stop point
** within this many eps_d (per member of a simultaneous group, whose members
** join pairwise within eps_d) of the wall or trace it stops at, and times
** within as many eps_t: crossing points are constructed (a few ulps) and
** the pairwise joins of a group can chain. */
#define WK_MCG_CHECK_SLACK 16.0

/* ------------------------------- rays against a moving wavefront (finders) */

/* A static ray hits a wavefront piece when its parameter along the piece
** is in [-WK_RAY_PIECE_SLACK, 1 + WK_RAY_PIECE_SLACK] (rounding of the
** crossing), and not more than WK_RAY_BEHIND_SLACK * eps_d behind the
** ray's start (the ray's own vertex's pieces are left out by the callers).
** A piece that close to a reflex vertex is a contact, which the reference's
** split test takes at once (it accepts a vertex up to eps_d behind a line).
** The bar was 1e-3 eps_d *ahead*: a fuzz finding, a pinch 1e-6 wide with
** eps_d = 0.43 (tests/data/fuzz/ealgo_arrangement_pinch.wpoly), put the
** other side's piece 1e-6 ahead of the vertex, the segment finder never
** met it and the vertex was left alive (exit 2 of a variant that finds splits by ray shots). */
#define WK_RAY_PIECE_SLACK 1e-12
#define WK_RAY_BEHIND_SLACK 1.0
/* A hit within WK_RAY_END_SNAP of a piece's end (as a fraction of the piece)
** is at the end vertex: ambiguous, the ray is shot again
** WK_RAY_RESHOOT_DELAY * eps_t later, when the vertex has moved off it. */
#define WK_RAY_END_SNAP 1e-9
#define WK_RAY_RESHOOT_DELAY 1e3
/* ... but when v would reach the line of a piece at the corner within that
** delay, the reshoot comes after this share of the time to that meeting:
** eps_d / wmax is no moment when a far vertex makes eps_d large, and a
** reshoot after v's own split of the corner's piece finds the piece behind
** v (wavefront_ray.c, reshoot_delay).  One half: the corner vertex moves
** off the ray, and v is still short of every piece there. */
#define WK_RAY_RESHOOT_GAP_SHARE 0.5
/* The reshoot picks among the pieces that pass within WK_RAY_RESHOOT_NEAR *
** eps_d of the hit point at the time of the first shot (vertices that close
** are one point to the simulation): which of the pieces at that vertex the
** ray enters.  Over the whole cycle it took whatever the ray met at the
** later time, and in the delay a fast vertex can sweep its piece across the
** ray: a fuzz finding (tests/data/fuzz/, the H at 1e6 with needles
** 1e5..5e5 long, issue 11): a reflex vertex's ray through a convex corner
** 1.4 away got the piece of a needle's reflex vertex (speed 2e5, 280 units
** in the delay) whose edge is collinear with the shooting vertex's own, so
** the hit was at the ray's start: its A(P) segment was empty, and the
** head-on collision of the two reflex vertices was never found (a cycle,
** exit 3).  When the ray meets none of those pieces later (the hit point
** is the shooting vertex itself, its neighbour's piece collapsing there:
** 3 shots on the star n = 200 of make regress), the whole cycle decides,
** as before; with that, no counter of make regress changed. */
#define WK_RAY_RESHOOT_NEAR 1.0
/* A point moving on a ray that rides along with a wavefront vertex (the
** vertex moves on the ray itself: head-on reflex vertices) never leaves its
** piece: their relative rate is zero within this times their speeds. */
#define WK_RIDE_ALONG_REL 1e-10
/* After a group, a point on a ray is put on a new piece at the same place
** when the two places agree within WK_RELOCATE_SLACK * eps_d (the group
** moved nothing by more than a few eps_d), else the ray is shot again. */
#define WK_RELOCATE_SLACK 1e3
/* Grids over rays and pieces (002's trace finder: its piece and trace
** grids): a wavefront piece is listed in every cell within
** WK_PIECE_GRID_MARGIN * eps_d of the region it sweeps; a ray's hit on it
** lies within WK_RAY_PIECE_SLACK of its length (far below eps_d on any
** piece the grid's cells can tell apart) plus rounding of the crossing of
** it.  A piece that shrinks is listed until WK_PIECE_GRID_COLLAPSE_SLACK *
** eps_t after its ends meet: the engine computes that edge event from the
** offset lines, not from these positions, and may take it a few eps_t
** later.  A trace part is listed WK_TRACE_GRID_PAD * eps_d longer at both
** ends (a crossing counts up to eps_d beyond a trace's ends) in every cell
** within twice that of it. */
#define WK_PIECE_GRID_MARGIN 8.0
#define WK_PIECE_GRID_COLLAPSE_SLACK 64.0
#define WK_TRACE_GRID_PAD 2.0
/* The bisector-segment finder of 000 (variants/) also tests, with the
** reference's split test, the pieces of v's cycle next to v's own two
** pieces, and goes on past each neighbour that lies within
** WK_ARR_NEAR_SLACK * eps_d of v (a chain of sub-tolerance edges).  Across
** a tiny edge v lies within eps_d of its neighbour's next piece: the
** reference splits it there at once (the test accepts a vertex up to eps_d
** behind a line and beyond a piece's end), while v's segment, a ray along
** v's motion, never meets that piece (89 of the 90 stress inputs, classes
** tiny_edge and mixed, where that finder's skeleton differed from the
** reference's: e.g. a reflex corner chamfered by a 1e-11 edge, which the
** reference resolves as the unchamfered corner). */
#define WK_ARR_NEAR_SLACK 16.0
/* Below this |denominator| a line-line intersection is not formed (the
** lines are parallel to the last bits; the quotient would overflow). */
#define WK_DIV_GUARD 1e-300

/* ---------------------------------------------------- sweep directions */

/* P counts as sweepable in direction d (every line perpendicular to d meets
** it in one interval: 001's class) when moving each vertex by at most
** WK_MONO_DIR_TOL * eps_d along d makes it so: below eps_d the simulation
** cannot tell such a polygon from a sweepable one.  Polygons sweepable only
** with edges perpendicular to the sweep, turned in doubles, need it: their
** "perpendicular" edges differ in direction by rounding (~1e-16 *
** |coordinates| / edge length), so the exact good directions of their
** reflex vertices do not meet (22 of 88 such polygons were refused as
** sweepable in no direction).  1: the rounding of
** turned coordinates (~1e-16 * (scale + offset)) stays far below
** eps_d = 1e-9 * scale unless the polygon lies ~1e6 of its own sizes from
** the origin. */
#define WK_MONO_DIR_TOL 1.0
/* The chain construction hands a polygon with an edge shorter than
** WK_MONO_TINY_EDGE_REL * scale (times the run's tolerance scale) to the
** reference wavefront instead.  Such an edge is a sub-tolerance feature
** (shorter than the simulation's eps_d = WK_TOL_REL * scale): the
** reference resolves it by a group at tolerance level, the chains by their
** local decisions, and the two valid results differ by up to the edge's
** influence on its neighbours (tests/stress, classes tiny_edge, mixed,
** regular_tiny_edge: 27 of the 28 differences of a 10^4 sweep had an edge
** below 1e-10 of the scale; the bar was 1e-10 until stress case
** s6-c04452-tiny_edge, an edge of 1.9e-10 of the scale between collinear
** edges of weights 3 and 4, where the collinear rule gave the 625-long
** neighbour's region to the other face: the whole sub-eps_d range goes to
** the reference). */
#define WK_MONO_TINY_EDGE_REL WK_TOL_REL
/* Arcs of good directions (direction.c) whose length is within this many
** radians of 0 or pi belong to a vertex whose neighbour offsets u1, u2 are
** (nearly) on one line: there the test of the arc's middle against u1 and
** u2 (products of projections ~ |u| sin(length / 2)) would be decided by the
** rounding of atan2, cos and sin (~1e-16 rad), so the arc is chosen by the
** sign of u1 . u2 instead (flat vertex or spike).  1e-6 is ten orders above
** that rounding and far below any exterior angle the test has to tell. */
#define WK_MONO_DIR_FLAT_ARC 1e-6
/* A run of good directions narrower than this (radians) is tried only through
** its edges' exact normals and its middle: inside it the widest gap between
** edge perpendiculars (the preferred candidate of a wide run) would be
** picked by the rounding of the angles (~1e-16 rad each, more for short
** edges far from the origin: 1e-12 rad for an edge of 10 at 1e5, see the
** variant's README.md), and 1e-7 keeps every gap counted far above
** that.  Not the decision itself: check_direction decides on projections. */
#define WK_MONO_DIR_WIDE 1e-7

/* ------------------------------------ chain skeletons and their merge */

/* Chain skeletons (chain_skeleton.c of the sweep variant).  A new chain
** vertex is snapped onto its two offset lines, and an edge collapse replaced
** by the meeting point of its three offset lines, within these windows; M''s
** next vertex (merge.c) is replaced by the meeting point of its three
** offset lines within WK_MONO_EXACT_SLACK * eps_d as well.  A chain's events
** are kinematic estimates extrapolated from each vertex's birth, and
** vertices between nearly parallel edges are fast, so the estimate drifts
** with speed and age far beyond the reference wavefront's few eps_d: the
** exact construction is the same event when it agrees in place and time,
** and taking it keeps later events on the input lines.  WK_MONO_EXACT_SLACK
** (a multiple of eps_d): 1e3, the validator's default tolerance
** (WK_VALIDATE_TOL_REL), so a snap never moves a point by more than the
** validator would accept (except along M''s ray and the crossed trace when
** the meeting point lies within eps_d of both lines: their crossing at a
** small angle is then placed along them by rounding alone, merge.c
** on_both_lines).  The collapse window is WK_REFINE_TIME_SLACK *
** eps_t and WK_REFINE_DIST_SLACK * eps_d * (1 + speed), as the wavefront's
** refine, plus WK_MONO_REFINE_AGE_REL times the vertex's age (time since its
** birth; times (1 + speed) for the distance): the drift of the
** extrapolation.  Both chosen on convex n = 2000 seeds 4 and 6, where they
** make the chain nodes the exact ones (checked in 60-digit arithmetic)
** while the reference wavefront's drift by 4e-7 of the scale (the variant's
** README.md, "The cliff"). */
#define WK_MONO_EXACT_SLACK 1e3
#define WK_MONO_REFINE_AGE_REL 1e-4
/* The merge walk (merge.c).  Two roof planes are one (coplanar edges: M'
** follows the vertex between them), or have no bisector, when their
** gradients n / w differ by at most WK_MONO_COPLANAR_REL * (1 / w_a + 1 / w_b)
** (in the L1 norm for the first test, the L2 norm for the second): the
** gradients are unit normals over weights, equal up to the rounding of the
** normals (~1e-16, up to 1e-12 rad for short edges turned in doubles far
** from the origin, README.md): 1e-12 allows that rounding and no more (the
** bar of WK_ANTIPARALLEL_SIN; WK_PARALLEL_SIN, 1e-9, would make the roofs
** of edges up to 1e-9 rad apart one plane). */
#define WK_MONO_COPLANAR_REL 1e-12
/* M''s ray runs along a wall trace (their unit directions' cross product is
** at most this) or, for a crossing, must leave the face by more than this:
** both unit vectors come from differences of constructed points, rounded to
** ~1e-16, and 1e-14 (100 times that) takes only the rounding as parallel;
** along a trace, the eps_d distance test then decides. */
#define WK_MONO_RAY_PARALLEL_SIN 1e-14
/* The merge walk asks whether two coplanar faces of different chains
** overlap next to a node where several traces meet (merge.c, overlap_at)
** by probing points WK_MONO_PROBE_REL * eps_d around it: far enough from
** the node that rounding (nodes within eps_d) cannot put a probe on the
** wrong side of a trace through it, near enough that no other trace lies
** between.  1e3 was too far: crosses 2 wide with a vertex at 1e7
** (eps_d 0.01, tests/fuzz/cross_far_vertex_sweep.py) were probed 10 units
** out, past their arms, and 7 of 59 survey mismatches stayed; at 16 one
** did. */
#define WK_MONO_PROBE_REL 16.0
/* A chain event's two remaining edges (chain_skeleton.c resolve) are facing
** walls that collide, as exactly antiparallel ones (WK_VEL_ANTIPARALLEL),
** when their unit normals' sine is at most this: turned in doubles, an
** edge's direction is rounded by ~1e-16 * |coordinates| / length, e.g.
** 2e-12 rad for a 17-long edge at 3e5 (random polygons sweepable along x, with
** vertical pairs turned by 0.3 rad: the walls met at sine 1.09e-12, above
** WK_ANTIPARALLEL_SIN, the vertex between them ran off along them at
** 1e12 times their speed, and the merge walk got lost: a fallback to the
** reference, > 600 s at n = 4e5).  The bar of WK_PARALLEL_SIN: the reference's
** own WK_ANTIPARALLEL_SIN stays tighter for its spikes (kinetics.c). */
#define WK_MONO_ANTIPARALLEL_SIN WK_PARALLEL_SIN
/* A wall is entered at the current level tau_p by binary search over its
** traces' times, with a window of WK_MONO_LEVEL_SLACK * eps_t +
** WK_MONO_LEVEL_REL * |tau_p|: levels are computed from points ((n . q -
** c) / w: rounding relative to tau_p, times the conditioning) and node times
** from events (within a few eps_t).  Loose on purpose: a wider window only
** costs a few more traces looked at, a narrower one would skip the trace the
** ray leaves through. */
#define WK_MONO_LEVEL_SLACK 1e3
#define WK_MONO_LEVEL_REL 1e-12

/* ------------------------------------------ a large group's point grid */

/* wavefront_group.c looks up a large group's nodes and vertices in a grid
** (point_grid.h) instead of scanning them, and must find every one its
** tests (a distance to a point or a band around a piece, in doubles) could
** accept.  So each query box is widened past those tests' reach by
** WK_GRID_WIDEN times the test's radius plus WK_GRID_ULPS ulps of the
** box's coordinates (the rounding of a difference of coordinates and of a
** dot product with a unit vector: a few ulps).  Not a tolerance of the
** skeleton: a wider box only lists a few more candidates, which the tests
** then reject, so the plan is the scan's, bit for bit. */
#define WK_GRID_WIDEN 1e-3
#define WK_GRID_ULPS 16.0

/* ----------------------------------------------------------- offsets */

/* wk_offset (offset.c) pairs the crossings of an offset line with a face's
** boundary along the line: sorted, they must alternate (entering, leaving).
** Where the sort does not alternate, a crossing within WK_OFFSET_TIE_REL *
** scale further along is taken first: two crossings that close are one
** point of the skeleton seen through two arcs (a node at time t, or nodes
** the skeleton placed within its own error), and their order is rounding.
** The validator's default tolerance: what the skeleton's nodes may be off
** by, and no farther: beyond it the sort is kept and the offset fails
** (WK_EALGO) rather than join crossings that are apart. */
#define WK_OFFSET_TIE_REL 1e-6

/* ------------------------------------------------------ the input domain */

/* A polygon is refused on input (polygon.c, check_width) when it may lie
** wholly within c = WK_POLYGON_MIN_WIDTH_REL * scale of its boundary: then
** every feature of it, the whole skeleton included, is below the
** simulation's tolerance, and the variants return skeletons of different
** topology that each pass the validator (fuzz findings in tests/data/fuzz:
** a 4-gon 4 wide and 2.4e11 long, eps_d = 243, where four variants gave
** three different skeletons, below_tolerance_thin_4gon_2e11.wpoly; a
** notched 12-gon of radius 1000 with one vertex at 2.2e13, eps_d = 2.2e4,
** where two variants differed,
** mismatch_deforming_notched_needle_2e13.wpoly).  The test: every point of a
** polygon whose largest inscribed circle has radius R lies within R of the
** boundary; its nearest boundary point is inside an edge (the point lies in
** the strip of width R over that edge on the inner side: area at most
** R * length) or a reflex vertex (the sector between the two edges'
** normals: area below pi/2 R^2), so A <= R P + pi/2 r R^2 (P the length of
** all rings, r the reflex vertices).  A < c P + pi/2 r c^2 is therefore
** necessary for R <= c: every polygon with R <= c is refused.  It is not
** sufficient: a thin triangle has R = 2A/P, twice the strip's A/P, and long
** needles (two edges closer than c) add perimeter and no area, so a polygon
** with R up to a few c can be refused.
** Why WK_TOL_REL, the nominal eps_d: with R <= eps_d no part of the polygon
** is above the tolerance of the first attempt of wk_solve_checked nor of any
** coarser retry (only its finer fallbacks, run when every coarser attempt
** failed, look below it); a bar at the coarsest retry (64 eps_d) would refuse
** polygons every variant resolves (R = 25 eps_d below).
** Measured as the mean width 2A / (P * scale) (the test for r = 0 is
** 2A / (P * scale) < 2e-9): the two findings above 2.1e-12 and 2.3e-11;
** the polygons of tests/data it refuses (14, fuzz findings of a part of
** size 1 to 1000 beside a vertex 5e8 to 2e13 away, and the degenerate
** reg64_far.wpoly, a unit 64-gon with a vertex 4e9 away: 2.5e-11) have an
** inscribed radius (the largest distance of a skeleton node from the
** boundary) of at most 6.4 eps_d, all at or below 1.5e-9; the smallest
** kept: 2.0e-9 (tests/data/fuzz/mismatch_monotone_long_collinear.wpoly, a
** triangle 1 high and 2.5e8 long, R = 2 eps_d, kept by 2e-9 of its area) and
** 4.7e-9 (tests/data/degenerate/deform_spike_tip_arrives.wpoly, a 33-gon of
** radius 100 with a vertex 4e9 away: R = 25 eps_d, which every variant
** resolves); the stress class regular_4e9 (6- to 64-gons of radius 1e-3
** to 1000, a vertex 4e9 away) refuses radius 1 and below (at most 2.2e-10)
** and keeps 100 and above (at least 2.4e-9, the 64-gon).  Far above:
** a road 1 m wide and 10 km long 1e-4, a spiral corridor 1e-5 of its size
** 7e-6, the bench generators' smallest at n = 10^5 2.9e-5 (star, comb,
** random; it falls as 1/n, to 6e-8 at the 5e7 vertices accepted). */
#define WK_POLYGON_MIN_WIDTH_REL WK_TOL_REL

#endif
