#ifndef EDYN_NETWORKING_PACKET_REGISTRY_SNAPSHOT_HPP
#define EDYN_NETWORKING_PACKET_REGISTRY_SNAPSHOT_HPP

#include "edyn/ecs/entity.hpp"
#include "edyn/networking/packet/pool_snapshot.hpp"
#include <vector>

namespace edyn::packet {

/// Inputs of one client as it sent them, with the server time at which the server applies them.
struct timed_inputs {
    double timestamp{};               ///< Server simulation time at which they apply.
    std::vector<entity> entities;     ///< The entities the pools refer to, by position (the server's).
    std::vector<pool_snapshot> pools; ///< The input values, one pool per component type.
};

/// Writes or reads a timed_inputs.
/// @param archive A memory_output_archive or memory_input_archive.
/// @param inputs The inputs to write from or read into.
template<typename Archive>
void serialize(Archive &archive, timed_inputs &inputs) {
    archive(inputs.timestamp, inputs.entities, inputs.pools);
}

/// Both ways: entities and the networked components of theirs that changed recently, as they
/// were at `timestamp`. Sent many times per second through an unreliable channel.
struct registry_snapshot {
    /// Server simulation time in seconds; a client stamps its own with the server time at which
    /// its inputs should apply.
    double timestamp{};
    std::vector<entity> entities;     ///< The entities the pools refer to, by position (the server's).
    std::vector<pool_snapshot> pools; ///< The changed values, one pool per component type.
    /// Server to client only: inputs of other clients that wait in the server's jitter buffer to
    /// apply at steps after `timestamp`, each in the two snapshots after it arrived. The client
    /// keeps them until a snapshot from after their time, and its extrapolation applies them at
    /// their times instead of holding those clients' inputs at their values at `timestamp`.
    /// A client must leave it empty.
    std::vector<timed_inputs> inputs;
    /// Server to client only: the program's components removed recently, one pool per component
    /// type whose data are the positions (in `entities`) of the entities that lost it. A client
    /// must leave it empty.
    std::vector<pool_snapshot> removed;
};

/// Writes or reads a registry_snapshot.
/// @param archive A memory_output_archive or memory_input_archive.
/// @param snapshot The packet to write from or read into.
template<typename Archive>
void serialize(Archive &archive, registry_snapshot &snapshot) {
    archive(snapshot.timestamp, snapshot.entities, snapshot.pools, snapshot.inputs, snapshot.removed);
}

} // namespace edyn::packet

#endif // EDYN_NETWORKING_PACKET_REGISTRY_SNAPSHOT_HPP
