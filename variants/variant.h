/*
** variant.h: the one interface every skeleton algorithm implements.
** A variant is a const wk_variant (name, capability flags, run function)
** declared here and listed in variants/registry.c.  A variant includes engine
** headers only, never another variant's.
*/
#ifndef WK_VARIANT_H
#define WK_VARIANT_H
#include "../engine/wskel.h"

extern const wk_variant wk_variant_naive;
extern const wk_variant wk_variant_monotone;
extern const wk_variant wk_variant_arrangement;

#endif
