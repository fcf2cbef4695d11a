/*
 * suggest.h - "did you mean" for misspelt words.
 */
#ifndef REFRAY_SUGGEST_H
#define REFRAY_SUGGEST_H

#include <stddef.h>

/* Optimal string alignment distance (Damerau-Levenshtein with adjacent
 * transpositions), case-insensitive; words longer than 63 bytes compare as
 * far apart. */
int suggest_distance(const char *a, size_t alen, const char *b);

/*
 * The candidate closest to word[0..len), or NULL when none is close enough
 * to be a plausible typo: distance <= 1 for words of up to 4 bytes, <= 2 up
 * to 8, else <= 3.  Ties go to the earlier candidate.
 */
const char *suggest_nearest(const char *word, size_t len, const char *const *candidates, int count);

#endif
