#ifndef EDYN_SRC_SIMULATION_ASYNC_PROTOCOL_HPP
#define EDYN_SRC_SIMULATION_ASYNC_PROTOCOL_HPP

// What the main thread and the simulation worker of execution_mode::asynchronous send each
// other. The main thread sends operations (closures run by the worker on its registry, in the
// order they were made); the worker sends one message per step it ran, and one more when a
// batch of operations ends, with what the main registry must learn.

#include "edyn/collision/contact_manifold.hpp"
#include "edyn/constraints/constraints.hpp"
#include "edyn/dynamics/orientation.hpp"
#include "edyn/dynamics/position.hpp"
#include "edyn/dynamics/velocity.hpp"
#include "edyn/ecs/entity_map.hpp"
#include "edyn/ecs/registry.hpp"
#include "edyn/simulation/contact_events.hpp"
#include "edyn/simulation/settings.hpp"
#include <cstdint>
#include <exception>
#include <functional>
#include <optional>
#include <tuple>
#include <vector>

namespace edyn {

// On a worker entity made for a main entity: which one. Its removal (by an operation that
// destroys the entity, or by a step callback) tells the main side the entity is gone.
struct remote_entity {
    entity value;
};

struct worker_context;
using worker_op = std::function<void(worker_context &)>;

// Motion of a body that moved in a step, addressed by its main entity.
struct body_state {
    entity main;
    position pos;
    orientation orn;
    linvel v;
    angvel w;
};

// Something the main side replays in order: a manifold made or destroyed by the worker, a
// collision event (with the manifold as it was when the event fired, so listeners on the main
// thread read the same points the worker's would), or a main entity the worker destroyed.
struct worker_record {
    enum class kind : std::uint8_t { manifold_created, manifold_destroyed, contact_event, entity_destroyed };
    kind type;
    entity worker_entity{null};    // the manifold (worker side)
    entity main_entity{null};      // entity_destroyed: the main entity
    contact_events::event event{}; // contact_event (event.manifold is the worker's)
    contact_manifold manifold{};   // manifold_created and contact_event (bodies: main side)
};

// A reply to run on the main thread during update() (entities in it already the main side's).
using main_reply = std::function<void(registry &main)>;

// Each constraint type's components after a step, addressed by main entity: what the solver
// keeps in them (angles, impulses) is read on the main side too.
template<typename... Constraints>
using constraint_states_of = std::tuple<std::vector<std::pair<entity, Constraints>>...>;

template<typename... Constraints>
constraint_states_of<Constraints...> constraint_states_type(constraint_type_list<Constraints...>);

using constraint_states = decltype(constraint_states_type(constraint_types{}));

// Manifolds whose points did not change are refreshed on the main side once in this many steps
// (their impulses are at most this many steps old there).
inline constexpr std::uint64_t manifold_refresh_steps = 8;

// The settings and pause of a registry: what the main side sends when the program changes them,
// and what the worker sends back when a step callback does.
struct world_controls {
    edyn::settings settings;
    bool paused{false};

    bool operator==(const world_controls &) const = default;
};

struct worker_message {
    std::vector<worker_record> records;
    // State after the step: every awake moving body; manifolds whose points changed, and a share
    // of the others (see manifold_refresh_steps).
    std::vector<body_state> bodies;
    std::vector<std::pair<entity, contact_manifold>> manifolds;
    edyn::constraint_states constraints;
    std::vector<entity> slept, woke; // main entities
    // Bodies and manifolds that fell asleep (and bodies made static), as they rest: applied
    // from every message.
    std::vector<body_state> rested;
    std::vector<std::pair<entity, contact_manifold>> rested_manifolds;
    edyn::constraint_states rested_constraints;
    std::vector<main_reply> replies;
    std::vector<std::exception_ptr> errors;
    bool stepped{false};
    // Whether `bodies` (and `slept`'s motion), and `manifolds` and `constraints`, were filled.
    bool has_motion{false};
    bool has_contacts{false};
    double simulation_time{0};
    std::uint64_t step_count{0};
    // Interpolation fraction for the present transforms, when the message ends an advance.
    bool has_alpha{false};
    scalar alpha{1};
    // Sequence number of the last operation applied before this message was made.
    std::uint64_t ops_applied{0};
    // The worker's settings and pause after the step, when its step callbacks changed them.
    std::optional<world_controls> controls;

    bool empty() const noexcept {
        return records.empty() && replies.empty() && errors.empty() && !stepped && !has_alpha &&
               slept.empty() && woke.empty() && rested.empty() && rested_manifolds.empty();
    }
};

} // namespace edyn

#endif // EDYN_SRC_SIMULATION_ASYNC_PROTOCOL_HPP
