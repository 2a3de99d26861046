/*
** fuzz_wpoly.c: libFuzzer target for the .wpoly reader
** (wk_polygon_read_wpoly through a memory stream).  Findings: a crash, UB
** or a leak (sanitizers; tracked bytes through the strict run), a status
** other than WK_OK / WK_EINPUT, a rejection without file, line or a clean
** reason, an input the byte rules say must be refused but was accepted, an
** accepted polygon whose values differ from an independent reading of the
** file, or that fails wk_polygon_validate or the writer round trip.
*/
#define _GNU_SOURCE
#include "fuzz_common.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
    wk_run R;
    wk_run_init_checked(&R);
    FILE *f = fmemopen((void *)data, size, "rb");
    if (!f) abort();
    wk_polygon *P = NULL;
    wk_status st = wk_polygon_read_wpoly(&R, f, "fuzz.wpoly", &P);
    fclose(f);
    check_status(&R, st, P, "fuzz.wpoly");
    if (st == WK_OK) {
        if (bytes_wpoly_refusable(data, size))
            finding("accepted an input with bytes the format does not allow");
        check_wpoly_values(data, size, P);
        check_accepted(&R, P);
        wk_polygon_free(&R, P);
    }
    close_run(&R, "wpoly reader");
    return 0;
}
