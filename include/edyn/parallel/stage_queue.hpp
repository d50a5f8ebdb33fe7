#ifndef EDYN_PARALLEL_STAGE_QUEUE_HPP
#define EDYN_PARALLEL_STAGE_QUEUE_HPP

#include "edyn/parallel/parallel_for_stages.hpp"
#include "edyn/parallel/task_scheduler.hpp"
#include <cstddef>
#include <cstdint>
#include <new>
#include <stdexcept>
#include <type_traits>
#include <vector>

namespace edyn {

/// Stages queued one after another, then run together as one parallel_for_stages task: a
/// solver's passes, each a stage or a colour's worth of them, cost one hand-over to the
/// scheduler for the whole sequence instead of one each.
///
/// A stage is a number of blocks and a function called once per block, fn(block) for block in
/// [0, blocks); the blocks of one stage may run at once on different threads, and a stage starts
/// only once every block of the stages before it is done. The queue keeps a copy of each
/// function, which must therefore be trivially copyable: capture by value, or by reference only
/// what outlives run(). Nothing is allocated once the queue has held as many stages as it holds
/// now.
///
/// One queue is used by one thread at a time.
class stage_queue {
public:
    /// Appends a stage of `blocks` blocks; one of no blocks is left out.
    /// @param blocks Number of blocks.
    /// @param fn Called as fn(std::uint32_t block) for every block, when run() runs the stage.
    template<typename Fn>
    void add(std::uint32_t blocks, const Fn &fn) {
        static_assert(std::is_trivially_copyable_v<Fn> && std::is_trivially_destructible_v<Fn>,
                      "stage_queue keeps a byte copy of each stage's function");
        static_assert(alignof(Fn) <= alignof(slot), "stage function over-aligned");
        if (blocks == 0) return;
        if (block_begin.empty()) block_begin.push_back(0); // moved from
        auto first = storage.size();
        storage.resize(first + (sizeof(Fn) + sizeof(slot) - 1) / sizeof(slot));
        ::new (static_cast<void *>(&storage[first])) Fn(fn);
        stages.push_back({&call<Fn>, first});
        block_begin.push_back(block_begin.back() + blocks);
    }

    /// Appends a stage that calls fn(i) for every i in [first, last), in blocks of `grain`
    /// indices (the last may have fewer); an empty range adds nothing.
    /// @param first First index.
    /// @param last One past the last index.
    /// @param grain Indices per block, at least 1.
    /// @param fn Called as fn(std::uint32_t i); copied into the queue, as add() says.
    /// @throws std::invalid_argument If grain is 0.
    template<typename Fn>
    void add_for(std::uint32_t first, std::uint32_t last, std::uint32_t grain, const Fn &fn) {
        if (grain == 0) throw std::invalid_argument("stage_queue::add_for: grain must be at least 1, not 0");
        if (last <= first) return;
        add((last - first - 1) / grain + 1, [first, last, grain, fn](std::uint32_t block) {
            auto begin = first + block * grain;
            auto end = last - begin < grain ? last : begin + grain;
            for (auto i = begin; i < end; ++i)
                fn(i);
        });
    }

    /// Whether no stage is queued.
    /// @return True if run() would do nothing.
    bool empty() const noexcept { return stages.empty(); }

    /// Runs every queued stage in order, each spread over the scheduler's threads, then empties
    /// the queue (keeping its capacity). Without a scheduler, or with one thread, the blocks run
    /// in order on the calling thread. If a block throws, every other block still runs, the
    /// queue is emptied and the first exception is rethrown here.
    /// @param scheduler Threads to spread the stages over; may be null.
    void run(task_scheduler *scheduler) {
        if (stages.empty()) return;
        struct emptied {
            stage_queue &queue;
            ~emptied() { queue.clear(); }
        } at_end{*this};
        parallel_for_stages(scheduler, sync, block_begin, [this](std::size_t k, std::uint32_t block) {
            auto &s = stages[k];
            s.call(&storage[s.first_slot], block - block_begin[k]);
        });
    }

    /// Drops every queued stage without running it, keeping the capacity.
    void clear() noexcept {
        stages.clear();
        storage.clear();
        block_begin.resize(1);
    }

private:
    // Storage unit of the functions' copies, aligned for any of them.
    struct alignas(std::max_align_t) slot {
        std::byte bytes[alignof(std::max_align_t)];
    };

    struct stage {
        void (*call)(const void *fn, std::uint32_t block);
        std::size_t first_slot;
    };

    template<typename Fn>
    static void call(const void *fn, std::uint32_t block) {
        (*std::launder(static_cast<const Fn *>(fn)))(block);
    }

    std::vector<stage> stages;
    std::vector<slot> storage;
    std::vector<std::uint32_t> block_begin{0};
    stage_sync sync;
};

} // namespace edyn

#endif // EDYN_PARALLEL_STAGE_QUEUE_HPP
