/* Lists of items per grid cell, kept only for the cells that have any: a
 * light's shadow polygons touch a small share of the grid's cells (on
 * make-mesh.sh 10^6 8, about 1 in 20 of 8 million), and an offset per cell
 * for all of them was 32 MB per light, most of it zeros that had to be
 * written. Per block of 64 cells, a bit mask of the occupied ones and how
 * many occupied cells come before the block; per occupied cell, where its
 * list starts. A lookup is a mask test and a population count. */
#ifndef HST_CELL_LISTS_H
#define HST_CELL_LISTS_H

#include <stddef.h>
#include <stdint.h>

typedef struct {
    uint64_t *occupied;    /* bit c & 63 of word c >> 6: cell c has a list */
    uint32_t *block_rank;  /* per word: occupied cells in the words before it */
    uint32_t *list_start;  /* per occupied cell, in cell order, + 1: offsets into items */
    uint32_t *items;
    size_t nitems;
    uint32_t noccupied;
    int nblocks;
} CellLists;

/* The lists of n registrations (cell[i], item[i]) over ncells cells, items
 * in registration order within each cell. Returns 0, or -1 when out of
 * memory (nothing kept). */
int cell_lists_build(CellLists *cl, int ncells, const uint32_t *cell, const uint32_t *item, size_t stride, size_t n);
void cell_lists_free(CellLists *cl);
static inline int cell_lists_built(const CellLists *cl) { return cl->occupied != NULL; }
/* Bytes it holds, for the statistics. */
size_t cell_lists_bytes(const CellLists *cl);

static inline uint32_t cell_lists_popcount(uint64_t x)
{
#if defined(__GNUC__)
    return (uint32_t)__builtin_popcountll(x);
#else
    uint32_t n = 0;
    for (; x; x &= x - 1)
        n++;
    return n;
#endif
}

/* Cell c's list: items[*begin, *end) (empty for a cell without one). */
static inline void cell_lists_get(const CellLists *cl, uint32_t c, uint32_t *begin, uint32_t *end)
{
    uint64_t word = cl->occupied[c >> 6], bit = 1ull << (c & 63u);
    if (!(word & bit)) {
        *begin = *end = 0;
        return;
    }
    uint32_t r = cl->block_rank[c >> 6] + cell_lists_popcount(word & (bit - 1));
    *begin = cl->list_start[r];
    *end = cl->list_start[r + 1];
}

#endif
