/* The pointer map (src/base/ptr_map.h) the world's build keys its tables
 * by: every key put finds its value, through the map's growth; keys never
 * put find none; a value put again replaces the first. */
#include <stdlib.h>

#include "ptr_map.h"
#include "tap.h"

#define N 20000

int main(void)
{
    static char objects[2 * N]; /* the even ones put, the odd ones not */
    PtrMap m = PTR_MAP_EMPTY;
    tap_ok(ptr_map_get(&m, &objects[0]) == -1, "an empty map finds nothing");
    int failed = 0;
    for (int i = 0; i < N; i++)
        failed += ptr_map_put(&m, &objects[2 * i], i) != 0;
    tap_ok(failed == 0, "%d keys put (%d failed)", N, failed);
    long wrong = 0, found_absent = 0;
    for (int i = 0; i < N; i++) {
        wrong += ptr_map_get(&m, &objects[2 * i]) != i;
        found_absent += ptr_map_get(&m, &objects[2 * i + 1]) != -1;
    }
    tap_ok(wrong == 0, "every key finds its value through the growths (%ld wrong)", wrong);
    tap_ok(found_absent == 0, "no key never put finds a value (%ld do)", found_absent);
    ptr_map_put(&m, &objects[6], 77);
    tap_ok(ptr_map_get(&m, &objects[6]) == 77 && m.used == N, "a key put again has the new value, counted once");
    tap_ok(m.slots >= 2 * m.used, "the map stays at most half full (%zu of %zu)", m.used, m.slots);
    ptr_map_free(&m);
    tap_ok(ptr_map_get(&m, &objects[0]) == -1, "a freed map finds nothing");
    return tap_done();
}
