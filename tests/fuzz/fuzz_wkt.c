/*
** fuzz_wkt.c: libFuzzer target for the WKT reader (wk_polygon_read_wkt on
** the bytes).  Findings as for the other readers (fuzz_common.h): a crash,
** UB or a leak, a status other than WK_OK / WK_EINPUT, a rejection without
** file, line or a clean reason, an accepted input that is not strict UTF-8
** or holds a control character, an accepted polygon that fails
** wk_polygon_validate or the .wpoly writer round trip.
*/
#define _GNU_SOURCE
#include "fuzz_common.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
    wk_run R;
    wk_run_init_checked(&R);
    wk_polygon *P = NULL;
    wk_status st = wk_polygon_read_wkt(&R, (const char *)data, size, "fuzz.wkt", &P);
    check_status(&R, st, P, "fuzz.wkt");
    if (st == WK_OK) {
        if (bytes_graphml_refusable(data, size)) /* the same byte rules */
            finding("accepted an input with bytes the format does not allow");
        check_accepted(&R, P);
        wk_polygon_free(&R, P);
    }
    close_run(&R, "wkt reader");
    return 0;
}
