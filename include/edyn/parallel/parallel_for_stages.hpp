#ifndef EDYN_PARALLEL_PARALLEL_FOR_STAGES_HPP
#define EDYN_PARALLEL_PARALLEL_FOR_STAGES_HPP

#include "edyn/parallel/parallel_for.hpp"
#include "edyn/parallel/task_scheduler.hpp"
#include <algorithm>
#include <atomic>
#include <cstdint>
#include <exception>
#include <memory>
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

/// What the threads of a parallel_for_stages call share: which blocks are claimed and how many
/// of each stage are done. Kept by the caller from call to call (one per sequence of calls that
/// never overlap), so that a call allocates nothing once it has seen as many blocks and stages.
class stage_sync {
public:
    /// Empty: the first call allocates what it needs.
    stage_sync() = default;
    /// Moves the state; `other` must not be in use by a call.
    stage_sync(stage_sync &&other) noexcept = default;
    /// Moves the state; neither may be in use by a call.
    /// @return This.
    stage_sync &operator=(stage_sync &&other) noexcept = default;

private:
    template<typename Fn>
    friend void parallel_for_stages(task_scheduler *, stage_sync &, std::span<const std::uint32_t>, Fn &&);

    // Blocks done in one stage; a cache line each, as the stage's threads add to it while the
    // next stage's wait on it.
    struct alignas(64) stage_count {
        std::atomic<std::uint32_t> done{0};
    };

    // Readies the state for a call with these many blocks and stages: a block is claimed in
    // this call when its entry holds `call`.
    void begin(std::size_t num_blocks, std::size_t num_stages) {
        if (num_blocks > block_capacity) {
            claimed = std::make_unique<std::atomic<std::uint32_t>[]>(num_blocks);
            block_capacity = num_blocks;
            call = 0;
        }
        if (num_stages > stage_capacity) {
            stages = std::make_unique<stage_count[]>(num_stages);
            stage_capacity = num_stages;
        }
        if (++call == 0) {
            // After 2^32 calls the numbers come round: a stale entry must not read as claimed.
            for (std::size_t b = 0; b < block_capacity; ++b)
                claimed[b].store(0, std::memory_order_relaxed);
            call = 1;
        }
        for (std::size_t k = 0; k < num_stages; ++k)
            stages[k].done.store(0, std::memory_order_relaxed);
    }

    // Whether this thread takes block b: the first to ask does.
    bool claim(std::uint32_t b) noexcept {
        return claimed[b].load(std::memory_order_relaxed) != call &&
               claimed[b].exchange(call, std::memory_order_relaxed) != call;
    }

    std::unique_ptr<std::atomic<std::uint32_t>[]> claimed;
    std::unique_ptr<stage_count[]> stages;
    std::size_t block_capacity{0}, stage_capacity{0};
    std::uint32_t call{0};
};

/// Runs `fn(stage, block)` for every block of every stage, stage after stage: the blocks of
/// stage k are [stage_begin[k], stage_begin[k + 1]) and run at once on the scheduler's threads,
/// each only once every block of the earlier stages is done (the colours of a solver pass, for
/// one).
///
/// All the stages are one task, so they cost one hand-over to the scheduler, not one each. Each
/// of its threads goes through every stage: it waits until the stage before is done, then takes
/// every block of this stage that no thread has taken yet, starting from its own place in the
/// stage (thread t of T at t/T of the way through it, so that the threads seldom ask for the
/// same block), and adds how many it ran to the stage's count once it has run them. A thread
/// runs a block as soon as it takes it and a stage is waited for only once all its blocks are
/// taken, so a thread only ever waits for blocks that running threads hold: the stages cannot
/// stall, however few of the task's ranges the scheduler runs at once. Consecutive stages of one
/// block each are taken as one: the thread that takes the first block runs all of them in order,
/// and the others wait for the last. Without a scheduler, with one thread, with a single block or
/// with no stage of two blocks or more, the blocks run in order on the calling thread.
/// @param scheduler Threads to spread each stage over; may be null.
/// @param sync State the call's threads share, reused from call to call; calls that share one
///        must not overlap.
/// @param stage_begin The first block of each stage, then one past the last block:
///        non-decreasing.
/// @param fn Called as fn(std::size_t stage, std::uint32_t block). It may throw: every other
///        block still runs, then the first exception is rethrown in the calling thread.
template<typename Fn>
void parallel_for_stages(task_scheduler *scheduler, stage_sync &sync,
                         std::span<const std::uint32_t> stage_begin, Fn &&fn) {
    if (stage_begin.size() < 2) return;
    auto num_blocks = stage_begin.back();
    auto num_stages = stage_begin.size() - 1;
    std::atomic<bool> failed{false};
    std::exception_ptr error;
    auto run = [&](std::size_t k, std::uint32_t b) {
        try {
            fn(k, b);
        } catch (...) {
            if (!failed.exchange(true)) error = std::current_exception();
        }
    };

    // Stage k is one of a run of stages of one block each (empty stages within the run aside):
    // such a run goes to one thread as a whole, its blocks in order, since handing each block of
    // it to the next thread would cost more than the block (a chain's joints, one colour each;
    // the last, smallest colours of a pass). Returns the run's last stage with a block, or k when
    // stage k has more blocks or the stage after it does.
    auto run_end = [&](std::size_t k) {
        auto last = k;
        for (auto next = k + 1; next < num_stages && stage_begin[next + 1] - stage_begin[next] <= 1; ++next) {
            if (stage_begin[next + 1] > stage_begin[next]) last = next;
        }
        return last;
    };

    auto threads = scheduler ? scheduler->concurrency() : 1u;
    // When no stage has two blocks, the whole call is one such run: it stays on this thread.
    auto widest = std::uint32_t(0);
    for (std::size_t k = 0; k < num_stages && widest < 2; ++k)
        widest = std::max(widest, stage_begin[k + 1] - stage_begin[k]);
    if (threads < 2 || num_blocks < 2 || widest < 2) {
        for (std::size_t k = 0; k < num_stages; ++k) {
            for (auto b = stage_begin[k]; b < stage_begin[k + 1]; ++b)
                run(k, b);
        }
        if (error) std::rethrow_exception(error);
        return;
    }

    sync.begin(num_blocks, num_stages);
    parallel_for(*scheduler, 0u, threads, 1, [&](std::uint32_t t) {
        // The last stage with blocks: once those are done, so are all before it.
        std::size_t before = num_stages;
        for (std::size_t k = 0; k < num_stages; ++k) {
            auto first = stage_begin[k], count = stage_begin[k + 1] - first;
            if (count == 0) continue;
            if (before < num_stages) {
                detail::wait_until(sync.stages[before].done, stage_begin[before + 1] - stage_begin[before]);
            }
            if (count == 1) {
                auto last = run_end(k);
                // The thread that takes the run's first block runs the whole run; the others go
                // on to wait for its last stage.
                if (sync.claim(first)) {
                    for (auto s = k; s <= last; ++s) {
                        for (auto b = stage_begin[s]; b < stage_begin[s + 1]; ++b)
                            run(s, b);
                    }
                    sync.stages[last].done.fetch_add(1, std::memory_order_release);
                }
                before = last;
                k = last;
                continue;
            }
            before = k;
            auto start = static_cast<std::uint32_t>(std::uint64_t(count) * t / threads);
            std::uint32_t ran = 0;
            for (std::uint32_t i = 0; i < count; ++i) {
                auto b = first + (start + i) % count;
                if (!sync.claim(b)) continue;
                run(k, b);
                ++ran;
            }
            if (ran > 0) sync.stages[k].done.fetch_add(ran, std::memory_order_release);
        }
    });
    if (error) std::rethrow_exception(error);
}

} // namespace edyn

#endif // EDYN_PARALLEL_PARALLEL_FOR_STAGES_HPP
