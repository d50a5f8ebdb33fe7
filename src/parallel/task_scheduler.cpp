#include "edyn/parallel/task_scheduler.hpp"
#include "thread_pool.hpp"
#include <algorithm>
#include <limits>
#include <stdexcept>
#include <string>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#if defined(__SANITIZE_THREAD__)
#define EDYN_THREAD_SANITIZER 1
#elif defined(__has_feature)
#if __has_feature(thread_sanitizer)
#define EDYN_THREAD_SANITIZER 1
#endif
#endif

namespace edyn {

namespace {

// The default scheduler runs the whole task before enqueue returns, the caller's thread taking
// part, so that there is nothing left to wait for.
void nothing_to_wait_for(void *, void *) {}

#ifdef EDYN_THREAD_SANITIZER

void *pool_enqueue(task_function fn, void *context, std::size_t count, std::size_t grain, void *user) {
    static_cast<thread_pool *>(user)->run(fn, context, count, grain);
    return nullptr;
}

} // namespace

struct task_scheduler::arena {
    thread_pool pool;
    explicit arena(int threads)
        : pool(unsigned(threads)) {}
    task_hooks hooks() { return {&pool_enqueue, &nothing_to_wait_for, &pool, pool.concurrency()}; }
};

#else

// The task is cut into ranges of exactly `grain` items (the last may be shorter): the same cuts
// whatever the thread count.
void *arena_enqueue(task_function fn, void *context, std::size_t count, std::size_t grain, void *user) {
    auto &arena = *static_cast<tbb::task_arena *>(user);
    auto num_ranges = (count + grain - 1) / grain;
    arena.execute([&] {
        tbb::parallel_for(
            tbb::blocked_range<std::size_t>(0, num_ranges, 1),
            [&](const tbb::blocked_range<std::size_t> &ranges) {
                for (auto r = ranges.begin(); r < ranges.end(); ++r)
                    fn(context, r * grain, std::min((r + 1) * grain, count));
            },
            tbb::simple_partitioner{});
    });
    return nullptr;
}

} // namespace

struct task_scheduler::arena {
    tbb::task_arena tbb_arena;
    explicit arena(int threads)
        : tbb_arena(threads) {
        tbb_arena.initialize();
    }
    task_hooks hooks() {
        return {&arena_enqueue, &nothing_to_wait_for, &tbb_arena, unsigned(tbb_arena.max_concurrency())};
    }
};

#endif

task_scheduler::task_scheduler(unsigned num_threads) {
    // oneTBB takes an int: a larger count would wrap to a negative one.
    if (num_threads > unsigned(std::numeric_limits<int>::max()))
        throw std::invalid_argument("task_scheduler: num_threads must be at most " +
                                    std::to_string(std::numeric_limits<int>::max()) + ", got " +
                                    std::to_string(num_threads));
    auto threads = num_threads == 0 ? tbb::info::default_concurrency() : int(num_threads);
    default_arena = std::make_unique<arena>(threads);
    hooks = default_arena->hooks();
}

task_scheduler::task_scheduler(const task_hooks &program_hooks)
    : hooks(program_hooks) {
    if (!hooks.enqueue) throw std::invalid_argument("task_scheduler: task_hooks::enqueue is null");
    if (!hooks.wait) throw std::invalid_argument("task_scheduler: task_hooks::wait is null");
    if (hooks.concurrency == 0) throw std::invalid_argument("task_scheduler: task_hooks::concurrency is 0");
}

task_scheduler::~task_scheduler() = default;

unsigned task_scheduler::concurrency() const noexcept { return hooks.concurrency; }

void task_scheduler::run(task_function fn, void *context, std::size_t count, std::size_t grain) {
    if (count == 0) return;
    auto *handle = hooks.enqueue(fn, context, count, grain == 0 ? 1 : grain, hooks.user);
    hooks.wait(handle, hooks.user);
}

} // namespace edyn
