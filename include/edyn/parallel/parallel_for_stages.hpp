#ifndef EDYN_PARALLEL_PARALLEL_FOR_STAGES_HPP
#define EDYN_PARALLEL_PARALLEL_FOR_STAGES_HPP

#include "edyn/parallel/parallel_for.hpp"
#include "edyn/parallel/task_scheduler.hpp"
#include <atomic>
#include <cstdint>
#include <exception>
#include <span>
#include <thread>
#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace edyn {

namespace detail {

// Spins until `done` reaches `target`, yielding the thread after a while.
inline void wait_until(const std::atomic<std::uint32_t> &done, std::uint32_t target) {
    for (unsigned spins = 0; done.load(std::memory_order_acquire) < target; ++spins) {
        if (spins < 256) {
#if defined(__SSE2__)
            _mm_pause();
#endif
        } else {
            std::this_thread::yield();
        }
    }
}

} // namespace detail

/// Runs `fn(stage, block)` for every block of every stage, stage after stage: the blocks of
/// stage k are [stage_begin[k], stage_begin[k + 1]) and run at once on the scheduler's threads,
/// each only once every block of the earlier stages is done (the colours of a solver pass, for
/// one).
///
/// All the stages are one task, so they cost one hand-over to the scheduler, not one each: each
/// of its threads claims the next block, in order, and waits before running it until the earlier
/// stages' blocks are done. Blocks are claimed in order, so a thread only ever waits for blocks
/// that running threads hold: the stages cannot stall, however few of the task's ranges the
/// scheduler runs at once. Without a scheduler, with one thread or with a single block, the
/// blocks run in order on the calling thread.
/// @param scheduler Threads to spread each stage over; may be null.
/// @param stage_begin The first block of each stage, then one past the last block:
///        non-decreasing.
/// @param fn Called as fn(std::size_t stage, std::uint32_t block). It may throw: every other
///        block still runs, then the first exception is rethrown in the calling thread.
template<typename Fn>
void parallel_for_stages(task_scheduler *scheduler, std::span<const std::uint32_t> stage_begin, Fn &&fn) {
    if (stage_begin.size() < 2) return;
    auto num_blocks = stage_begin.back();
    std::atomic<bool> failed{false};
    std::exception_ptr error;
    auto run = [&](std::size_t k, std::uint32_t b) {
        try {
            fn(k, b);
        } catch (...) {
            if (!failed.exchange(true)) error = std::current_exception();
        }
    };

    auto threads = scheduler ? scheduler->concurrency() : 1u;
    if (threads < 2 || num_blocks < 2) {
        for (std::size_t k = 0; k + 1 < stage_begin.size(); ++k) {
            for (auto b = stage_begin[k]; b < stage_begin[k + 1]; ++b)
                run(k, b);
        }
        if (error) std::rethrow_exception(error);
        return;
    }

    std::atomic<std::uint32_t> next_block{0}, blocks_done{0};
    parallel_for(*scheduler, 0u, threads, 1, [&](std::uint32_t) {
        std::size_t k = 0;
        for (auto b = next_block.fetch_add(1, std::memory_order_relaxed); b < num_blocks;
             b = next_block.fetch_add(1, std::memory_order_relaxed)) {
            while (stage_begin[k + 1] <= b)
                ++k;
            detail::wait_until(blocks_done, stage_begin[k]);
            run(k, b);
            blocks_done.fetch_add(1, std::memory_order_release);
        }
    });
    if (error) std::rethrow_exception(error);
}

} // namespace edyn

#endif // EDYN_PARALLEL_PARALLEL_FOR_STAGES_HPP
