#ifndef EDYN_NETWORKING_ACTION_LIST_HPP
#define EDYN_NETWORKING_ACTION_LIST_HPP

#include "edyn/ecs/registry.hpp"
#include <limits>
#include <vector>

namespace edyn {

/// One-shot events of a client's (a jump, a shot) on an entity it owns.
///
/// Actions are not components: they are collected in this list, which is. To add one, get the
/// entity's list (`get_or_emplace`) and push the action into `actions`. A step callback consumes
/// them, and they are cleared after the step that saw them. Each client snapshot carries the
/// actions of the last second with the time they were made (action_history), so that a lost
/// packet loses none, and the server applies each once, at that time.
///
/// Register the action type with `register_external_components<action_list<A>>` and
/// `register_networked_components<...>(registry, std::tuple<A>{})`; an action type that is not
/// empty needs a `serialize` function.
///
/// @tparam Action The program's action type.
template<typename Action>
struct action_list {
    /// Actions added since the last step consumed them, oldest first. Written by the program
    /// (client side) or by the engine (server side, from the client's snapshots); empty by
    /// default.
    std::vector<Action> actions;
};

/// Writes or reads an action_list: its actions, each with the action type's own serializer.
/// @param archive A memory_output_archive or memory_input_archive.
/// @param list The list to write from or read into.
template<typename Archive, typename Action>
void serialize(Archive &archive, action_list<Action> &list) {
    archive(list.actions);
}

/// The actions of the last second on a client's entity, with the (server) time each was made.
///
/// Kept by the client's engine and sent in every snapshot; the program does not write it. The
/// server adds each entry to the entity's action_list once, the first time it sees it.
///
/// @tparam Action The program's action type.
template<typename Action>
struct action_history {
    /// The actions recorded at one time.
    struct entry {
        double timestamp{};          ///< Server time in seconds at which the actions were made.
        std::vector<Action> actions; ///< The actions, in the order they were added.
    };
    /// Entries of the last second, oldest first.
    std::vector<entry> entries;
    /// Not sent. On the receiving side: the time (seconds) of the newest entry applied; minus
    /// infinity before the first.
    double last_applied{-std::numeric_limits<double>::infinity()};
    /// Not sent. On the sending side: how many of the action_list's actions are in `entries`
    /// already (0 by default).
    std::size_t recorded{0};
};

/// Writes or reads an action_history: its entries (time and actions), not the local-only
/// `last_applied` and `recorded`. Reading never allocates more entries than there are bytes
/// left in the archive.
/// @param archive A memory_output_archive or memory_input_archive.
/// @param history The history to write from or read into.
template<typename Archive, typename Action>
void serialize(Archive &archive, action_history<Action> &history) {
    if constexpr (Archive::is_output) {
        archive.write_size(history.entries.size());
    } else {
        history.entries.resize(archive.read_size(archive.remaining()));
    }
    for (auto &entry : history.entries)
        archive(entry.timestamp, entry.actions);
}

} // namespace edyn

#endif // EDYN_NETWORKING_ACTION_LIST_HPP
