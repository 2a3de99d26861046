/*
** wskel_cgal.cpp: the CGAL baseline, bin/wskel-cgal.
**
** Reads a unit-weight .wpoly polygon, builds its interior straight skeleton
** with CGAL::create_interior_straight_skeleton_2 (Exact_predicates_inexact_
** constructions_kernel) and writes it in the wskel JSON contract
** ("format":"wskel-1"), so scripts/compare_skeletons.py can hold wskel's
** variants against it and the benchmarks can quote CGAL's time and memory.
**
** What it is not: part of the library.  It links only CGAL, GMP and MPFR, so
** it builds (and tests/test_cgal_agreement.py runs) independently of the C
** code, and it does no weighted skeletons: CGAL has no weights, so any weight
** other than 1 is refused.
**
** Numbering (the contract's, see engine/wskel.h):
**   - nodes[0..n) are the input vertices in input line order at t = 0, even
**     when the input is clockwise and CGAL was given the reversed copy;
**   - the other nodes are CGAL's skeleton vertices in CGAL's order, t = time();
**   - edge i runs from input vertex i to input vertex i+1 (mod n); a face is
**     named by its edge.  CGAL's face f is bounded by the contour halfedge
**     f->halfedge() (the face lies on its left, i.e. inside the polygon); its
**     two endpoints are input vertices a and b, and the edge joining them is
**     a if b == a+1 (mod n) (counter-clockwise input), or b if a == b+1
**     (the reversed copy of a clockwise input).  Deriving the id from the
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

#include <sys/resource.h>

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
    std::vector<double> x, y; /* in input line order */
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
    long n = -1;
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
    while (next_line(&line)) {
        if (!data_line(line.c_str())) continue;
        const char *s = line.c_str();
        if (n < 0) {
            char *end;
            errno = 0;
            long v = std::strtol(s, &end, 10);
            if (end == s || !only_blanks(end) || errno == ERANGE) {
                res = fail(EXIT_INPUT, where(path, lineno) + "expected the vertex count");
                break;
            }
            if (v < 3 || v > 100000000L) {
                res = fail(EXIT_INPUT, where(path, lineno) + "vertex count must be in [3, 1e8] (got " +
                                           std::to_string(v) + ")");
                break;
            }
            n = v;
            in->x.reserve((size_t)n);
            in->y.reserve((size_t)n);
            continue;
        }
        if ((long)in->x.size() == n) {
            res = fail(EXIT_INPUT, where(path, lineno) + "more than " + std::to_string(n) +
                                       " vertices");
            break;
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
    }
    if (f != stdin) std::fclose(f);
    if (res.code) return res;
    if (n < 0) return fail(EXIT_INPUT, path + ": no vertex count (empty file?)");
    if ((long)in->x.size() != n)
        return fail(EXIT_INPUT, where(path, lineno) + "expected " + std::to_string(n) +
                                    " vertices, found " + std::to_string(in->x.size()));
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

static void write_json(FILE *f, uint32_t n, uint32_t r, const std::vector<Node> &nodes,
                       const std::vector<Arc> &arcs, double time_s, long peak_rss) {
    std::fprintf(f, "{\"format\":\"wskel-1\",\"variant\":\"cgal\",\"k\":null,\"n\":%u,\"r\":%u,\n", n, r);
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
};

static Failure build(const std::string &path, const Input &in, Result *res) {
    const uint32_t n = (uint32_t)in.x.size();

    /* CGAL wants a counter-clockwise outer contour.  order[j] is the input
    ** index of the j-th vertex handed to CGAL. */
    Polygon poly;
    for (uint32_t i = 0; i < n; i++) poly.push_back(Point(in.x[i], in.y[i]));
    /* Simplicity is a precondition of CGAL's builder, not something it
    ** checks; a crossing polygon yields garbage or a crash, so refuse it. */
    if (!poly.is_simple())
        return fail(EXIT_INPUT, path + ": polygon is not simple (edges cross, touch or repeat a vertex)");
    std::vector<uint32_t> order(n);
    bool reversed = poly.orientation() == CGAL::CLOCKWISE;
    for (uint32_t j = 0; j < n; j++) order[j] = reversed ? n - 1 - j : j;
    std::vector<Point> ccw;
    ccw.reserve(n);
    for (uint32_t j = 0; j < n; j++) ccw.push_back(Point(in.x[order[j]], in.y[order[j]]));

    /* Reflex vertices, counted on the counter-clockwise copy with the exact
    ** orientation predicate; collinear vertices are not reflex. */
    for (uint32_t j = 0; j < n; j++)
        if (CGAL::orientation(ccw[(j + n - 1) % n], ccw[j], ccw[(j + 1) % n]) == CGAL::RIGHT_TURN)
            res->r++;

    auto t0 = std::chrono::steady_clock::now();
    boost::shared_ptr<Ss> ss = CGAL::create_interior_straight_skeleton_2(ccw.begin(), ccw.end(), K());
    auto t1 = std::chrono::steady_clock::now();
    res->time_s = std::chrono::duration<double>(t1 - t0).count();
    if (!ss) return fail(EXIT_ALGO, path + ": CGAL could not build the straight skeleton (null result)");

    /* Contour vertices are found by their exact coordinates: the polygon is
    ** simple, so the input points are distinct, and CGAL copies them
    ** unchanged. */
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
        if (b == (a + 1) % n) return a;
        if (a == (b + 1) % n) return b;
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
    std::fputs("usage: wskel-cgal [--stats] [-o FILE] INPUT.wpoly\n"
               "  CGAL's interior straight skeleton (unit weights only) as wskel-1 JSON.\n"
               "  -o FILE   write to FILE (via FILE.tmp and a rename) instead of stdout\n"
               "  --stats   print n, r, nodes, arcs, time and peak RSS to stderr\n",
               f);
}

static long peak_rss_bytes() {
    struct rusage ru;
    if (getrusage(RUSAGE_SELF, &ru) != 0) return -1;
    return ru.ru_maxrss * 1024L; /* Linux reports kilobytes */
}

int main(int argc, char **argv) {
    bool stats = false;
    std::string out, in_path;
    for (int i = 1; i < argc; i++) {
        std::string a = argv[i];
        if (a == "--stats") {
            stats = true;
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
            e = build(in_path, in, &res);
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
        write_json(f, (uint32_t)in.x.size(), res.r, res.nodes, res.arcs, res.time_s, rss);
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
    write_json(f, (uint32_t)in.x.size(), res.r, res.nodes, res.arcs, res.time_s, rss);
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
