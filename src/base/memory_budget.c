/* The memory budget's default and its sizes as text (memory_budget.h). */
#include "memory_budget.h"

#include <stdint.h>
#include <stdio.h>
#include <unistd.h>

size_t memory_budget_default(void)
{
    long pages = sysconf(_SC_PHYS_PAGES), page = sysconf(_SC_PAGESIZE);
    if (pages <= 0 || page <= 0)
        return (size_t)4 << 30;
    uintmax_t bytes = (uintmax_t)pages * (uintmax_t)page / 4;
    if (bytes < ((uintmax_t)256 << 20))
        bytes = (uintmax_t)256 << 20;
    return bytes > SIZE_MAX ? SIZE_MAX : (size_t)bytes;
}

void memory_size_text(char *buf, size_t n, size_t bytes)
{
    static const char *const units[] = { "bytes", "KiB", "MiB", "GiB", "TiB", "PiB", "EiB" };
    double v = (double)bytes;
    int u = 0;
    while (v >= 1024.0 && u < 6) {
        v /= 1024.0;
        u++;
    }
    if (u == 0)
        snprintf(buf, n, "%zu bytes", bytes);
    else
        snprintf(buf, n, v < 10.0 && v != (double)(long)v ? "%.1f %s" : "%.0f %s", v, units[u]);
}
