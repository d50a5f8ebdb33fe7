#ifndef EDYN_SIMULATION_ACTION_LIST_HPP
#define EDYN_SIMULATION_ACTION_LIST_HPP

#include "edyn/ecs/registry.hpp"
#include <functional>
#include <type_traits>
#include <vector>

namespace edyn {

/// One-shot events (a jump, a shot) on an entity, for the step callbacks to act on.
///
/// Actions are not components: they are collected in this list, which is. To add one, get the
/// entity's list (`get_or_emplace`) and push the action into `actions`; no patch is needed.
/// The next step's callbacks see them, and the list is emptied after that step, so that each
/// action is seen by exactly one step however many steps an update runs. In asynchronous mode
/// the lists go to the simulation worker when the update sends its batch, are emptied in the
/// main registry then, and the worker's step sees them.
///
/// Register each action type as the second argument of register_external_components (and, in
/// networked programs, of register_networked_components, with the same types):
/// @code
/// edyn::register_external_components<steering>(registry, std::tuple<jump>{});
/// @endcode
///
/// @tparam Action The program's action type.
template<typename Action>
struct action_list {
    /// Actions added since the last step consumed them, oldest first. Written by the program,
    /// or on a server by the engine from the client's snapshots; empty by default.
    std::vector<Action> actions;
};

/// True for the action_list types.
template<typename T>
inline constexpr bool is_action_list_v = false;
/// True: an action_list.
template<typename Action>
inline constexpr bool is_action_list_v<action_list<Action>> = true;

namespace detail {

struct replication_sink;

// Type-erased handlers of one action type.
struct action_type {
    const void *id; // unique per type
    // Empties every list of the type, without signalling a change.
    void (*clear)(registry &);
    // Asynchronous mode, main side: queues every non-empty list's actions for the worker, which
    // appends them to its own list of the entity.
    void (*send)(registry &, replication_sink &);
};

// The registry's action types (in its context), and what runs before their lists are emptied.
struct action_types {
    std::vector<action_type> types;
    // Set by a networking client: records the lists into their action histories.
    std::function<void(registry &)> before_clear;
};

// Adds the type to the registry's context (and to the worker's, in asynchronous mode); a type
// added already is not added again. Throws std::invalid_argument naming `function` when the
// registry is not attached.
void register_action_type(registry &registry, const char *function, const action_type &type);

// Called after every step (sequential modes and the worker) and, in asynchronous mode, when the
// main registry sends a batch to the worker: runs before_clear, sends the lists to the worker
// where there is one, and empties them.
void consume_actions(registry &registry);

} // namespace detail

} // namespace edyn

#endif // EDYN_SIMULATION_ACTION_LIST_HPP
