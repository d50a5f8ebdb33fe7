#ifndef EDYN_PARALLEL_BACKGROUND_JOB_HPP
#define EDYN_PARALLEL_BACKGROUND_JOB_HPP

#include <condition_variable>
#include <functional>
#include <mutex>
#include <thread>

namespace edyn {

// One piece of work at a time run on a thread of its own while the caller goes on (a networked
// client's extrapolation): start it, poll finished(), read what it wrote once finished. The
// thread is made with the job and kept for every run; the destructor waits for the current run.
// Whatever the function writes belongs to it until finished() returns true.
class background_job {
public:
    background_job();
    ~background_job();
    background_job(const background_job &) = delete;
    background_job &operator=(const background_job &) = delete;

    // Runs `fn` on the job's thread. Throws std::logic_error while a run is in progress. `fn`
    // must not throw: it has no caller to throw to (an exception escaping it ends the program).
    void start(std::function<void()> fn);
    // Whether a run was started and has finished (its writes are visible to the caller then).
    // False again after the next start.
    bool finished();
    // Whether a run is in progress.
    bool busy();
    // Blocks until the run in progress, if any, has finished.
    void wait();

private:
    void loop();

    std::mutex mutex;
    std::condition_variable cv;
    std::function<void()> work;
    bool has_work{false};
    bool is_busy{false};
    bool has_finished{false};
    bool stopping{false};
    std::thread thread;
};

} // namespace edyn

#endif // EDYN_PARALLEL_BACKGROUND_JOB_HPP
