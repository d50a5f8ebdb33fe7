#ifndef EDYN_NETWORKING_ACTION_LIST_HPP
#define EDYN_NETWORKING_ACTION_LIST_HPP

#include "edyn/ecs/registry.hpp"
#include <limits>
#include <vector>

namespace edyn {

// One-shot events of a client's (a jump, a shot) on an entity it owns. Add to the entity's list
// (emplace it if it has none); a step callback consumes them, and they are cleared after the
// step that saw them. Each client snapshot carries the actions of the last second with the time
// they were made, so that a lost packet loses none, and the server applies each once, at that
// time. Register the action type with register_external_components<action_list<A>> and
// register_networked_components<...>(registry, std::tuple<A>{}); an action type that is not
// empty needs a serialize function.
template<typename Action>
struct action_list {
    std::vector<Action> actions;
};

template<typename Archive, typename Action>
void serialize(Archive &archive, action_list<Action> &list) {
    archive(list.actions);
}

// The actions of the last second on a client's entity, with the (server) time each was made:
// kept by the client and sent in every snapshot. The server adds each entry to the entity's
// action_list once, the first time it sees it.
template<typename Action>
struct action_history {
    struct entry {
        double timestamp{};
        std::vector<Action> actions;
    };
    std::vector<entry> entries;
    // Not sent. On the receiving side: the time of the newest entry applied. On the sending side:
    // how many of the action_list's actions are in `entries` already.
    double last_applied{-std::numeric_limits<double>::infinity()};
    std::size_t recorded{0};
};

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
