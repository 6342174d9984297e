/* Sparse cell lists (cell_lists.h). */
#include "cell_lists.h"
#include "big_memory.h"

#include <stdlib.h>
#include <string.h>

static inline uint32_t rank_of(const CellLists *cl, uint32_t c)
{
    uint64_t word = cl->occupied[c >> 6], bit = 1ull << (c & 63u);
    return cl->block_rank[c >> 6] + cell_lists_popcount(word & (bit - 1));
}

int cell_lists_build(CellLists *cl, int ncells, const uint32_t *cell, const uint32_t *item, size_t stride, size_t n)
{
    memset(cl, 0, sizeof *cl);
    cl->nblocks = (ncells + 63) / 64;
    size_t nb = (size_t)(cl->nblocks > 0 ? cl->nblocks : 1);
    cl->occupied = big_calloc(nb, sizeof *cl->occupied);
    cl->block_rank = big_malloc(nb * sizeof *cl->block_rank);
    cl->items = big_malloc((n ? n : 1) * sizeof *cl->items);
    if (!cl->occupied || !cl->block_rank || !cl->items) {
        cell_lists_free(cl);
        return -1;
    }
#define CELL(i) (*(const uint32_t *)((const char *)cell + (i) * stride))
#define ITEM(i) (*(const uint32_t *)((const char *)item + (i) * stride))
    for (size_t i = 0; i < n; i++)
        cl->occupied[CELL(i) >> 6] |= 1ull << (CELL(i) & 63u);
    uint32_t rank = 0;
    for (int b = 0; b < cl->nblocks; b++) {
        cl->block_rank[b] = rank;
        rank += cell_lists_popcount(cl->occupied[b]);
    }
    cl->noccupied = rank;
    cl->list_start = big_calloc((size_t)rank + 1, sizeof *cl->list_start);
    uint32_t *fill = big_malloc(((size_t)rank + 1) * sizeof *fill);
    if (!cl->list_start || !fill) {
        free(fill);
        cell_lists_free(cl);
        return -1;
    }
    /* Counting sort, as the dense offsets did: items keep their order per cell. */
    for (size_t i = 0; i < n; i++)
        cl->list_start[rank_of(cl, CELL(i)) + 1]++;
    for (uint32_t r = 0; r < rank; r++)
        cl->list_start[r + 1] += cl->list_start[r];
    memcpy(fill, cl->list_start, ((size_t)rank + 1) * sizeof *fill);
    for (size_t i = 0; i < n; i++)
        cl->items[fill[rank_of(cl, CELL(i))]++] = ITEM(i);
#undef CELL
#undef ITEM
    cl->nitems = n;
    free(fill);
    return 0;
}

void cell_lists_free(CellLists *cl)
{
    free(cl->occupied);
    free(cl->block_rank);
    free(cl->list_start);
    free(cl->items);
    memset(cl, 0, sizeof *cl);
}

size_t cell_lists_bytes(const CellLists *cl)
{
    if (!cl->occupied)
        return 0;
    return (size_t)cl->nblocks * (sizeof *cl->occupied + sizeof *cl->block_rank) +
           ((size_t)cl->noccupied + 1) * sizeof *cl->list_start + cl->nitems * sizeof *cl->items;
}
