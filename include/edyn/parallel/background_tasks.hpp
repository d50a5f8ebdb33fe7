#ifndef EDYN_PARALLEL_BACKGROUND_TASKS_HPP
#define EDYN_PARALLEL_BACKGROUND_TASKS_HPP

#include "edyn/parallel/background_job.hpp"
#include "edyn/parallel/task_scheduler.hpp"
#include <deque>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <vector>

namespace edyn {

/// Runs tasks that must not hold up their caller (loading the pages of a paged_triangle_mesh),
/// each once, while the caller goes on.
///
/// With a program's task_hooks, every task goes to the program's scheduler as a task of one item
/// (`enqueue(fn, context, 1, 1, user)`), and its handle is given back to `wait` once the task has
/// run: the program sees and runs all of edyn's background work. Without hooks, the tasks run one
/// after another, in the order posted, on a background_job whose thread is made when the first
/// task is posted (a world that posts nothing makes no thread).
///
/// A task tells its poster that it ran through what it writes, under its own synchronisation.
/// post() and release_finished() are called by one thread at a time, the owner's; tasks run on
/// other threads, or inside `enqueue` when a program's scheduler runs them there.
class background_tasks {
public:
    /// Tasks run on a thread of the parallel layer's own (a background_job), made on first use.
    background_tasks();
    /// Tasks go to the program's scheduler.
    /// @param hooks The program's hooks, copied.
    /// @throws std::invalid_argument If `hooks.enqueue` or `hooks.wait` is null.
    explicit background_tasks(const task_hooks &hooks);
    /// Waits until every posted task has run (and, with hooks, hands every handle to `wait`).
    ~background_tasks();
    background_tasks(const background_tasks &) = delete;
    background_tasks &operator=(const background_tasks &) = delete;

    /// Starts `task` in the background and returns at once (or once it ran, when a program's
    /// `enqueue` runs it before returning). `task` must not throw: it has no caller to throw to.
    /// @param task The work to run, once.
    void post(std::function<void()> task);
    /// With hooks, hands the handles of the tasks that have run to the program's `wait`, so that
    /// its scheduler may release them; does nothing otherwise. post() does it too; call it now
    /// and then when posting stops for a while (the step does, every step).
    void release_finished();
    /// Whether the tasks go to a program's scheduler.
    /// @return True when made with task_hooks.
    bool uses_program_scheduler() const noexcept { return hooks.has_value(); }

private:
    struct hooked_task;

    void drain();

    std::optional<task_hooks> hooks;
    // With hooks: the tasks enqueued whose handles have not been waited for yet.
    std::vector<std::unique_ptr<hooked_task>> enqueued;

    // Without hooks: tasks waiting for the job's thread, which drains them in order.
    std::mutex mutex;
    std::deque<std::function<void()>> queue;
    bool draining{false};
    std::unique_ptr<background_job> job;
};

} // namespace edyn

#endif // EDYN_PARALLEL_BACKGROUND_TASKS_HPP
