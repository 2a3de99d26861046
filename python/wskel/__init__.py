"""wskel: weighted straight skeletons, offsets and roofs from Python.

A thin ctypes binding of the C library (built by ``make python`` into
python/wskel/_libwskel.so, next to this file) through the flat interface of
python/wskel/shim.c.  Every call opens one run (wk_run), solves, copies the
results into numpy arrays and closes the run again; a run that does not
return to 0 tracked bytes raises LeakError.

Polygons
    outer: the outer ring, an (m, 2) array-like of points, either orientation.
    holes: a sequence of rings (each (m, 2), either orientation), each
           strictly inside outer and disjoint from the others.
    weights: None (every edge weight 1), or one weight per edge over all
           rings, either flat (outer's edges first, then each hole's, in the
           order given: edge i runs from point i to the next point of its
           ring) or as one sequence per ring ([outer_w, hole0_w, ...]).
    Points are numbered as given, over the rings concatenated: point i of
    hole h is vertex len(outer) + sum(len(holes[:h])) + i.

Results use that numbering (node i < n is input vertex i; arc faces and
roof faces are input edges), as the CLI's writers do.

PSLGs (planar straight-line graphs; README "PSLGs")
    pslg_skeleton, pslg_offset and pslg_roof take a graph instead:
    points: an (m, 2) array-like of nodes; edges: a (k, 2) array-like of
    node index pairs; weights: None (1) or one weight per edge.  Nodes and
    edges in a GraphML file's document order give the skeleton the CLI
    computes from that file (read_graphml reads one so).  A PSLG's
    skeleton is unbounded; it is computed up to a time horizon (until=T,
    or by default until every bounded wavefront has vanished, plus a
    margin).  Numbering as in the CLI's JSON: node i < n is corner i of the
    initial wavefront (a node of degree d is d corners, a terminal 2),
    edge i the piece from corner i to the next corner of its ring (a side
    of a segment, or a terminal's cap); corner_node and edge_of map them
    back to the graph (-1: a cap); arcs with left == -1 are the wavefront
    at the horizon.  Variants: naive (any weights) and motorcycle (equal
    weights); the others raise UnsupportedError.

Errors are subclasses of wskel.Error carrying .message, .input,
.input_line, .src_file, .src_line (where in wskel it was raised), .status
(the engine's status name) and .exit_code (the CLI's exit code for it):
    InputError (1)          invalid polygon (also a ValueError)
    AlgorithmError (2)      the variant could not handle the input; its
                            subclasses UnsupportedError (the variant does not
                            apply) and MemoryLimitError (out of memory)
    InvalidOutputError (3)  the validator rejected the skeleton
    UsageError (64)         bad arguments, e.g. an unknown variant
                            (also a ValueError)
    LeakError (2)           a run did not return to 0 tracked bytes
"""
import collections
import ctypes
import os

import numpy as np

__all__ = ["skeleton", "offset", "roof", "variants", "Skeleton", "Roof", "pslg_skeleton",
           "pslg_offset", "pslg_roof", "read_graphml", "PslgSkeleton", "PslgRoof", "Error",
           "InputError",
           "AlgorithmError", "UnsupportedError", "MemoryLimitError", "InvalidOutputError",
           "UsageError", "LeakError", "K_MAX", "run_stats"]

_HERE = os.path.dirname(os.path.abspath(__file__))
_LIB_PATH = os.path.join(_HERE, "_libwskel.so")
if not os.path.exists(_LIB_PATH):
    raise ImportError("wskel: %s not found: run `make python` in the wskel checkout" % _LIB_PATH)
_lib = ctypes.CDLL(_LIB_PATH)

K_MAX = 2 ** 32 - 2  # WK_K_MAX: a variant's cache holds everything (k="max")

_u32p = ctypes.POINTER(ctypes.c_uint32)
_f64p = ctypes.POINTER(ctypes.c_double)
_h = ctypes.c_void_p


def _sig(name, restype, *argtypes):
    f = getattr(_lib, name)
    f.restype = restype
    f.argtypes = list(argtypes)
    return f


_new = _sig("wks_new", _h)
_new_checked = _sig("wks_new_checked", _h, ctypes.c_uint64)
_alloc_requests = _sig("wks_alloc_requests", ctypes.c_uint64, _h)
_close = _sig("wks_close", ctypes.c_size_t, _h)
_c_solve = _sig("wks_solve", ctypes.c_int, _h, ctypes.c_uint32, _u32p, _f64p, _f64p, _f64p,
              ctypes.c_char_p, ctypes.c_char_p, ctypes.c_uint32, ctypes.c_int, ctypes.c_int)
_n_input = _sig("wks_n_input", ctypes.c_uint32, _h)
_n_nodes = _sig("wks_n_nodes", ctypes.c_uint32, _h)
_n_arcs = _sig("wks_n_arcs", ctypes.c_uint32, _h)
_time_s = _sig("wks_time_s", ctypes.c_double, _h)
_peak_bytes = _sig("wks_peak_bytes", ctypes.c_size_t, _h)
_nodes = _sig("wks_nodes", None, _h, _f64p)
_arcs = _sig("wks_arcs", None, _h, _u32p)
_n_counters = _sig("wks_n_counters", ctypes.c_uint32, _h)
_counter_name = _sig("wks_counter_name", ctypes.c_char_p, _h, ctypes.c_uint32)
_counter_value = _sig("wks_counter_value", ctypes.c_uint64, _h, ctypes.c_uint32)
_c_offset = _sig("wks_offset", ctypes.c_int, _h, ctypes.c_double)
_offset_sizes = _sig("wks_offset_sizes", None, _h, _u32p, _u32p, _u32p)
_offset_copy = _sig("wks_offset_copy", None, _h, _u32p, _u32p, _f64p)
_c_roof = _sig("wks_roof", ctypes.c_int, _h)
_roof_size = _sig("wks_roof_size", ctypes.c_uint32, _h)
_roof_copy = _sig("wks_roof_copy", None, _h, _u32p, _u32p)
_roof_faces = _sig("wks_roof_faces", ctypes.c_uint32, _h)
_c_solve_pslg = _sig("wks_solve_pslg", ctypes.c_int, _h, ctypes.c_uint32, _f64p, _f64p,
                     ctypes.c_uint32, _u32p, _u32p, _f64p, ctypes.c_char_p, ctypes.c_char_p,
                     ctypes.c_double, ctypes.c_int, ctypes.c_int)
_pslg_sizes = _sig("wks_pslg_sizes", None, _h, _f64p, _u32p, _u32p, _u32p)
_pslg_copy = _sig("wks_pslg_copy", None, _h, _u32p, _u32p, _u32p)
_err_status = _sig("wks_error_status", ctypes.c_int, _h)
_err_status_name = _sig("wks_error_status_name", ctypes.c_char_p, _h)
_err_exit = _sig("wks_error_exit_code", ctypes.c_int, _h)
_err_msg = _sig("wks_error_message", ctypes.c_char_p, _h)
_err_input = _sig("wks_error_input", ctypes.c_char_p, _h)
_err_input_line = _sig("wks_error_input_line", ctypes.c_long, _h)
_err_src_file = _sig("wks_error_src_file", ctypes.c_char_p, _h)
_err_src_line = _sig("wks_error_src_line", ctypes.c_int, _h)


# ------------------------------------------------------------------ errors

class Error(Exception):
    """A wskel failure: message, where (input, input_line; src_file,
    src_line in wskel), status name and the CLI's exit code."""
    exit_code = 2

    def __init__(self, message, input="", input_line=0, src_file="", src_line=0,
                 status="", exit_code=None):
        self.message = message
        self.input = input
        self.input_line = input_line
        self.src_file = src_file
        self.src_line = src_line
        self.status = status
        if exit_code is not None:
            self.exit_code = exit_code
        where = input + (":%d" % input_line if input_line else "")
        # Errors found by the binding itself (argument shapes) have no place in wskel's C.
        origin = ", raised at %s:%d" % (src_file, src_line) if src_file else ""
        super().__init__("%s%s (%s%s)" % (where + ": " if where else "", message, status, origin))


class InputError(Error, ValueError):
    """Invalid input polygon (CLI exit 1)."""
    exit_code = 1


class AlgorithmError(Error):
    """The variant could not handle the input (CLI exit 2)."""
    exit_code = 2


class UnsupportedError(AlgorithmError):
    """The variant does not apply to this kind of polygon (exit 2)."""


class MemoryLimitError(AlgorithmError, MemoryError):
    """An allocation failed (exit 2)."""


class InvalidOutputError(Error):
    """The validator rejected the skeleton (CLI exit 3)."""
    exit_code = 3


class UsageError(Error, ValueError):
    """Bad arguments, e.g. an unknown variant (CLI exit 64)."""
    exit_code = 64


class LeakError(Error):
    """A run closed with tracked bytes still live (a bug in wskel)."""
    exit_code = 2


# By wk_status (engine/wskel.h): WK_EINPUT 1, WK_ENOMEM 2, WK_EALGO 3,
# WK_EUNSUPPORTED 4, WK_EINVALID 5, WK_EUSAGE 6.
_BY_STATUS = {1: InputError, 2: MemoryLimitError, 3: AlgorithmError, 4: UnsupportedError,
              5: InvalidOutputError, 6: UsageError}


def _raise(h):
    name = _err_status_name(h).decode()
    cls = _BY_STATUS.get(_err_status(h), AlgorithmError)
    raise cls(_err_msg(h).decode(errors="replace"), _err_input(h).decode(errors="replace"),
              int(_err_input_line(h)), _err_src_file(h).decode(), int(_err_src_line(h)), name,
              int(_err_exit(h)))


# -------------------------------------------------------------- the runs

# Counts over this process: runs closed, the tracked bytes they left live
# (each must be 0; a nonzero one also raised LeakError), and the allocation
# requests of the last checked run.
_stats = {"runs": 0, "leaked_bytes": 0, "last_alloc_requests": 0}

# For tests (tests/test_python.py), not for use: while "checked" is true,
# runs use the debug allocator backend (every free's size checked, guard
# bytes), and with "fail_at" = N > 0 its N-th allocation request fails.
_test_alloc = {"checked": os.environ.get("WSKEL_CHECKED_RUNS") == "1", "fail_at": 0}


def run_stats():
    """{"runs": runs closed so far, "leaked_bytes": tracked bytes they left,
    "last_alloc_requests": allocation requests of the last checked run}."""
    return dict(_stats)


class _Run:
    """One handle (one wk_run); closes it and checks the byte count."""

    def __enter__(self):
        if _test_alloc["checked"] or _test_alloc["fail_at"]:
            self.h = _new_checked(_test_alloc["fail_at"])
            self.checked = True
        else:
            self.h = _new()
            self.checked = False
        if not self.h:
            raise MemoryLimitError("could not allocate a run handle", status="memory")
        return self.h

    def __exit__(self, exc_type, exc, tb):
        if self.checked:
            _stats["last_alloc_requests"] = int(_alloc_requests(self.h))
        live = _close(self.h)
        _stats["runs"] += 1
        _stats["leaked_bytes"] += live
        if live and exc_type is None:
            raise LeakError("run closed with %d tracked bytes live" % live, status="leak")
        return False


def _ring(a, what):
    r = np.ascontiguousarray(np.asarray(a, dtype=np.float64))
    if r.ndim != 2 or r.shape[1] != 2:
        raise InputError("%s must be an (m, 2) array of points (got shape %s)"
                         % (what, r.shape), status="input")
    if r.shape[0] < 3:
        raise InputError("%s has %d points, a ring needs at least 3" % (what, r.shape[0]),
                         status="input")
    return r


def _weights(weights, sizes):
    if weights is None:
        return None
    n = sum(sizes)
    try:
        flat = np.asarray(weights, dtype=np.float64)
    except (ValueError, TypeError):
        flat = None  # ragged: one sequence per ring
    if flat is None or flat.ndim != 1:
        parts = list(weights)
        if len(parts) != len(sizes):
            raise InputError("weights per ring: %d sequences for %d rings"
                             % (len(parts), len(sizes)), status="input")
        for i, (p, m) in enumerate(zip(parts, sizes)):
            if len(p) != m:
                raise InputError("weights of ring %d: %d values for %d edges" % (i, len(p), m),
                                 status="input")
        flat = np.concatenate([np.asarray(p, dtype=np.float64) for p in parts])
    if flat.shape != (n,):
        raise InputError("weights: %d values for %d edges" % (flat.size, n), status="input")
    return np.ascontiguousarray(flat)


def _k_arg(k):
    if isinstance(k, str) and k == "max":
        return K_MAX
    if not isinstance(k, (int, np.integer)) or k < 1 or k >= K_MAX:
        raise UsageError("k must be a positive integer or 'max' (got %r)" % (k,), status="usage")
    return int(k)


def _solve(h, outer, holes, weights, variant, k, check, name):
    rings = [_ring(outer, "outer")] + [_ring(r, "hole %d" % i) for i, r in enumerate(holes)]
    sizes = [len(r) for r in rings]
    w = _weights(weights, sizes)
    xy = np.concatenate(rings)
    x = np.ascontiguousarray(xy[:, 0])
    y = np.ascontiguousarray(xy[:, 1])
    rs = np.asarray(sizes, dtype=np.uint32)
    st = _c_solve(h, len(rings), rs.ctypes.data_as(_u32p), x.ctypes.data_as(_f64p),
                y.ctypes.data_as(_f64p), w.ctypes.data_as(_f64p) if w is not None else None,
                name.encode(), str(variant).encode(), _k_arg(k), 1, 1 if check else 0)
    if st != 0:
        _raise(h)


Skeleton = collections.namedtuple("Skeleton", "nodes arcs counters n time_s peak_bytes")
Skeleton.__doc__ = """A straight skeleton.
nodes: structured array (x, y, t), the first n the input vertices (t = 0);
arcs: structured array (a, b, left, right): node a to node b, the faces of
    input edges left and right of a->b;
counters: {name: count} of the variant's counters;
n: input vertices; time_s: construction time; peak_bytes: its peak tracked bytes."""

NODE_DTYPE = np.dtype([("x", np.float64), ("y", np.float64), ("t", np.float64)])
ARC_DTYPE = np.dtype([("a", np.uint32), ("b", np.uint32), ("left", np.uint32),
                      ("right", np.uint32)])


def _read_skeleton(h):
    nn, na = _n_nodes(h), _n_arcs(h)
    nodes = np.zeros(nn, dtype=NODE_DTYPE)
    arcs = np.zeros(na, dtype=ARC_DTYPE)
    if nn:
        _nodes(h, nodes.ctypes.data_as(_f64p))
    if na:
        _arcs(h, arcs.ctypes.data_as(_u32p))
    counters = {_counter_name(h, i).decode(): int(_counter_value(h, i))
                for i in range(_n_counters(h))}
    return Skeleton(nodes, arcs, counters, int(_n_input(h)), float(_time_s(h)),
                    int(_peak_bytes(h)))


def skeleton(outer, holes=(), weights=None, variant="naive", k=1, check=True, name="<python>"):
    """The weighted straight skeleton of the polygon (see the module doc for
    outer, holes, weights).  variant: a registered variant (variants());
    k: its cache size where it has one (an int >= 1 or "max"); check:
    validate the skeleton (as the CLI does by default; on failure the
    engine retries with coarser tolerances, else InvalidOutputError);
    name: the input's name in error messages.  Returns a Skeleton."""
    with _Run() as h:
        _solve(h, outer, holes, weights, variant, k, check, name)
        return _read_skeleton(h)


def _read_offset(h):
    n_pol, n_ring, n_pt = ctypes.c_uint32(), ctypes.c_uint32(), ctypes.c_uint32()
    _offset_sizes(h, ctypes.byref(n_pol), ctypes.byref(n_ring), ctypes.byref(n_pt))
    ps = np.zeros(n_pol.value + 1, dtype=np.uint32)
    rs = np.zeros(n_ring.value + 1, dtype=np.uint32)
    xy = np.zeros((n_pt.value, 2), dtype=np.float64)
    _offset_copy(h, ps.ctypes.data_as(_u32p), rs.ctypes.data_as(_u32p), xy.ctypes.data_as(_f64p))
    return [[xy[rs[j]:rs[j + 1]].copy() for j in range(ps[i], ps[i + 1])]
            for i in range(n_pol.value)]


def offset(outer, holes=(), weights=None, t=1.0, variant="naive", k=1, check=True,
           name="<python>"):
    """The wavefront (offset polygons) at time t, computed from the skeleton
    (for unit weights t is the inward distance).  t: a number, or a sequence
    of numbers (one skeleton for all).  For one t: a list of polygons, each a
    list of rings as (m, 2) arrays, its outer ring counter-clockwise first,
    then its holes clockwise (rings not closed); empty once the polygon has
    collapsed.  For a sequence: a list of those, one per t."""
    times = np.atleast_1d(np.asarray(t, dtype=np.float64))
    if times.ndim != 1:
        raise UsageError("t must be a number or a sequence of numbers", status="usage")
    with _Run() as h:
        _solve(h, outer, holes, weights, variant, k, check, name)
        out = []
        for ti in times:
            if _c_offset(h, float(ti)) != 0:
                _raise(h)
            out.append(_read_offset(h))
    return out if np.ndim(t) else out[0]


Roof = collections.namedtuple("Roof", "vertices faces")
Roof.__doc__ = """The roof over a polygon: vertices an (N, 3) array (x, y, z = t),
the skeleton's nodes; faces a list, face i (of input edge i) an array of
vertex ids around it, starting with the edge's two endpoints."""


def roof(outer, holes=(), weights=None, variant="naive", k=1, check=True, name="<python>"):
    """The roof (the skeleton lifted by t) as a mesh: one face per input edge,
    from the engine's face cycles (wk_face_cycle).  Returns a Roof."""
    with _Run() as h:
        _solve(h, outer, holes, weights, variant, k, check, name)
        if _c_roof(h) != 0:
            _raise(h)
        sk = _read_skeleton(h)
        n = sk.n
        assert _roof_faces(h) == n
        starts = np.zeros(n + 1, dtype=np.uint32)
        ids = np.zeros(_roof_size(h), dtype=np.uint32)
        _roof_copy(h, starts.ctypes.data_as(_u32p), ids.ctypes.data_as(_u32p))
    verts = np.column_stack([sk.nodes["x"], sk.nodes["y"], sk.nodes["t"]])
    return Roof(verts, [ids[starts[i]:starts[i + 1]].copy() for i in range(n)])


def variants():
    """The registered variants' names (as `bin/wskel --list-variants`)."""
    names = []
    f = _sig("wk_variant_at", ctypes.c_void_p, ctypes.c_size_t)
    nm = _sig("wk_variant_name", ctypes.c_char_p, ctypes.c_void_p)
    i = 0
    while True:
        v = f(i)
        if not v:
            return names
        names.append(nm(v).decode())
        i += 1


# ------------------------------------------------------------------ PSLGs

_NONE = 2 ** 32 - 1  # WK_NONE: the cap's side of an arc, a cap's graph edge


def _pslg_arrays(points, edges, weights):
    p = np.ascontiguousarray(np.asarray(points, dtype=np.float64))
    if p.ndim != 2 or p.shape[1] != 2:
        raise InputError("points must be an (m, 2) array of nodes (got shape %s)" % (p.shape,),
                         status="input")
    try:
        e = np.asarray(edges)
    except ValueError:
        e = None  # ragged
    if e is None or e.ndim != 2 or e.shape[1] != 2 or (e.size and e.dtype.kind not in "iu"):
        raise InputError("edges must be a (k, 2) array of integer node indices (got %s)"
                         % ("shape %s dtype %s" % (e.shape, e.dtype) if e is not None
                            else "a ragged sequence"), status="input")
    if e.size and (e.min() < 0 or e.max() >= len(p)):
        bad = int(np.nonzero((e < 0).any(axis=1) | (e >= len(p)).any(axis=1))[0][0])
        raise InputError("edge %d: node index out of range (%d, %d) for %d points"
                         % (bad, e[bad][0], e[bad][1], len(p)), status="input")
    src = np.ascontiguousarray(e[:, 0], dtype=np.uint32) if e.size else np.zeros(0, np.uint32)
    dst = np.ascontiguousarray(e[:, 1], dtype=np.uint32) if e.size else np.zeros(0, np.uint32)
    w = None
    if weights is not None:
        w = np.ascontiguousarray(np.asarray(weights, dtype=np.float64))
        if w.shape != (len(src),):
            raise InputError("weights: %s values for %d edges (one weight per edge)"
                             % (w.size if w.ndim == 1 else "shape %s" % (w.shape,), len(src)),
                             status="input")
    return p, src, dst, w


def _until_arg(until):
    if until is None:
        return 0.0
    try:
        u = float(until)
    except (TypeError, ValueError):
        u = float("nan")
    if not (u > 0) or u == float("inf"):
        raise UsageError("until must be a positive number or None (got %r)" % (until,),
                         status="usage")
    return u


def _solve_pslg(h, points, edges, weights, until, variant, check, name):
    p, src, dst, w = _pslg_arrays(points, edges, weights)
    x = np.ascontiguousarray(p[:, 0])
    y = np.ascontiguousarray(p[:, 1])
    st = _c_solve_pslg(h, len(p), x.ctypes.data_as(_f64p), y.ctypes.data_as(_f64p), len(src),
                       src.ctypes.data_as(_u32p), dst.ctypes.data_as(_u32p),
                       w.ctypes.data_as(_f64p) if w is not None else None, name.encode(),
                       str(variant).encode(), until, 1, 1 if check else 0)
    if st != 0:
        _raise(h)


PslgSkeleton = collections.namedtuple(
    "PslgSkeleton", "nodes arcs counters n time_s peak_bytes horizon rings corner_node edge_of")
PslgSkeleton.__doc__ = """The straight skeleton of a PSLG up to its horizon.
nodes: structured array (x, y, t), the first n the corners of the initial
    wavefront (t = 0), the last ones at t = horizon;
arcs: structured array (a, b, left, right), left and right int64 stored
    edges (-1: the cap, the wavefront at the horizon, on the left);
counters, n, time_s, peak_bytes: as in Skeleton;
horizon: the time T the skeleton is computed up to;
rings: the face cycles' sizes (corners in order, as the JSON's "rings");
corner_node: the graph node of each corner (int64, n values);
edge_of: the graph edge of each stored edge (int64, -1 for a terminal's cap)."""

PSLG_ARC_DTYPE = np.dtype([("a", np.uint32), ("b", np.uint32), ("left", np.int64),
                           ("right", np.int64)])


def _read_pslg_skeleton(h):
    sk = _read_skeleton(h)
    arcs = np.zeros(len(sk.arcs), dtype=PSLG_ARC_DTYPE)
    for f in ("a", "b"):
        arcs[f] = sk.arcs[f]
    for f in ("left", "right"):
        side = sk.arcs[f].astype(np.int64)
        side[sk.arcs[f] == _NONE] = -1
        arcs[f] = side
    horizon = ctypes.c_double()
    n_rings, gv, ge = ctypes.c_uint32(), ctypes.c_uint32(), ctypes.c_uint32()
    _pslg_sizes(h, ctypes.byref(horizon), ctypes.byref(n_rings), ctypes.byref(gv), ctypes.byref(ge))
    rings = np.zeros(n_rings.value, dtype=np.uint32)
    corner = np.zeros(sk.n, dtype=np.uint32)
    edge_of = np.zeros(sk.n, dtype=np.uint32)
    _pslg_copy(h, rings.ctypes.data_as(_u32p), corner.ctypes.data_as(_u32p),
               edge_of.ctypes.data_as(_u32p))
    eo = edge_of.astype(np.int64)
    eo[edge_of == _NONE] = -1
    return PslgSkeleton(sk.nodes, arcs, sk.counters, sk.n, sk.time_s, sk.peak_bytes,
                        float(horizon.value), rings.astype(np.int64), corner.astype(np.int64), eo)


def pslg_skeleton(points, edges, weights=None, until=None, variant="naive", check=True,
                  name="<python>"):
    """The weighted straight skeleton of a PSLG (see the module doc for
    points, edges, weights and the numbering) up to the horizon until (a
    positive time; None: the default horizon, by which every bounded
    wavefront has vanished).  variant: naive (the reference, any weights)
    or motorcycle (equal weights; it may hand an input to naive, counted
    in counters["reference_fallbacks"]); other variants raise
    UnsupportedError.  check: validate with the PSLG validator (retrying
    at coarser tolerances; else InvalidOutputError).  Invalid graphs
    (crossing or touching edges, duplicate points or edges, isolated
    nodes, edges closer than 1e-7 diagonals, ...) raise InputError naming
    the edge or node (0-based).  Returns a PslgSkeleton."""
    with _Run() as h:
        _solve_pslg(h, points, edges, weights, _until_arg(until), variant, check, name)
        return _read_pslg_skeleton(h)


def pslg_offset(points, edges, weights=None, t=1.0, until=None, variant="naive", check=True,
                name="<python>"):
    """The region a PSLG's wavefront has swept by time t (a weighted buffer
    of the graph): one polygon around each connected component, its outer
    ring the wavefront (counter-clockwise), holes (clockwise) where a
    bounded face's wavefront is still closed; t = 0 gives no polygon.  t: a
    number or a sequence (one skeleton for all), as in offset().  Without
    until, a t past the default horizon makes the skeleton be followed up
    to the largest t instead (as the CLI's --offset); a t past a given
    until raises UnsupportedError (the skeleton is not known there)."""
    times = np.atleast_1d(np.asarray(t, dtype=np.float64))
    if times.ndim != 1:
        raise UsageError("t must be a number or a sequence of numbers", status="usage")
    u = _until_arg(until)
    latest = float(times.max()) if times.size else 0.0
    for attempt in (0, 1):
        with _Run() as h:
            _solve_pslg(h, points, edges, weights, u, variant, check, name)
            horizon = ctypes.c_double()
            z = ctypes.c_uint32()
            _pslg_sizes(h, ctypes.byref(horizon), ctypes.byref(z), ctypes.byref(z),
                        ctypes.byref(z))
            if latest > horizon.value and until is None and attempt == 0:
                u = latest  # past the default horizon: follow it up to the latest t
                continue
            out = []
            for ti in times:
                if until is not None and ti > u:
                    raise UnsupportedError(
                        "offset time %g is beyond the horizon until=%g up to which the PSLG's "
                        "skeleton is computed: raise until or leave it out" % (ti, u),
                        name, status="unsupported")
                if _c_offset(h, float(ti)) != 0:
                    _raise(h)
                out.append(_read_offset(h))
            break
    return out if np.ndim(t) else out[0]


PslgRoof = collections.namedtuple("PslgRoof", "vertices faces n_edge_faces horizon")
PslgRoof.__doc__ = """The roof over the region a PSLG's wavefront has swept by its horizon
T, as the CLI's OBJ: vertices an (N, 3) array (x, y, z = t), the skeleton's
nodes; faces[i] for i < n_edge_faces the face of stored edge i (a side of a
segment, or a cap) on its edge's plane, the later ones at z = T closing the
bounded faces whose wavefront is still alive at T (counter-clockwise); each
face an array of vertex ids (a face with an island is one weakly simple
cycle, the island bridged in)."""


def pslg_roof(points, edges, weights=None, until=None, variant="naive", check=True,
              name="<python>"):
    """The roof of a PSLG's skeleton up to its horizon (see PslgRoof).  A
    bounded face's wavefront that still encloses another component at the
    horizon gives a cap face with that component's wavefront bridged in as
    a hole (one weakly simple cycle, as the CLI's OBJ)."""
    with _Run() as h:
        _solve_pslg(h, points, edges, weights, _until_arg(until), variant, check, name)
        if _c_roof(h) != 0:
            _raise(h)
        sk = _read_pslg_skeleton(h)
        nf = _roof_faces(h)
        starts = np.zeros(nf + 1, dtype=np.uint32)
        ids = np.zeros(_roof_size(h), dtype=np.uint32)
        _roof_copy(h, starts.ctypes.data_as(_u32p), ids.ctypes.data_as(_u32p))
    verts = np.column_stack([sk.nodes["x"], sk.nodes["y"], sk.nodes["t"]])
    return PslgRoof(verts, [ids[starts[i]:starts[i + 1]].copy() for i in range(nf)], sk.n,
                    sk.horizon)


def read_graphml(path):
    """A GraphML graph as (points, edges, weights) for pslg_skeleton: nodes
    with the data keys named vertex-coordinate-x and vertex-coordinate-y,
    edges with edge-weight (its key's default, else 1), both in document
    order, edges as node index pairs.  A plain reader for the Salzburg /
    surfer2 layout (README "Input formats"); the C reader's checks (valid
    numbers aside) happen in pslg_skeleton.  Raises InputError naming the
    file on a missing key, node or coordinate."""
    import xml.etree.ElementTree as ET
    try:
        root = ET.parse(path).getroot()
    except (ET.ParseError, OSError) as ex:
        raise InputError("cannot read GraphML: %s" % ex, str(path), status="input")

    def local(tag):
        return tag.rsplit("}", 1)[-1]
    keys, default_w = {}, 1.0
    for k in root.iter():
        if local(k.tag) == "key":
            keys[k.get("id")] = k.get("attr.name")
            if k.get("attr.name") == "edge-weight":
                for d in k:
                    if local(d.tag) == "default" and (d.text or "").strip():
                        default_w = float(d.text)
    ids, pts, edges, weights = {}, [], [], []

    def data(el):
        return {keys.get(d.get("key")): (d.text or "").strip() for d in el
                if local(d.tag) == "data"}
    for el in root.iter():
        if local(el.tag) == "node":
            d = data(el)
            try:
                pts.append((float(d["vertex-coordinate-x"]), float(d["vertex-coordinate-y"])))
            except (KeyError, ValueError):
                raise InputError("node %r: no valid vertex-coordinate-x/y" % el.get("id"),
                                 str(path), status="input")
            ids[el.get("id")] = len(pts) - 1
    for el in root.iter():
        if local(el.tag) == "edge":
            a, b = el.get("source"), el.get("target")
            if a not in ids or b not in ids:
                raise InputError("edge %d: unknown node %r" % (len(edges), a if a not in ids else b),
                                 str(path), status="input")
            edges.append((ids[a], ids[b]))
            w = data(el).get("edge-weight")
            weights.append(float(w) if w else default_w)
    return (np.array(pts, dtype=np.float64).reshape(-1, 2),
            np.array(edges, dtype=np.int64).reshape(-1, 2), np.array(weights, dtype=np.float64))
