#ifndef EDYN_SRC_SIMULATION_SIMULATION_WORKER_HPP
#define EDYN_SRC_SIMULATION_SIMULATION_WORKER_HPP

#include "async_protocol.hpp"
#include "edyn/ecs/registry.hpp"
#include <condition_variable>
#include <cstdint>
#include <functional>
#include <mutex>
#include <optional>
#include <thread>
#include <vector>

namespace edyn {

// The worker's side: its registry (attached in sequential mode), the map from main entities to
// its own, and the message being filled. Only the worker thread touches it once it runs.
struct worker_context {
    registry reg;
    entity_map to_worker;      // main entity -> worker entity
    std::vector<entity> slept; // worker entities that fell asleep since the last message
    std::vector<entity> fixed; // worker entities made static since the last message
    worker_message message;
    // Hands a finished message to the main side (set by simulation_worker).
    std::function<void(worker_message &&)> publish;
    std::uint64_t ops_applied{0};
    // Whether collision events are recorded and sent (only while the main side listens).
    bool sends_events{false};

    worker_context();
    worker_context(const worker_context &) = delete;
    worker_context &operator=(const worker_context &) = delete;

    // The worker entity for main entity `main`, made (and tagged with remote_entity) if there
    // is none yet.
    entity local(entity main);
    // The worker entity for `main`, or null.
    entity find(entity main) const noexcept;
    // The main entity a worker entity stands for, or null.
    entity main_of(entity worker) const noexcept;

    // Runs the steps due at the caller's `time`, one message each, and records where the
    // present lies between the last two.
    void advance(double time);
    // Runs one step now, paused or not.
    void step_once();
    // Hands the message being filled over, if it holds anything.
    void finish_message();
    // Starts or stops recording collision events for the main side.
    void send_events(bool on);

private:
    // Runs a step, keeping what its callbacks changed of the settings and what it threw.
    void run_one_step();
    // Sends the step just run: `motion` sends every awake body's motion, `contacts` (the
    // batch's last step) every awake manifold and constraint, and the present's fraction: 1 for
    // a `single` step, else what the clock leaves after the step.
    void send_step(bool motion, bool contacts, bool single);
    void snapshot_motion();
    void snapshot_contacts();
};

// The thread of execution_mode::asynchronous. The main thread sends batches of operations and
// takes messages back; neither ever waits for the other, except in wait().
class simulation_worker {
public:
    simulation_worker();
    // Stops the thread (dropping operations not yet applied) and joins it.
    ~simulation_worker();
    simulation_worker(const simulation_worker &) = delete;
    simulation_worker &operator=(const simulation_worker &) = delete;

    // Queues `ops` (emptying it) as one batch, and, with `time`, asks for the steps due at that
    // time to run after them; returns the batch's number. Batches that wait while the worker is
    // busy are applied together, and only the latest time is stepped to: a worker that falls
    // behind drops time (at most max_steps_per_update steps) as the sequential mode does,
    // rather than queueing ever more work.
    std::uint64_t send(std::vector<worker_op> &ops, std::optional<double> time = std::nullopt);
    // The messages finished so far, oldest first.
    std::vector<worker_message> receive();
    // Blocks until batch `batch` has been applied and its messages are ready.
    void wait(std::uint64_t batch);

private:
    void run();

    std::mutex mutex;
    std::condition_variable work_arrived;
    std::condition_variable batch_done;
    std::vector<worker_op> inbox;
    std::optional<double> target_time;
    std::vector<worker_message> outbox;
    std::uint64_t batches_sent{0};
    std::uint64_t batches_done{0};
    bool stopping{false};
    worker_context context;
    std::thread thread;
};

} // namespace edyn

#endif // EDYN_SRC_SIMULATION_SIMULATION_WORKER_HPP
