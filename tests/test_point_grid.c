/*
** test_point_grid.c: engine/point_grid.h, the hashed grid by which a large
** group of simultaneous events looks up its nodes and vertices
** (wavefront_group.c), and the group code's use of it under allocation
** failure.  The plans must be the scans' bit for bit; that the skeletons
** did not change is checked by comparing outputs (see the motorcycle
** README's Cost section), not here.
*/
#include <criterion/criterion.h>
#include <math.h>

#include "helpers.h"
#include "point_grid.h"

/* splitmix64: a reproducible stream without globals */
static uint64_t next_u64(uint64_t *s) {
    uint64_t z = (*s += 0x9E3779B97F4A7C15u);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9u;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBu;
    return z ^ (z >> 31);
}

static double uniform(uint64_t *s) { return (double)(next_u64(s) >> 11) * 0x1.0p-53; }

/* Every point inside a box is listed, increasing, each once, for boxes
** from below a cell to many cells, points on cell walls included. */
Test(point_grid, lists_every_point_in_the_box) {
    wk_run R;
    wk_run_init(&R);
    wk_point_grid G;
    wk_point_grid_init(&G);
    enum { N = 3000 };
    static wk_point p[N];
    uint64_t seed = 7;
    for (int round = 0; round < 3; round++) {
        double h = round == 0 ? 0.1 : round == 1 ? 1e-9 : 3.0;
        cr_assert_eq(wk_point_grid_reset(&R, &G, -1.0, -2.0, h), WK_OK);
        for (uint32_t i = 0; i < N; i++) {
            /* a third on the grid's walls (multiples of h from the origin) */
            double x = uniform(&seed) * 4 - 2, y = uniform(&seed) * 4 - 2;
            if (i % 3 == 0) x = -1.0 + h * floor((x + 1.0) / h);
            if (i % 3 == 1) y = -2.0 + h * floor((y + 2.0) / h);
            p[i] = (wk_point){x, y};
            cr_assert_eq(wk_point_grid_add(&R, &G, i, p[i]), WK_OK);
        }
        for (int q = 0; q < 300; q++) {
            wk_point c = p[next_u64(&seed) % N];
            double r = (q % 4 == 0) ? 0 : uniform(&seed) * h * (q % 2 ? 0.5 : 5);
            wk_point lo = {c.x - r, c.y - r}, hi = {c.x + r, c.y + r};
            if (!wk_point_grid_query(&G, lo, hi, UINT64_MAX)) continue;
            for (uint32_t k = 1; k < G.n_out; k++) cr_assert_lt(G.out[k - 1], G.out[k]);
            uint32_t k = 0;
            for (uint32_t i = 0; i < N; i++) {
                if (!(p[i].x >= lo.x && p[i].x <= hi.x && p[i].y >= lo.y && p[i].y <= hi.y)) continue;
                while (k < G.n_out && G.out[k] < i) k++;
                cr_assert(k < G.n_out && G.out[k] == i, "h %g: point %u in the box not listed", h, i);
            }
        }
    }
    /* too many cells, or a box that is not finite: the caller scans */
    cr_assert_eq(wk_point_grid_reset(&R, &G, 0, 0, 1e-9), WK_OK);
    cr_assert(!wk_point_grid_query(&G, (wk_point){0, 0}, (wk_point){1, 1}, 1000));
    cr_assert(!wk_point_grid_query(&G, (wk_point){NAN, 0}, (wk_point){1, 1}, UINT64_MAX));
    cr_assert(wk_point_grid_query(&G, (wk_point){0, 0}, (wk_point){0, 0}, 1));
    cr_assert_eq(G.n_out, 0);
    wk_point_grid_free(&R, &G);
    ASSERT_CLEAN_CLOSE(R);
}

/* A comb's groups hold hundreds of events at once (so the group code takes
** its grids, and the motorcycle finder its forward-piece index): every
** allocation failure in them is reported and leaks nothing. */
Test(point_grid, large_groups_every_allocation_failure_is_clean, .timeout = 300) {
    const char *names[] = {"naive", "motorcycle"};
    for (int vi = 0; vi < 2; vi++) {
        wk_run R;
        wk_run_init(&R);
        const wk_variant *V = variant(names[vi]);
        R.variant = V;
        wk_polygon *P = NULL;
        cr_assert_eq(gen(&R, "comb", 600, -1, 1, NULL, &P), WK_OK);
        size_t base = R.alloc.live;
        int failures = 0;
        for (int64_t N = 0;; N++) {
            R.err.code = WK_OK;
            R.alloc.fail_after = (int64_t)R.alloc.calls + N;
            wk_skeleton *S = NULL;
            wk_status st = wk_solve(&R, V, P, &S, NULL, NULL);
            R.alloc.fail_after = -1;
            if (S) wk_skeleton_free(&R, S);
            cr_assert_eq(R.alloc.live, base, "%s N=%lld: %zu bytes leaked", names[vi], (long long)N,
                         R.alloc.live - base);
            if (st == WK_OK) break;
            cr_assert_eq(st, WK_ENOMEM, "%s N=%lld: status %d (%s)", names[vi], (long long)N, st,
                         R.err.msg);
            failures++;
            cr_assert_lt(N, 200000);
        }
        cr_assert_gt(failures, 10);
        cr_assert_gt(counter(&R, "simultaneous_event_groups"), 0);
        wk_polygon_free(&R, P);
        ASSERT_CLEAN_CLOSE(R);
    }
}
