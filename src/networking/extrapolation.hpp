#ifndef EDYN_SRC_NETWORKING_EXTRAPOLATION_HPP
#define EDYN_SRC_NETWORKING_EXTRAPOLATION_HPP

// A client's extrapolation: the server's state of some bodies, which is in the past when it
// arrives, simulated forward to the client's present in a registry of its own, with the
// client's world around them, its recorded inputs re-applied at the times they were made and
// the other clients' inputs the server forwarded applied at the times the server applies them.
// Everything it reads is copied in, so that it can run on another thread.

#include "edyn/ecs/entity_map.hpp"
#include "edyn/networking/networked_components.hpp"
#include "edyn/simulation/settings.hpp"
#include "network_motion.hpp"
#include "network_registry.hpp"
#include <memory>
#include <vector>

namespace edyn {

struct decoded_packet {
    double time{};
    std::vector<entity> entities; // the client's (null where it has none)
    std::vector<std::unique_ptr<detail::decoded_pool>> pools;
};

struct extrapolation_input {
    edyn::settings settings;
    // A copy of the client's list of types (its change records left out).
    network_registry types;
    // The client's networked entities and their components now (entities of members: the
    // client's).
    decoded_packet world;
    // The server's state at `start_time` (entities of members: the server's, translated by
    // remote_to_local).
    decoded_packet snapshot;
    entity_map remote_to_local;
    // The client's inputs and the other clients' forwarded ones, oldest first: the client's up
    // to start_time set the state it starts from (entities of members: the server's).
    std::vector<decoded_packet> inputs;
    double start_time{};
    double end_time{};
};

struct extrapolation_result {
    double end_time{};
    // Where the bodies of the snapshot are at end_time, by the client's entity.
    std::vector<std::pair<entity, network_motion>> bodies;
};

// Most steps one extrapolation runs (a second at 60 Hz): past that, a snapshot is too old to
// be worth it.
inline constexpr unsigned max_extrapolation_steps = 60;

void run_extrapolation(const extrapolation_input &input, extrapolation_result &result);

} // namespace edyn

#endif // EDYN_SRC_NETWORKING_EXTRAPOLATION_HPP
