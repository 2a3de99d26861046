/*
** wskel_cgal.cpp: the CGAL baseline, bin/wskel-cgal.
**
** Reads a unit-weight .wpoly polygon, possibly with holes (further rings after
** the first, each its own count line and vertex lines; the first ring is the
** outer boundary; any ring in either orientation), builds its interior
** straight skeleton with CGAL::create_interior_straight_skeleton_2
** (Exact_predicates_inexact_constructions_kernel; the outer contour
** counter-clockwise, the holes clockwise) and writes it in the wskel JSON
** contract ("format":"wskel-1", with "rings"), so scripts/compare_skeletons.py can hold wskel's
** variants against it and the benchmarks can quote CGAL's time and memory.
**
** What it is not: part of the library.  It links only CGAL, GMP and MPFR, so
** it builds (and tests/test_cgal_agreement.py runs) independently of the C
** code, and it does no weighted skeletons: CGAL has no weights, so any weight
** other than 1 is refused.
**
** Numbering (the contract's, see engine/wskel.h):
**   - nodes[0..n) are the input vertices in input line order over all rings
**     (file order) at t = 0, even when a ring was handed to CGAL reversed;
**   - the other nodes are CGAL's skeleton vertices in CGAL's order, t = time();
**   - edge i runs from input vertex i to the next input vertex of its ring
**     (next(i) = i+1, or the ring's first vertex after its last); a face is
**     named by its edge.  CGAL's face f is bounded by the contour halfedge
**     f->halfedge() (the face lies on its left, i.e. inside the polygon); its
**     two endpoints are input vertices a and b, and the edge joining them is
**     a if b == next(a) (the ring was given in CGAL's orientation), or b if
**     a == next(b) (the reversed copy).  Deriving the id from the
**     endpoints, not from CGAL's vertex ids, keeps this right however CGAL
**     numbers its contour.
**   - one arc per pair of opposite bisector halfedges, [a, b, left, right]:
**     a is the endpoint with the smaller time (ties: smaller node id), left is
**     the face on the left of a->b (CGAL keeps a halfedge's face on its left),
**     right the face of the opposite halfedge.  Contour halfedges are skipped.
**
** Exit codes follow the wskel CLI: 0 ok, 1 bad input, 2 CGAL failed, 64 usage.
*/
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_2.h>
#include <CGAL/create_straight_skeleton_2.h>
#include <CGAL/Polygon_with_holes_2.h>
#include <CGAL/create_offset_polygons_2.h>
#include <CGAL/arrange_offset_polygons_2.h>

#include <sys/resource.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <sys/stat.h>
#include <unistd.h>
#include <cstdlib>
#include <cstring>
#include <map>
#include <string>
#include <utility>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_2 Point;
typedef CGAL::Polygon_2<K> Polygon;
typedef CGAL::Straight_skeleton_2<K> Ss;
typedef CGAL::Polygon_with_holes_2<K> Pwh;

static const uint32_t NONE = UINT32_MAX;

enum { EXIT_INPUT = 1, EXIT_ALGO = 2, EXIT_USAGE = 64 };

/* Failures carry a message and the exit code; main prints and exits. */
struct Failure {
    int code;
    std::string msg;
};

static Failure fail(int code, const std::string &msg) { return Failure{code, msg}; }

/* ----------------------------------------------------------------- input */

struct Input {
    std::vector<double> x, y;       /* in input line order, over all rings */
    std::vector<uint32_t> ring_start; /* ring k is [ring_start[k], ring_start[k+1]) */
    uint32_t rings() const { return (uint32_t)ring_start.size() - 1; }
    uint32_t next(uint32_t i) const {
        size_t k = ring_of(i);
        return i + 1 == ring_start[k + 1] ? ring_start[k] : i + 1;
    }
    size_t ring_of(uint32_t i) const {
        size_t lo = 0, hi = ring_start.size() - 1; /* ring_start[lo] <= i < ring_start[hi] */
        while (hi - lo > 1) {
            size_t mid = (lo + hi) / 2;
            if (ring_start[mid] <= i) lo = mid;
            else hi = mid;
        }
        return lo;
    }
};

/* Trim leading blanks; true if the line carries data (not blank, not '#'). */
static bool data_line(const char *s) {
    while (*s == ' ' || *s == '\t' || *s == '\r' || *s == '\n') s++;
    return *s != '\0' && *s != '#';
}

static std::string where(const std::string &name, long line) {
    return name + ":" + std::to_string(line) + ": ";
}

/* Parse one finite double at *s, advancing it; false on junk. */
static bool parse_double(const char **s, double *out) {
    char *end;
    errno = 0;
    double v = std::strtod(*s, &end);
    if (end == *s || errno == ERANGE || !std::isfinite(v)) return false;
    *s = end;
    *out = v;
    return true;
}

static bool only_blanks(const char *s) {
    while (*s == ' ' || *s == '\t' || *s == '\r' || *s == '\n') s++;
    return *s == '\0';
}

/* Read the .wpoly file at path ("-": stdin).  Returns a Failure with code 0
** on success. */
static Failure read_wpoly(const std::string &path, Input *in) {
    FILE *f = path == "-" ? stdin : std::fopen(path.c_str(), "r");
    if (!f) return fail(EXIT_INPUT, path + ": cannot open: " + std::strerror(errno));
    std::string line;
    long lineno = 0;
    long m = -1;      /* the current ring's vertex count; -1 before the first */
    size_t got = 0;   /* vertices of the current ring so far */
    Failure res{0, ""};
    char buf[4096];
    /* Lines longer than buf are glued back together before parsing. */
    auto next_line = [&](std::string *out) -> bool {
        out->clear();
        while (std::fgets(buf, sizeof buf, f)) {
            out->append(buf);
            if (!out->empty() && out->back() == '\n') break;
        }
        if (out->empty()) return false;
        lineno++;
        return true;
    };
    in->ring_start.assign(1, 0);
    while (next_line(&line)) {
        if (!data_line(line.c_str())) continue;
        const char *s = line.c_str();
        if (m < 0 || (long)got == m) {
            /* a count line: the outer ring's or a hole's */
            char *end;
            errno = 0;
            long v = std::strtol(s, &end, 10);
            if (end == s || !only_blanks(end) || errno == ERANGE) {
                res = fail(EXIT_INPUT, where(path, lineno) +
                                           (m < 0 ? "expected the vertex count"
                                                  : "more than " + std::to_string(m) +
                                                        " vertices (a hole starts with its own "
                                                        "count line)"));
                break;
            }
            if (v < 3 || v > 100000000L || (long)in->x.size() + v > 100000000L) {
                res = fail(EXIT_INPUT, where(path, lineno) +
                                           (m < 0 ? "vertex count" : "vertex count of a hole") +
                                           " must be in [3, 1e8] (got " + std::to_string(v) + ")");
                break;
            }
            if (m >= 0) in->ring_start.push_back((uint32_t)in->x.size());
            m = v;
            got = 0;
            in->x.reserve(in->x.size() + (size_t)m);
            in->y.reserve(in->y.size() + (size_t)m);
            continue;
        }
        double x, y, w = 1.0;
        if (!parse_double(&s, &x) || !parse_double(&s, &y)) {
            res = fail(EXIT_INPUT, where(path, lineno) + "expected \"x y [w]\" with finite numbers");
            break;
        }
        if (!only_blanks(s) && (!parse_double(&s, &w) || !only_blanks(s))) {
            res = fail(EXIT_INPUT, where(path, lineno) + "expected \"x y [w]\" with finite numbers");
            break;
        }
        if (w != 1.0) {
            res = fail(EXIT_INPUT, "wskel-cgal: " + path + ": CGAL baseline supports unit weights only");
            break;
        }
        in->x.push_back(x);
        in->y.push_back(y);
        got++;
    }
    if (f != stdin) std::fclose(f);
    if (res.code) return res;
    if (m < 0) return fail(EXIT_INPUT, path + ": no vertex count (empty file?)");
    if ((long)got != m)
        return fail(EXIT_INPUT, where(path, lineno) + "expected " + std::to_string(m) +
                                    " vertices, found " + std::to_string(got));
    in->ring_start.push_back((uint32_t)in->x.size());
    return res;
}

/* ---------------------------------------------------------------- output */

struct Node {
    double x, y, t;
};
struct Arc {
    uint32_t a, b, left, right;
};

static void put_double(FILE *f, double v) {
    /* %.17g round-trips; JSON has no inf/nan, and none can reach here. */
    std::fprintf(f, "%.17g", v);
}

static void write_json(FILE *f, const Input &in, uint32_t r, const std::vector<Node> &nodes,
                       const std::vector<Arc> &arcs, double time_s, long peak_rss) {
    std::fprintf(f, "{\"format\":\"wskel-1\",\"variant\":\"cgal\",\"k\":null,\"n\":%zu,\"r\":%u,",
                 in.x.size(), r);
    std::fprintf(f, "\"rings\":[");
    for (uint32_t k = 0; k < in.rings(); k++)
        std::fprintf(f, "%s%u", k ? "," : "", in.ring_start[k + 1] - in.ring_start[k]);
    std::fprintf(f, "],\n");
    std::fprintf(f, "\"nodes\":[");
    for (size_t i = 0; i < nodes.size(); i++) {
        std::fputs(i ? ",\n[" : "\n[", f);
        put_double(f, nodes[i].x);
        std::fputc(',', f);
        put_double(f, nodes[i].y);
        std::fputc(',', f);
        put_double(f, nodes[i].t);
        std::fputc(']', f);
    }
    std::fprintf(f, "],\n\"arcs\":[");
    for (size_t i = 0; i < arcs.size(); i++)
        std::fprintf(f, "%s[%u,%u,%u,%u]", i ? ",\n" : "\n", arcs[i].a, arcs[i].b, arcs[i].left,
                     arcs[i].right);
    std::fprintf(f, "],\n\"stats\":{\"time_s\":");
    put_double(f, time_s);
    std::fprintf(f, ",\"peak_bytes\":null,\"peak_rss_bytes\":%ld}}\n", peak_rss);
}

/* ------------------------------------------------------------- skeleton */

struct Result {
    uint32_t r = 0;
    std::vector<Node> nodes;
    std::vector<Arc> arcs;
    double time_s = 0;
    std::vector<std::string> offset_wkt; /* --offset: one MULTIPOLYGON line per time */
};

/* One ring as WKT, closed. */
static void put_ring(std::string &s, const Polygon &p) {
    char buf[80];
    s += "(";
    for (size_t i = 0; i <= p.size(); i++) {
        const Point &q = p[i % p.size()];
        std::snprintf(buf, sizeof buf, "%s%.17g %.17g", i ? ", " : "", CGAL::to_double(q.x()),
                      CGAL::to_double(q.y()));
        s += buf;
    }
    s += ")";
}

/* CGAL's offset at time t from the skeleton (create_offset_polygons_2, then
** arrange_offset_polygons_2 to nest holes into their components): the
** MULTIPOLYGON line bin/wskel --offset --format wkt writes for the same t. */
static Failure offset_wkt(const std::string &path, const Ss &ss, double t, std::string *out) {
    std::vector<boost::shared_ptr<Polygon>> rings = CGAL::create_offset_polygons_2<Polygon>(t, ss, K());
    bool ok = true;
    std::vector<boost::shared_ptr<Pwh>> polys = CGAL::arrange_offset_polygons_2<Pwh>(rings, ok);
    if (!ok) return fail(EXIT_ALGO, path + ": CGAL could not arrange the offset polygons");
    std::string s;
    for (size_t i = 0; i < polys.size(); i++) {
        s += i ? ", (" : "(";
        put_ring(s, polys[i]->outer_boundary());
        for (auto h = polys[i]->holes_begin(); h != polys[i]->holes_end(); ++h) {
            s += ", ";
            put_ring(s, *h);
        }
        s += ")";
    }
    *out = polys.empty() ? "MULTIPOLYGON EMPTY" : "MULTIPOLYGON (" + s + ")";
    return Failure{0, ""};
}

/* Bounding box of ring k's points. */
struct Box {
    double x0, y0, x1, y1;
    bool meets(const Box &o) const { return x0 <= o.x1 && o.x0 <= x1 && y0 <= o.y1 && o.y0 <= y1; }
};
static Box box_of(const std::vector<Point> &p) {
    Box b{INFINITY, INFINITY, -INFINITY, -INFINITY};
    for (const Point &q : p) {
        b.x0 = std::min(b.x0, q.x()), b.y0 = std::min(b.y0, q.y());
        b.x1 = std::max(b.x1, q.x()), b.y1 = std::max(b.y1, q.y());
    }
    return b;
}
static Box seg_box(const Point &a, const Point &b) {
    return Box{std::min(a.x(), b.x()), std::min(a.y(), b.y()), std::max(a.x(), b.x()),
               std::max(a.y(), b.y())};
}

/* CGAL's builder assumes a valid polygon with holes and checks none of it:
** each ring simple (build checks that), the rings pairwise disjoint (not even touching), every
** hole strictly inside the outer ring and in no other hole.  Pairs of rings
** are tested edge against edge where the bounding boxes meet (exact
** predicates), so O(m_k m_l) for rings whose boxes overlap: fine at the
** sizes this baseline is run at. */
static Failure check_rings(const std::string &path, const std::vector<std::vector<Point>> &ring) {
    std::vector<Box> boxes;
    for (size_t k = 0; k < ring.size(); k++) boxes.push_back(box_of(ring[k]));
    for (size_t k = 0; k < ring.size(); k++)
        for (size_t l = k + 1; l < ring.size(); l++) {
            if (!boxes[k].meets(boxes[l])) continue;
            const std::vector<Point> &A = ring[k], &B = ring[l];
            for (size_t i = 0; i < A.size(); i++) {
                const Point &a0 = A[i], &a1 = A[(i + 1) % A.size()];
                Box ba = seg_box(a0, a1);
                if (!ba.meets(boxes[l])) continue;
                for (size_t j = 0; j < B.size(); j++) {
                    const Point &b0 = B[j], &b1 = B[(j + 1) % B.size()];
                    if (ba.meets(seg_box(b0, b1)) &&
                        CGAL::do_intersect(K::Segment_2(a0, a1), K::Segment_2(b0, b1)))
                        return fail(EXIT_INPUT, path + ": rings " + std::to_string(k) + " and " +
                                                    std::to_string(l) + " meet");
                }
            }
        }
    /* Disjoint rings: one vertex decides which contains which. */
    for (size_t k = 1; k < ring.size(); k++) {
        if (CGAL::bounded_side_2(ring[0].begin(), ring[0].end(), ring[k][0], K()) != CGAL::ON_BOUNDED_SIDE)
            return fail(EXIT_INPUT, path + ": hole " + std::to_string(k) + " is not inside the outer ring");
        for (size_t l = 1; l < ring.size(); l++)
            if (l != k && boxes[l].meets(boxes[k]) &&
                CGAL::bounded_side_2(ring[l].begin(), ring[l].end(), ring[k][0], K()) != CGAL::ON_UNBOUNDED_SIDE)
                return fail(EXIT_INPUT, path + ": hole " + std::to_string(k) + " is inside hole " +
                                            std::to_string(l));
    }
    return Failure{0, ""};
}

static Failure build(const std::string &path, const Input &in, const std::vector<double> &times,
                     Result *res) {
    const uint32_t n = (uint32_t)in.x.size(), h = in.rings();

    /* CGAL wants the outer contour counter-clockwise and the holes
    ** clockwise; each ring is reversed if it came the other way. */
    std::vector<std::vector<Point>> ring(h);
    for (uint32_t k = 0; k < h; k++) {
        uint32_t s0 = in.ring_start[k], m = in.ring_start[k + 1] - s0;
        Polygon poly;
        for (uint32_t i = 0; i < m; i++) poly.push_back(Point(in.x[s0 + i], in.y[s0 + i]));
        /* Simplicity is a precondition of CGAL's builder, not something it
        ** checks; a crossing polygon yields garbage or a crash, so refuse it. */
        if (!poly.is_simple())
            return fail(EXIT_INPUT, path + ": " + (k ? "hole " + std::to_string(k) : std::string("polygon")) +
                                        " is not simple (edges cross, touch or repeat a vertex)");
        bool reversed = poly.orientation() != (k == 0 ? CGAL::COUNTERCLOCKWISE : CGAL::CLOCKWISE);
        ring[k].reserve(m);
        for (uint32_t j = 0; j < m; j++) {
            uint32_t i = s0 + (reversed ? m - 1 - j : j);
            ring[k].push_back(Point(in.x[i], in.y[i]));
        }
    }
    if (h > 1) {
        Failure e = check_rings(path, ring);
        if (e.code) return e;
    }

    /* Reflex vertices, counted on the stored orientation (interior on the
    ** left of every edge) with the exact orientation predicate; collinear
    ** vertices are not reflex. */
    for (uint32_t k = 0; k < h; k++) {
        const std::vector<Point> &c = ring[k];
        size_t m = c.size();
        for (size_t j = 0; j < m; j++)
            if (CGAL::orientation(c[(j + m - 1) % m], c[j], c[(j + 1) % m]) == CGAL::RIGHT_TURN)
                res->r++;
    }
    std::vector<Polygon> holes;
    for (uint32_t k = 1; k < h; k++) holes.push_back(Polygon(ring[k].begin(), ring[k].end()));
    const std::vector<Point> &ccw = ring[0];

    auto t0 = std::chrono::steady_clock::now();
    boost::shared_ptr<Ss> ss = CGAL::create_interior_straight_skeleton_2(ccw.begin(), ccw.end(),
                                                                         holes.begin(), holes.end(), K());
    auto t1 = std::chrono::steady_clock::now();
    res->time_s = std::chrono::duration<double>(t1 - t0).count();
    if (!ss) return fail(EXIT_ALGO, path + ": CGAL could not build the straight skeleton (null result)");
    for (double t : times) {
        std::string line;
        Failure e = t > 0 ? offset_wkt(path, *ss, t, &line) : Failure{0, ""};
        if (e.code) return e;
        if (t == 0) { /* CGAL's offset at 0 is undefined (degenerate): the polygon itself */
            line = "MULTIPOLYGON ((";
            for (uint32_t k = 0; k < h; k++) {
                if (k) line += ", ";
                put_ring(line, Polygon(ring[k].begin(), ring[k].end()));
            }
            line += "))";
        }
        res->offset_wkt.push_back(line);
    }

    /* Contour vertices are found by their exact coordinates: the polygon is
    ** simple and its rings disjoint, so the input points are distinct, and
    ** CGAL copies them unchanged. */
    std::map<std::pair<double, double>, uint32_t> input_of;
    for (uint32_t i = 0; i < n; i++) input_of[std::make_pair(in.x[i], in.y[i])] = i;

    res->nodes.resize(n);
    for (uint32_t i = 0; i < n; i++) res->nodes[i] = Node{in.x[i], in.y[i], 0.0};

    std::vector<uint32_t> node_of; /* CGAL vertex id -> output node id */
    for (auto v = ss->vertices_begin(); v != ss->vertices_end(); ++v) {
        size_t id = (size_t)v->id();
        if (id >= node_of.size()) node_of.resize(id + 1, NONE);
        if (v->has_infinite_time())
            return fail(EXIT_ALGO, path + ": CGAL left a vertex at infinite time in its result");
        if (v->is_contour()) {
            auto it = input_of.find(std::make_pair(CGAL::to_double(v->point().x()),
                                                   CGAL::to_double(v->point().y())));
            if (it == input_of.end())
                return fail(EXIT_ALGO, path + ": CGAL contour vertex matches no input vertex");
            node_of[id] = it->second;
        } else {
            node_of[id] = (uint32_t)res->nodes.size();
            res->nodes.push_back(Node{CGAL::to_double(v->point().x()),
                                      CGAL::to_double(v->point().y()), CGAL::to_double(v->time())});
        }
    }

    /* Face -> input edge id, through the face's contour halfedge. */
    auto node = [&](Ss::Vertex_const_handle v) { return node_of[(size_t)v->id()]; };
    auto edge_of_face = [&](Ss::Face_const_handle f) -> uint32_t {
        Ss::Halfedge_const_handle h = f->halfedge();
        uint32_t a = node(h->opposite()->vertex()), b = node(h->vertex());
        if (a >= n || b >= n) return NONE;
        if (b == in.next(a)) return a;
        if (a == in.next(b)) return b;
        return NONE;
    };

    for (auto h = ss->halfedges_begin(); h != ss->halfedges_end(); ++h) {
        if (!h->is_bisector()) continue;
        Ss::Halfedge_const_handle o = h->opposite();
        /* Each pair once: keep the halfedge with the smaller id. */
        if (o->id() < h->id()) continue;
        uint32_t a = node(o->vertex()), b = node(h->vertex());
        uint32_t left = edge_of_face(h->face()), right = edge_of_face(o->face());
        if (a == NONE || b == NONE || left == NONE || right == NONE)
            return fail(EXIT_ALGO, path + ": CGAL bisector with an unknown end or face");
        /* Orient from the earlier to the later node: swapping the ends swaps
        ** the faces. */
        const Node &na = res->nodes[a], &nb = res->nodes[b];
        if (nb.t < na.t || (nb.t == na.t && b < a)) {
            std::swap(a, b);
            std::swap(left, right);
        }
        res->arcs.push_back(Arc{a, b, left, right});
    }
    return Failure{0, ""};
}

/* ------------------------------------------------------------------ main */

static void usage(FILE *f) {
    std::fputs("usage: wskel-cgal [--stats] [--offset T1,T2,...] [-o FILE] INPUT.wpoly\n"
               "  CGAL's interior straight skeleton (unit weights only; holes as further\n"
               "  rings after the outer one) as wskel-1 JSON.\n"
               "  -o FILE   write to FILE (via FILE.tmp and a rename) instead of stdout\n"
               "  --stats   print n, r, nodes, arcs, time and peak RSS to stderr\n"
               "  --offset T1,T2,...  instead, CGAL's offset polygons at these times\n"
               "            (create_offset_polygons_2 and arrange_offset_polygons_2 on the\n"
               "            skeleton): one WKT MULTIPOLYGON line per time, outer rings\n"
               "            counter-clockwise, holes clockwise, as bin/wskel --format wkt\n",
               f);
}

/* The skeleton as JSON, or with --offset the offset lines. */
static void emit(FILE *f, const Input &in, const Result &res, const std::vector<double> &times,
                 long rss) {
    if (times.empty()) {
        write_json(f, in, res.r, res.nodes, res.arcs, res.time_s, rss);
        return;
    }
    for (const std::string &l : res.offset_wkt) std::fprintf(f, "%s\n", l.c_str());
}

static long peak_rss_bytes() {
    struct rusage ru;
    if (getrusage(RUSAGE_SELF, &ru) != 0) return -1;
    return ru.ru_maxrss * 1024L; /* Linux reports kilobytes */
}

int main(int argc, char **argv) {
    bool stats = false;
    std::string out, in_path;
    std::vector<double> times;
    for (int i = 1; i < argc; i++) {
        std::string a = argv[i];
        if (a == "--stats") {
            stats = true;
        } else if (a == "--offset") {
            if (i + 1 >= argc) {
                std::fprintf(stderr, "wskel-cgal: --offset needs a list of times\n");
                return EXIT_USAGE;
            }
            const char *c = argv[++i];
            while (*c) {
                char *end;
                double t = std::strtod(c, &end);
                if (end == c || !(t >= 0) || !std::isfinite(t) || (*end && *end != ',')) {
                    std::fprintf(stderr, "wskel-cgal: --offset must be a list of times >= 0\n");
                    return EXIT_USAGE;
                }
                times.push_back(t);
                c = *end ? end + 1 : end;
            }
        } else if (a == "-o" || a == "--output") {
            if (i + 1 >= argc) {
                std::fprintf(stderr, "wskel-cgal: %s needs a file name\n", a.c_str());
                usage(stderr);
                return EXIT_USAGE;
            }
            out = argv[++i];
        } else if (a == "-h" || a == "--help") {
            usage(stdout);
            return 0;
        } else if (a.size() > 1 && a[0] == '-') {
            std::fprintf(stderr, "wskel-cgal: unknown option %s\n", a.c_str());
            usage(stderr);
            return EXIT_USAGE;
        } else if (in_path.empty()) {
            in_path = a;
        } else {
            std::fprintf(stderr, "wskel-cgal: only one input file, got %s and %s\n",
                         in_path.c_str(), a.c_str());
            return EXIT_USAGE;
        }
    }
    if (in_path.empty()) {
        usage(stderr);
        return EXIT_USAGE;
    }

    Input in;
    Result res;
    Failure e = read_wpoly(in_path, &in);
    if (!e.code) {
        try {
            e = build(in_path, in, times, &res);
        } catch (const std::exception &ex) {
            /* CGAL reports failed preconditions and assertions this way. */
            e = fail(EXIT_ALGO, in_path + ": CGAL failed: " + ex.what());
        }
    }
    if (e.code) {
        /* The unit-weight message already carries its "wskel-cgal: " prefix. */
        if (e.msg.compare(0, 12, "wskel-cgal: ") == 0)
            std::fprintf(stderr, "%s\n", e.msg.c_str());
        else
            std::fprintf(stderr, "wskel-cgal: %s\n", e.msg.c_str());
        return e.code;
    }
    long rss = peak_rss_bytes();

    FILE *f = stdout;
    std::string tmp;
    /* An existing target that is not a regular file (/dev/null, a FIFO) is
    ** written directly: renaming over it would replace the device. */
    struct stat sb;
    bool direct = !out.empty() && stat(out.c_str(), &sb) == 0 && !S_ISREG(sb.st_mode);
    if (direct) {
        f = std::fopen(out.c_str(), "w");
        if (!f) {
            std::fprintf(stderr, "wskel-cgal: %s: cannot write: %s\n", out.c_str(), std::strerror(errno));
            return EXIT_INPUT;
        }
        emit(f, in, res, times, rss);
        bool ok = !std::ferror(f);
        ok = (std::fclose(f) == 0) && ok;
        return ok ? 0 : EXIT_INPUT;
    }
    if (!out.empty()) {
        tmp = out + ".tmp." + std::to_string((long)getpid());
        f = std::fopen(tmp.c_str(), "w");
        if (!f) {
            std::fprintf(stderr, "wskel-cgal: %s: cannot write: %s\n", tmp.c_str(), std::strerror(errno));
            return EXIT_INPUT;
        }
    }
    emit(f, in, res, times, rss);
    if (!out.empty()) {
        bool ok = !std::ferror(f);
        ok = (std::fclose(f) == 0) && ok;
        if (!ok || std::rename(tmp.c_str(), out.c_str()) != 0) {
            std::fprintf(stderr, "wskel-cgal: %s: cannot write: %s\n", out.c_str(), std::strerror(errno));
            std::remove(tmp.c_str());
            return EXIT_INPUT;
        }
    } else if (std::fflush(stdout) != 0) {
        std::fprintf(stderr, "wskel-cgal: cannot write to stdout\n");
        return EXIT_INPUT;
    }
    if (stats)
        std::fprintf(stderr, "wskel-cgal: %s: n=%zu r=%u nodes=%zu arcs=%zu time_s=%.6f peak_rss_bytes=%ld\n",
                     in_path.c_str(), in.x.size(), res.r, res.nodes.size(), res.arcs.size(), res.time_s,
                     rss);
    return 0;
}
