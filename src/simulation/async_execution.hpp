#ifndef EDYN_SRC_SIMULATION_ASYNC_EXECUTION_HPP
#define EDYN_SRC_SIMULATION_ASYNC_EXECUTION_HPP

#include "async_protocol.hpp"
#include "edyn/dynamics/material_mixing.hpp"
#include "edyn/ecs/registry.hpp"
#include "edyn/simulation/replication.hpp"
#include <cstdint>
#include <exception>
#include <memory>
#include <optional>
#include <vector>

namespace edyn {

class simulation_worker;

// The main registry's side of execution_mode::asynchronous, in its context: the worker, the
// operations waiting to be sent, and what the main side needs to apply the worker's messages.
//
// Main -> worker: every change to a replicated component (edyn's own, and those registered
// with register_external_components) of an entity the worker has is queued as an operation;
// update() sends the queue, the settings and the time to advance to as one batch.
// Worker -> main: update() applies the messages finished since the last call, without waiting:
// manifolds made and destroyed, collision events, body motion, sleeping, replies to queries.
// The present transforms are interpolated as the sequential mode would have one update earlier.
class async_execution final : public detail::replication_sink {
public:
    explicit async_execution(registry &registry);
    ~async_execution() override;

    // Sends the bodies, constraints and external entities made before attach() (once this
    // object is in the registry's context, where the listeners find it).
    void adopt_existing(registry &registry);

    void update(registry &registry, double time);
    void step_simulation(registry &registry);
    // Sends what is queued, waits until the worker has applied it and applies its messages.
    void wait(registry &registry);
    // Queues an operation made by the main side (not tied to one entity).
    void push(worker_op op);
    // Queues set_gravity for the worker: it wakes the worker's resting bodies at every call, as
    // it does in the other modes, even when the gravity ends up as it was.
    void push_gravity(const vector3 &gravity);
    // Queues `call` to run in the worker on main entity e's worker entity, if it has one.
    // `sets`: the parts of the entity's motion the call sets.
    void push_call(entity e, std::function<void(registry &, entity)> call, motion_parts sets);

    void add_type(registry &registry, const detail::replicated_type &type);
    // Stops the listeners (detach).
    void disconnect(registry &registry);

    bool accepts(registry &registry, entity e, bool edyn_component) override;
    void send(entity e, std::function<void(registry &, entity, const std::function<entity(entity)> &)> apply,
              motion_parts sets) override;

private:
    void send_batch(registry &registry, worker_op last, std::optional<double> time = std::nullopt);
    void apply_messages(registry &registry);
    // `motion` and `contacts`: whether to apply the message's body motion, and its manifolds and
    // constraints (skipped when later messages of the same update carry newer ones).
    void apply(registry &registry, worker_message &message, bool motion, bool contacts);
    void apply_records(registry &registry, const std::vector<worker_record> &records);
    void adopt_controls(registry &registry, const worker_message &message);
    void apply_motion(registry &registry, const std::vector<body_state> &states, std::uint64_t ops_applied);
    void apply_manifolds(registry &registry, const std::vector<std::pair<entity, contact_manifold>> &states);
    template<typename Constraint>
    void apply_constraint_states(registry &registry, const std::vector<std::pair<entity, Constraint>> &states,
                                 std::uint64_t ops_applied);
    void mark_pending(entity e, motion_parts sets);
    // Whether an operation on e came after the first `ops_applied` (any operation, or one that
    // sets the given parts of its motion).
    bool pending_after(entity e, std::uint64_t ops_applied) const noexcept;
    bool pending_after(entity e, std::uint64_t ops_applied, motion_parts part) const noexcept;

    std::unique_ptr<simulation_worker> worker;
    std::vector<worker_op> ops;
    std::uint64_t ops_made{0};
    std::uint64_t last_batch{0};
    entity_map manifolds; // worker manifold -> main manifold
    // The last operation made for each main entity (by index), and the last that set its
    // transform and its velocity, so that motion or a constraint the worker computed before
    // applying them does not overwrite what the program just set. Only the parts the program
    // set wait: a body the program pushes every frame still moves on the main side.
    struct pending_slot {
        entity e{null};
        std::uint64_t seq{0};
        std::uint64_t transform_seq{0};
        std::uint64_t velocity_seq{0};
    };
    std::vector<pending_slot> pending;
    std::vector<detail::replicated_type> types;
    std::vector<detail::replicated_type> external_types;
    std::vector<std::exception_ptr> errors;
    // The material table the worker has, to send it again only when the program changes it.
    std::optional<material_mix_table> sent_table;
    // The settings and pause last sent to the worker (or taken from it), and the operation
    // that sent them.
    std::optional<world_controls> sent_controls;
    std::uint64_t controls_seq{0};
    scalar alpha{1};
};

} // namespace edyn

#endif // EDYN_SRC_SIMULATION_ASYNC_EXECUTION_HPP
