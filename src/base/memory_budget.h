/* The memory budget (--max-memory) that a render's parse, the pictures it
 * reads and the world built from it are held to, and `hstrace compare`
 * too: its default, and sizes written as people read them in the messages
 * of whatever refuses to go past it. */
#ifndef HST_MEMORY_BUDGET_H
#define HST_MEMORY_BUDGET_H

#include <stddef.h>

/* A fair share of the machine: a quarter of its physical memory, at least
 * 256 MiB (4 GiB when the size is unknown). */
size_t memory_budget_default(void);

/* 1.5 GiB, 256 MiB, 12 KiB, 100 bytes. */
void memory_size_text(char *buf, size_t n, size_t bytes);

#endif
