/*
** registry.c: the static const list of variants (Redis's backend table).
** To add a variant: declare it here and list it below; the Makefile builds
** every .c file of every folder under variants/ into the library.  The first
** entry is the reference variant (wk_variant_reference).
*/
#include "variant.h"

#include <string.h>

extern const wk_variant wk_variant_naive;
extern const wk_variant wk_variant_monotone;
extern const wk_variant wk_variant_arrangement;
extern const wk_variant wk_variant_motorcycle;
extern const wk_variant wk_variant_deforming;

static const wk_variant *const registry[] = {
    &wk_variant_naive,
    &wk_variant_monotone,
    &wk_variant_arrangement,
    &wk_variant_motorcycle,
    &wk_variant_deforming,
    NULL,
};

const wk_variant *wk_variant_find(const char *name) {
    for (size_t i = 0; registry[i]; i++)
        if (strcmp(registry[i]->name, name) == 0) return registry[i];
    return NULL;
}

const wk_variant *wk_variant_at(size_t i) {
    return i < sizeof registry / sizeof registry[0] - 1 ? registry[i] : NULL;
}

const wk_variant *wk_variant_reference(void) { return registry[0]; }
