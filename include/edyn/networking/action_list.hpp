#ifndef EDYN_NETWORKING_ACTION_LIST_HPP
#define EDYN_NETWORKING_ACTION_LIST_HPP

#include "edyn/simulation/action_list.hpp"
#include <limits>
#include <vector>

namespace edyn {

/// Writes or reads an action_list: its actions, each with the action type's own serializer.
/// @param archive A memory_output_archive or memory_input_archive.
/// @param list The list to write from or read into.
template<typename Archive, typename Action>
void serialize(Archive &archive, action_list<Action> &list) {
    archive(list.actions);
}

/// The actions of the last second on a client's entity, with the (server) time each was made.
///
/// Kept by the client's engine: after each step (in asynchronous mode, when an update sends its
/// batch), before the lists are emptied, their actions are added to it with the client's
/// estimate of the server time. Sent in every snapshot; the program does not write it. The
/// server adds each entry to the entity's action_list once, the first time it sees it, and its
/// next step sees them.
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
};

/// Writes or reads an action_history: its entries (time and actions), not the local-only
/// `last_applied`. Reading never allocates more entries than there are bytes
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
