#ifndef EDYN_COLLISION_COLLISION_FILTER_HPP
#define EDYN_COLLISION_COLLISION_FILTER_HPP

#include "edyn/ecs/entity.hpp"
#include "edyn/ecs/entity_members.hpp"
#include <array>
#include <cstddef>
#include <cstdint>

namespace edyn {

/// Collision groups and masks of a body: each of the 64 bits is a group.
///
/// Two bodies collide only when each one's `group` has a bit in common with the other's `mask`
/// (see should_collide_default). Bodies without this component are in every group and collide
/// with every group (the defaults below). make_rigidbody() emplaces it from
/// `rigidbody_def::collision_group` and `collision_mask`; the user may change it at any time,
/// through `registry::replace` or `registry::patch` (or `patch` after writing the component
/// directly), in every mode: that is what makes the body's existing contacts be filtered again
/// (a pair the new filter refuses stops colliding at once) and, in asynchronous mode, what
/// sends the change to the simulation worker. A value written without either is read only when
/// the body meets a new neighbour.
struct collision_filter {
    /// Every bit set: member of, or colliding with, all groups.
    static constexpr std::uint64_t all_groups = ~std::uint64_t{0};

    /// Groups the body belongs to, one bit each; all groups by default.
    std::uint64_t group{all_groups};
    /// Groups the body collides with, one bit each; all groups by default.
    std::uint64_t mask{all_groups};
};

/// Entities a body never collides with, whatever their filters.
///
/// Bounded so that the component stays a flat value that is cheap to copy across threads and the
/// network; use collision groups for larger sets. Fill it through exclude_collision(), which keeps
/// both bodies' lists symmetric and drops the entities destroyed since they were added.
struct collision_exclusion {
    /// Most entities one body can exclude.
    static constexpr std::size_t max_exclusions = 16;

    /// The excluded entities; only the first `num_entities` are meaningful.
    std::array<entity, max_exclusions> entities{};
    /// How many entries of `entities` are in use (0 by default).
    std::size_t num_entities{0};

    /// Whether `other` is among the excluded entities.
    /// @param other The entity to look for.
    /// @return True when `other` is one of the first `num_entities` entries.
    bool contains(entity other) const noexcept {
        for (std::size_t i = 0; i < num_entities; ++i) {
            if (entities[i] == other) return true;
        }
        return false;
    }
};

/// Declares the entity-valued members of collision_exclusion, so that its entities are mapped
/// between registries (simulation worker, network).
template<>
struct entity_members<collision_exclusion> {
    /// Calls `fn(entity &)` for each excluded entity in use.
    /// @param exclusion The component whose entities are visited.
    /// @param fn Callable taking an `entity &`; it may rewrite the entity in place.
    template<typename Fn>
    static void each(collision_exclusion &exclusion, Fn &&fn) {
        for (std::size_t i = 0; i < exclusion.num_entities; ++i)
            fn(exclusion.entities[i]);
    }
};

} // namespace edyn

#endif // EDYN_COLLISION_COLLISION_FILTER_HPP
