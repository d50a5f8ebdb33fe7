#ifndef EDYN_PARALLEL_TASK_SCHEDULER_HPP
#define EDYN_PARALLEL_TASK_SCHEDULER_HPP

#include <cstddef>
#include <memory>

namespace edyn {

// A ranged task: processes the items [begin, end) of the work described by `context`.
using task_function = void (*)(void *context, std::size_t begin, std::size_t end);

// How a program hands edyn's parallel work to its own scheduler, as game engines that own their
// worker threads need. `enqueue` starts running `fn` over [0, count), split into ranges of at
// least `grain` items that may run at once on any threads (the caller's included), and returns a
// handle; `wait` blocks until every range of the task behind that handle has run. `enqueue` may
// also run the whole task before returning, and return any handle. `user` is passed back to both.
struct task_hooks {
    void *(*enqueue)(task_function fn, void *context, std::size_t count, std::size_t grain,
                     void *user){nullptr};
    void (*wait)(void *handle, void *user){nullptr};
    void *user{nullptr};
    // Threads that run tasks at once, the caller's included (a hint for splitting work).
    unsigned concurrency{1};
};

// Runs ranged tasks on worker threads: on a oneTBB task arena of its own by default, or through a
// program's task_hooks. Threads are created once, with the scheduler, never per task.
class task_scheduler {
public:
    // A oneTBB arena of `num_threads` threads, the caller's included; 0 means one per hardware
    // thread.
    explicit task_scheduler(unsigned num_threads = 0);
    // The program's scheduler. Throws std::invalid_argument if a hook is missing or concurrency is 0.
    explicit task_scheduler(const task_hooks &hooks);
    ~task_scheduler();
    task_scheduler(const task_scheduler &) = delete;
    task_scheduler &operator=(const task_scheduler &) = delete;

    // Threads that may run a task's ranges at once.
    unsigned concurrency() const noexcept;

    // Runs fn over [0, count) in ranges of `grain` items (the default scheduler cuts exactly
    // that, the last range shorter; a program's hooks may cut otherwise) and returns when all
    // have run. The ranges may run in any order and on any threads: fn must write only what its
    // items own, and must not throw (parallel_for catches for it).
    void run(task_function fn, void *context, std::size_t count, std::size_t grain);

private:
    struct arena;
    std::unique_ptr<arena> default_arena;
    task_hooks hooks;
};

} // namespace edyn

#endif // EDYN_PARALLEL_TASK_SCHEDULER_HPP
