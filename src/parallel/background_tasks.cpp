#include "edyn/parallel/background_tasks.hpp"
#include <atomic>
#include <stdexcept>

namespace edyn {

struct background_tasks::hooked_task {
    std::function<void()> fn;
    void *handle{nullptr};
    // Set once fn has returned: waiting for the handle will not block then.
    std::atomic<bool> finished{false};

    static void run(void *context, std::size_t, std::size_t) {
        auto &task = *static_cast<hooked_task *>(context);
        task.fn();
        task.finished.store(true, std::memory_order_release);
    }
};

background_tasks::background_tasks() = default;

background_tasks::background_tasks(const task_hooks &program_hooks)
    : hooks(program_hooks) {
    if (!hooks->enqueue) throw std::invalid_argument("background_tasks: task_hooks::enqueue is null");
    if (!hooks->wait) throw std::invalid_argument("background_tasks: task_hooks::wait is null");
}

background_tasks::~background_tasks() {
    if (hooks) {
        for (auto &task : enqueued)
            hooks->wait(task->handle, hooks->user);
        return;
    }
    // Nothing is posted any more: the run in progress, if any, drains what is queued.
    if (job) job->wait();
}

void background_tasks::post(std::function<void()> task) {
    if (hooks) {
        release_finished();
        enqueued.push_back(std::make_unique<hooked_task>());
        auto &record = *enqueued.back();
        record.fn = std::move(task);
        record.handle = hooks->enqueue(&hooked_task::run, &record, 1, 1, hooks->user);
        return;
    }
    std::lock_guard lock(mutex);
    queue.push_back(std::move(task));
    if (draining) return;
    draining = true;
    if (!job) job = std::make_unique<background_job>();
    // The last drain cleared `draining` as its final step under the lock; its run may not have
    // returned yet, and a job runs one thing at a time. It needs the lock no more: no deadlock.
    job->wait();
    job->start([this] { drain(); });
}

void background_tasks::release_finished() {
    if (!hooks || enqueued.empty()) return;
    std::erase_if(enqueued, [&](const std::unique_ptr<hooked_task> &task) {
        if (!task->finished.load(std::memory_order_acquire)) return false;
        hooks->wait(task->handle, hooks->user);
        return true;
    });
}

void background_tasks::drain() {
    std::unique_lock lock(mutex);
    while (!queue.empty()) {
        auto task = std::move(queue.front());
        queue.pop_front();
        lock.unlock();
        task();
        lock.lock();
    }
    draining = false;
}

} // namespace edyn
