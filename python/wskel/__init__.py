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

__all__ = ["skeleton", "offset", "roof", "variants", "Skeleton", "Roof", "Error", "InputError",
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
