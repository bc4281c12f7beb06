// Per-thread bump arenas in huge pages, kept for the process and reused by later threads.
#include "core/scratch_arena.h"

#include <atomic>
#include <cstdint>
#include <mutex>

#include "core/large_blocks.h"

namespace rs {

namespace {

/// Arenas made at most: threads beyond this many at once get none (std::allocator serves
/// them). Address space only: an arena's pages are faulted as they are first written.
constexpr std::size_t kMaxArenas = 64;
/// Every block starts on a cache line, as malloc's larger blocks about do (the kernel's lane
/// loops read its arrays a lane at a time).
constexpr std::size_t kBlockAlign = 64;

/// Arenas made so far, [0, arenaCount): each is set once and never freed, so scratchOwns
/// may read them from any thread without a lock.
std::atomic<char*> arenas[kMaxArenas];
std::atomic<std::size_t> arenaCount{0};
/// Which arenas a live thread holds; guarded by `poolLock`.
bool arenaHeld[kMaxArenas];
std::mutex poolLock;

/// The calling thread's arena: trivially destructible, so readable even while the thread's
/// other thread_local objects are being destroyed (after `Release` has run).
struct ThreadArena {
    char* base = nullptr;
    std::size_t used = 0;
    std::size_t slot = 0;
    bool tried = false;  ///< An arena was asked for (none left, or released at thread exit).
};
thread_local ThreadArena current;

/// Hands the thread's arena back at thread exit. Constructed by scratchTouch() before any
/// thread_local object that allocates scratch, so destroyed after all of them.
struct Release {
    ~Release() {
        if (current.base) {
            const std::lock_guard<std::mutex> lock(poolLock);
            arenaHeld[current.slot] = false;
        }
        current.base = nullptr;
        current.tried = true;  // Anything allocated from now on comes from std::allocator.
    }
};

/// A free arena for the calling thread (a new one when all made are held), or nullptr.
void takeArena() noexcept {
    current.tried = true;
    const std::lock_guard<std::mutex> lock(poolLock);
    const std::size_t made = arenaCount.load(std::memory_order_relaxed);
    std::size_t slot = 0;
    while (slot < made && arenaHeld[slot]) ++slot;
    if (slot == kMaxArenas) return;
    if (slot == made) {
        try {
            arenas[slot].store(static_cast<char*>(largeAllocate(kScratchArenaBytes)),
                               std::memory_order_release);
        } catch (const std::bad_alloc&) {
            return;
        }
        arenaCount.store(made + 1, std::memory_order_release);
    }
    arenaHeld[slot] = true;
    current.base = arenas[slot].load(std::memory_order_relaxed);
    current.used = 0;
    current.slot = slot;
}

}  // namespace

void scratchTouch() noexcept {
    if constexpr (kScratchArenas) {
        thread_local Release release;
        (void)release;
    }
}

void* scratchAllocate(std::size_t bytes, std::size_t align) noexcept {
    if constexpr (!kScratchArenas) return nullptr;
    if (!current.base) {
        if (current.tried) return nullptr;
        scratchTouch();
        takeArena();
        if (!current.base) return nullptr;
    }
    (void)align;  // At most kBlockAlign, which every block has.
    const std::size_t start = (current.used + kBlockAlign - 1) & ~(kBlockAlign - 1);
    if (bytes > kScratchArenaBytes - start) return nullptr;
    current.used = start + bytes;
    return current.base + start;
}

bool scratchOwns(const void* p) noexcept {
    if constexpr (!kScratchArenas) return false;
    const auto at = reinterpret_cast<std::uintptr_t>(p);
    auto inside = [at](const char* base) {
        const auto lo = reinterpret_cast<std::uintptr_t>(base);
        return base && lo <= at && at - lo < kScratchArenaBytes;
    };
    if (inside(current.base)) return true;  // The common case: the thread's own arena.
    const std::size_t made = arenaCount.load(std::memory_order_acquire);
    for (std::size_t i = 0; i < made; ++i)
        if (inside(arenas[i].load(std::memory_order_acquire))) return true;
    return false;
}

std::size_t scratchBytesUsed() noexcept {
    return current.base ? current.used : 0;
}

}  // namespace rs
