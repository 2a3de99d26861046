/*
** fuzz_graphml.c: libFuzzer target for the GraphML reader
** (wk_polygon_read_graphml on the bytes).  Findings: a crash, UB or a leak
** (sanitizers, LeakSanitizer for libxml2's side; tracked bytes through the
** strict run), a status other than WK_OK / WK_EINPUT, a rejection without
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
    wk_status st = wk_polygon_read_graphml(&R, (const char *)data, size, "fuzz.graphml", &P);
    check_status(&R, st, P, "fuzz.graphml");
    if (st == WK_OK) {
        if (bytes_graphml_refusable(data, size))
            finding("accepted an input with bytes the format does not allow");
        check_accepted(&R, P);
        wk_polygon_free(&R, P);
    }
    close_run(&R, "graphml reader");
    return 0;
}
