/* A hash map from pointers to ints (ptr_map.h). */
#include "ptr_map.h"

#include <stdint.h>
#include <stdlib.h>

static size_t slot_of(const void *const *keys, size_t slots, const void *key)
{
    uint64_t h = (uint64_t)(uintptr_t)key * 0x9E3779B97F4A7C15u;
    size_t j = (size_t)(h >> 17) & (slots - 1);
    while (keys[j] && keys[j] != key)
        j = (j + 1) & (slots - 1);
    return j;
}

int ptr_map_get(const PtrMap *m, const void *key)
{
    if (m->slots == 0)
        return -1;
    size_t j = slot_of(m->keys, m->slots, key);
    return m->keys[j] ? m->values[j] : -1;
}

int ptr_map_put(PtrMap *m, const void *key, int value)
{
    if (m->slots > 0) {
        size_t j = slot_of(m->keys, m->slots, key);
        if (m->keys[j]) {
            m->values[j] = value;
            return 0;
        }
    }
    if (2 * (m->used + 1) > m->slots) {
        size_t slots = m->slots ? 2 * m->slots : 64;
        const void **keys = calloc(slots, sizeof *keys);
        int *values = calloc(slots, sizeof *values);
        if (!keys || !values) {
            free(keys);
            free(values);
            return -1;
        }
        for (size_t i = 0; i < m->slots; i++) {
            if (!m->keys[i])
                continue;
            size_t j = slot_of(keys, slots, m->keys[i]);
            keys[j] = m->keys[i];
            values[j] = m->values[i];
        }
        free(m->keys);
        free(m->values);
        m->keys = keys;
        m->values = values;
        m->slots = slots;
    }
    size_t j = slot_of(m->keys, m->slots, key);
    m->keys[j] = key;
    m->values[j] = value;
    m->used++;
    return 0;
}

void ptr_map_free(PtrMap *m)
{
    free(m->keys);
    free(m->values);
    m->keys = NULL;
    m->values = NULL;
    m->slots = m->used = 0;
}
