/*
** naive.h: what the files of the reference variant share.
*/
#ifndef WK_NAIVE_H
#define WK_NAIVE_H
#include "wavefront.h"

/* The brute-force split finder (split_brute.c). */
extern const wk_split_finder naive_split_finder;

#endif
