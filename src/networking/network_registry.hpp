#ifndef EDYN_SRC_NETWORKING_NETWORK_REGISTRY_HPP
#define EDYN_SRC_NETWORKING_NETWORK_REGISTRY_HPP

// What a server or client registry knows about networked component types, in its context: the
// list both ends share (edyn's own first, then the program's in registration order), and when
// each entity's value of each type last changed.

#include "edyn/dynamics/rigidbody_def.hpp"
#include "edyn/networking/networked_components.hpp"
#include "edyn/networking/packet/pool_snapshot.hpp"
#include "network_motion.hpp"
#include <cstdint>
#include <limits>
#include <memory>
#include <optional>
#include <vector>

namespace edyn {

// Each input is sent by this many consecutive updates (frames) of the client, whatever the
// snapshot rate: a lost one changes what the server simulates, and a copy must follow soon
// after, within the playout delay the server sets.
inline constexpr int input_repeats = 5;

// Indices of edyn's own types in the list.
namespace network_index {
inline constexpr std::uint16_t body = 0;   // rigidbody_def: creates the rigid body
inline constexpr std::uint16_t motion = 1; // network_motion: transform and velocities, quantised
inline constexpr std::uint16_t first_constraint = 2;
} // namespace network_index

struct network_registry {
    std::vector<detail::networked_type> types;
    // edyn's own types come first: the program's start here.
    std::uint16_t first_program_type{0};
    // Network index by type_index, or -1.
    std::vector<int> index_of_type;
    // Per network index, per entity index: the entity and the time its value last changed.
    struct change {
        entity e{null};
        double time{-std::numeric_limits<double>::infinity()};
    };
    std::vector<std::vector<change>> changes;
    // The same for removals: per network index, per entity index, when the program removed it.
    std::vector<std::vector<change>> removals;
    // Simulation time changes are recorded at (set by the server's and client's updates).
    double now{0};
    // While set, changes are not recorded (values being applied from the other end).
    bool muted{false};
    // Bodies whose definition (shape, material, mass, kind, ...) and constraints whose values the
    // program changed since the server last sent them, in the order of the changes (an entity
    // may appear more than once). Kept only when `track_redefined` (a server) is set.
    std::vector<entity> redefined;
    bool track_redefined{false};

    int index_of(std::size_t type) const noexcept {
        return type < index_of_type.size() ? index_of_type[type] : -1;
    }
    void mark(std::size_t type, entity e);
    // Records that the program changed `e`'s definition (a body) or value (a constraint).
    void mark_redefined(entity e);
    // When `e`'s value of `index` last changed (-inf when it never did).
    double changed_at(std::uint16_t index, entity e) const noexcept;
    void mark_removed(std::size_t type, entity e);
    // When `index` was last removed from `e` (-inf when it never was).
    double removed_at(std::uint16_t index, entity e) const noexcept;
    void forget(entity e);
};

// The registry's network_registry, made (with edyn's own types, listeners connected) if needed.
network_registry &ensure_network_registry(registry &registry);

// Decodes every pool of a packet; empty when one is malformed or names an unknown type.
std::optional<std::vector<std::unique_ptr<detail::decoded_pool>>>
decode_pools(const network_registry &types, const std::vector<packet::pool_snapshot> &pools,
             std::size_t entity_count);

// Applies the pools in order, then wakes the bodies that received inputs or actions (a step
// callback reads them to push the body, which the simulation cannot see).
void apply_pools(registry &registry, const network_registry &types,
                 const std::vector<std::unique_ptr<detail::decoded_pool>> &pools,
                 const std::vector<entity> &entities, const detail::entity_mapper &map);

// An empty decoded pool of motion (network_index::motion), to fill: applying it sets the
// bodies' transforms and velocities.
std::unique_ptr<detail::typed_decoded_pool<network_motion>> make_motion_pool();

// An empty decoded pool of bodies (network_index::body), to fill with definitions: applying it
// makes the bodies, or updates those that exist, as a received one does.
std::unique_ptr<detail::typed_decoded_pool<rigidbody_def>> make_body_pool();

// Builds the entity list and pools of a packet, one value at a time.
class pool_writer {
public:
    pool_writer(const network_registry &types, const registry &registry, detail::entity_mapper map = {})
        : types(&types)
        , source(&registry)
        , map(std::move(map)) {}
    // Adds `e`'s value of the type at `index` (which it must have); `e` joins the entity list
    // (translated by the map) the first time.
    void add(entity e, std::uint16_t index);
    // Adds a value already encoded by the type's `write`.
    void add_encoded(entity e, std::uint16_t index, const std::vector<std::uint8_t> &bytes);
    // Puts `e` in the entity list without a value.
    void include(entity e) { position_of(e); }
    // Records that `e` lost the type at `index`; `e` joins the entity list the first time.
    void remove(entity e, std::uint16_t index);
    bool empty() const noexcept { return entities.empty(); }
    // The bytes of its values so far, in all pools, and in the largest one.
    std::size_t bytes() const noexcept;
    std::size_t largest_pool() const noexcept;
    // Starts over, keeping the memory.
    void clear() noexcept;
    void finish(std::vector<entity> &entities_out, std::vector<packet::pool_snapshot> &pools_out);
    // The same, with the removals as pools of positions.
    void finish(std::vector<entity> &entities_out, std::vector<packet::pool_snapshot> &pools_out,
                std::vector<packet::pool_snapshot> &removed_out);

private:
    std::uint32_t position_of(entity e);

    const network_registry *types;
    const registry *source;
    detail::entity_mapper map;
    std::vector<entity> entities;
    std::vector<std::pair<entity, std::uint32_t>> positions; // by entity index
    std::vector<std::vector<std::uint8_t>> pool_data;        // by network index
    std::vector<std::vector<std::uint8_t>> removed_data;     // positions, by network index
};

} // namespace edyn

#endif // EDYN_SRC_NETWORKING_NETWORK_REGISTRY_HPP
