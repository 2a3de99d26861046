/*
** fuzz_geojson.c: libFuzzer target for the GeoJSON reader
** (wk_polygon_read_geojson on the bytes).  Findings as for the other readers
** (fuzz_common.h), except the line: jansson keeps no positions for values,
** so a rejection after parsing names the JSON path instead (line 0); a byte
** fault or a JSON syntax error ("JSON error:") must still carry its line.
** Leaks on jansson's side show through LeakSanitizer.
*/
#define _GNU_SOURCE
#include "fuzz_common.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
    wk_run R;
    wk_run_init_checked(&R);
    wk_polygon *P = NULL;
    wk_status st = wk_polygon_read_geojson(&R, (const char *)data, size, "fuzz.geojson", &P);
    geojson_line_exception(&R, st);
    check_status(&R, st, P, "fuzz.geojson");
    if (st == WK_OK) {
        if (bytes_graphml_refusable(data, size)) /* the same byte rules */
            finding("accepted an input with bytes the format does not allow");
        check_accepted(&R, P);
        wk_polygon_free(&R, P);
    }
    close_run(&R, "geojson reader");
    return 0;
}
