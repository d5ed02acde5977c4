// Bounds on what glibc's malloc keeps of the memory the server freed (docs/deployment.md
// "Memory"). HTTP workers come and go with the load (up to --threads, server/http/
// elastic_task_queue.h); each thread allocates from one of glibc's arenas, of which there are
// up to 8 per core by default, and an arena keeps the memory freed in it for its next
// allocations. After concurrent large answers (skydomes, batches of thousands of views), that
// freed memory was most of the resident memory: measured with malloc_stats() after 600 large
// answers to 48 concurrent clients, 16 arenas held 128.8 MB for 1.7 MB in use (147 MB
// resident), and malloc_trim(0) brought the process back to 58 MB. So:
//  - bound_heap_arenas() (at start, before any thread): at most kHeapArenaMax arenas, and
//    allocations from kHeapMmapThresholdBytes up mapped on their own and unmapped when freed
//    (glibc otherwise raises that threshold to the largest block freed, up to 32 MiB, and keeps
//    answer-sized blocks in the arenas). Either is left as it is when the environment sets it
//    (MALLOC_ARENA_MAX, MALLOC_MMAP_THRESHOLD_, GLIBC_TUNABLES), so an operator can choose.
//  - release_free_heap_memory(): the free memory of every arena goes back to the system
//    (malloc_trim), called when an HTTP worker retires (the load fell), at most once a second.
// Without glibc (another C library, or a sanitizer's allocator) both do nothing.
// Thread-safety: bound_heap_arenas() before other threads start; release_free_heap_memory()
// from any thread.
#pragma once

#include <cstddef>
#include <string>

namespace clearsky::server {

inline constexpr int kHeapArenaMax = 4;
inline constexpr std::size_t kHeapMmapThresholdBytes = 256 * 1024;

// Applies the bounds the environment does not set; returns what it did, for the start-up log
// (e.g. "malloc arenas <= 4, blocks >= 262144 bytes mapped").
std::string bound_heap_arenas();

// malloc_trim(0) unless another call did it within the last second; returns whether it ran.
bool release_free_heap_memory();
// malloc_trim(0) at once: after a table build, whose intermediates were freed in the arena of
// the threads that built it (docs/tables-and-memory.md "The server with every default ready").
void release_free_heap_memory_now();

}  // namespace clearsky::server
