/*
 * suggest.c - edit distance over short words, in a fixed table on the stack.
 */
#include <ctype.h>
#include <string.h>
#include "base/suggest.h"

enum { WORD_MAX = 63, FAR_APART = 1000 };

static int min3(int a, int b, int c)
{
    int m = a < b ? a : b;
    return m < c ? m : c;
}

static int same(char a, char b)
{
    return tolower((unsigned char)a) == tolower((unsigned char)b);
}

int suggest_distance(const char *a, size_t alen, const char *b)
{
    size_t blen = strlen(b);
    if (alen > WORD_MAX || blen > WORD_MAX)
        return FAR_APART;
    int d[WORD_MAX + 1][WORD_MAX + 1];
    for (size_t i = 0; i <= alen; i++)
        d[i][0] = (int)i;
    for (size_t j = 0; j <= blen; j++)
        d[0][j] = (int)j;
    for (size_t i = 1; i <= alen; i++) {
        for (size_t j = 1; j <= blen; j++) {
            int cost = same(a[i - 1], b[j - 1]) ? 0 : 1;
            d[i][j] = min3(d[i - 1][j] + 1, d[i][j - 1] + 1, d[i - 1][j - 1] + cost);
            if (i > 1 && j > 1 && same(a[i - 1], b[j - 2]) && same(a[i - 2], b[j - 1]) &&
                d[i - 2][j - 2] + 1 < d[i][j])
                d[i][j] = d[i - 2][j - 2] + 1;
        }
    }
    return d[alen][blen];
}

const char *suggest_nearest(const char *word, size_t len, const char *const *candidates, int count)
{
    int limit = len <= 4 ? 1 : len <= 8 ? 2 : 3;
    const char *best = NULL;
    int best_distance = limit + 1;
    for (int i = 0; i < count; i++) {
        int dist = suggest_distance(word, len, candidates[i]);
        if (dist < best_distance) {
            best = candidates[i];
            best_distance = dist;
        }
    }
    return best;
}
