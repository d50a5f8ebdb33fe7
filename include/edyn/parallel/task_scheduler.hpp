#ifndef EDYN_PARALLEL_TASK_SCHEDULER_HPP
#define EDYN_PARALLEL_TASK_SCHEDULER_HPP

#include <cstddef>
#include <memory>

namespace edyn {

/// A ranged task: processes the items [begin, end) of the work described by `context`. It may
/// be called from any thread, several ranges at once.
using task_function = void (*)(void *context, std::size_t begin, std::size_t end);

/// How a program hands edyn's parallel work to its own scheduler, as game engines that own their
/// worker threads need; given to `init_config::scheduler` or to `task_scheduler`'s constructor.
///
/// `enqueue` starts running `fn` over [0, count), split into ranges of at least `grain` items
/// that may run at once on any threads (the caller's included), and returns a handle; `wait`
/// blocks until every range of the task behind that handle has run. `enqueue` may also run the
/// whole task before returning, and return any handle. `user` is passed back to both. Both
/// hooks must be set and `concurrency` must be at least 1, or `task_scheduler` throws.
struct task_hooks {
    /// Starts running `fn(context, begin, end)` over [0, count) in ranges of at least `grain`
    /// items and returns a handle for `wait`. Required (null by default).
    void *(*enqueue)(task_function fn, void *context, std::size_t count, std::size_t grain,
                     void *user){nullptr};
    /// Blocks until every range of the task behind `handle` has run. Required (null by default).
    void (*wait)(void *handle, void *user){nullptr};
    /// Passed back unchanged to `enqueue` and `wait`, for example the program's scheduler object.
    /// May be null (the default).
    void *user{nullptr};
    /// Threads that run tasks at once, the caller's included (a hint for splitting work); at
    /// least 1 (the default).
    unsigned concurrency{1};
};

/// Runs ranged tasks on worker threads: on a oneTBB task arena of its own by default, or through
/// a program's task_hooks. Threads are created once, with the scheduler, never per task.
///
/// The world makes one in the `sequential_multithreaded` execution mode only (from
/// `init_config::scheduler` or `init_config::num_worker_threads`); `parallel_for` spreads loops
/// over it.
class task_scheduler {
public:
    /// A oneTBB arena of `num_threads` threads, the caller's included.
    /// @param num_threads Number of threads; 0 means one per hardware thread. Bounded here only by
    /// what oneTBB can take, INT_MAX (`init_config::num_worker_threads` is bounded tighter, at
    /// `init_config::max_worker_threads`).
    /// @throws std::invalid_argument If `num_threads` is above INT_MAX.
    explicit task_scheduler(unsigned num_threads = 0);
    /// A scheduler that hands its work to the program's own scheduler.
    /// @param hooks The program's hooks, copied.
    /// @throws std::invalid_argument If `hooks.enqueue` or `hooks.wait` is null or
    /// `hooks.concurrency` is 0.
    explicit task_scheduler(const task_hooks &hooks);
    /// Releases the arena's threads; no task may be running.
    ~task_scheduler();
    task_scheduler(const task_scheduler &) = delete;
    task_scheduler &operator=(const task_scheduler &) = delete;

    /// Threads that may run a task's ranges at once.
    /// @return The arena's concurrency, or `task_hooks::concurrency`; at least 1.
    unsigned concurrency() const noexcept;

    /// Runs `fn` over [0, count) in ranges of `grain` items (the default scheduler cuts exactly
    /// that, the last range shorter; a program's hooks may cut otherwise) and returns when all
    /// have run. The ranges may run in any order and on any threads: `fn` must write only what
    /// its items own, and must not throw (`parallel_for` catches for it).
    /// @param fn The ranged task.
    /// @param context Passed to every call of `fn`.
    /// @param count Number of items; 0 returns at once.
    /// @param grain Items per range; 0 is taken as 1.
    void run(task_function fn, void *context, std::size_t count, std::size_t grain);

private:
    struct arena;
    std::unique_ptr<arena> default_arena;
    task_hooks hooks;
};

} // namespace edyn

#endif // EDYN_PARALLEL_TASK_SCHEDULER_HPP
