#ifndef EDYN_PARALLEL_BACKGROUND_JOB_HPP
#define EDYN_PARALLEL_BACKGROUND_JOB_HPP

#include <condition_variable>
#include <functional>
#include <mutex>
#include <thread>

namespace edyn {

/// One piece of work at a time run on a thread of its own while the caller goes on (a networked
/// client's extrapolation): start it, poll finished(), read what it wrote once finished.
///
/// The thread is made with the job and kept for every run; the destructor waits for the current
/// run. Whatever the function writes belongs to it until finished() returns true. The member
/// functions may be called from any thread.
class background_job {
public:
    /// Starts the job's thread, idle until `start`.
    background_job();
    /// Waits for the run in progress, if any, then stops and joins the thread.
    ~background_job();
    background_job(const background_job &) = delete;
    background_job &operator=(const background_job &) = delete;

    /// Runs `fn` on the job's thread and returns at once. `fn` must not throw: it has no caller
    /// to throw to (an exception escaping it ends the program).
    /// @param fn The work to run.
    /// @throws std::logic_error While a run is in progress.
    void start(std::function<void()> fn);
    /// Whether a run was started and has finished (its writes are visible to the caller then).
    /// False again after the next start.
    /// @return True once the last started run has finished.
    bool finished();
    /// Whether a run is in progress.
    /// @return True from `start` until the run returns.
    bool busy();
    /// Blocks until the run in progress, if any, has finished.
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
