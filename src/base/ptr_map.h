/* A hash map from pointers to ints (open addressing, grown by doubling):
 * for tables keyed by the identity of something the scene made once, as
 * the world's build keeps them (a texture_map built once, the placements
 * of a mesh's faces). */
#ifndef HST_PTR_MAP_H
#define HST_PTR_MAP_H

#include <stddef.h>

typedef struct {
    const void **keys;  /* NULL: an empty slot */
    int *values;
    size_t slots, used; /* slots: 0 or a power of two */
} PtrMap;

#define PTR_MAP_EMPTY { NULL, NULL, 0, 0 }

/* key's value, or -1 when key is not in the map. */
int ptr_map_get(const PtrMap *m, const void *key);
/* Sets key's value (key not NULL). Returns 0, or -1 when out of memory
 * (the map is then as it was). */
int ptr_map_put(PtrMap *m, const void *key, int value);
void ptr_map_free(PtrMap *m);

#endif
