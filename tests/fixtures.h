/*
** fixtures.h: renamed tests/helpers.h.  Kept only for the test files not yet
** switched (tests/test_run.c); delete it once nothing includes it.
*/
#include "helpers.h"
