#include "edyn/parallel/background_job.hpp"
#include <stdexcept>

namespace edyn {

background_job::background_job()
    : thread([this] { loop(); }) {}

background_job::~background_job() {
    {
        auto lock = std::unique_lock(mutex);
        stopping = true;
    }
    cv.notify_all();
    thread.join();
}

void background_job::start(std::function<void()> fn) {
    {
        auto lock = std::unique_lock(mutex);
        if (is_busy) throw std::logic_error("background_job::start: a run is in progress");
        work = std::move(fn);
        has_work = true;
        is_busy = true;
        has_finished = false;
    }
    cv.notify_all();
}

bool background_job::finished() {
    auto lock = std::unique_lock(mutex);
    return has_finished;
}

bool background_job::busy() {
    auto lock = std::unique_lock(mutex);
    return is_busy;
}

void background_job::wait() {
    auto lock = std::unique_lock(mutex);
    cv.wait(lock, [this] { return !is_busy; });
}

void background_job::loop() {
    auto lock = std::unique_lock(mutex);
    while (true) {
        cv.wait(lock, [this] { return has_work || stopping; });
        if (stopping && !has_work) return;
        auto fn = std::move(work);
        has_work = false;
        lock.unlock();
        fn();
        lock.lock();
        is_busy = false;
        has_finished = true;
        cv.notify_all();
    }
}

} // namespace edyn
