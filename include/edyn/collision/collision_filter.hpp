#ifndef EDYN_COLLISION_COLLISION_FILTER_HPP
#define EDYN_COLLISION_COLLISION_FILTER_HPP

#include "edyn/ecs/entity.hpp"
#include "edyn/ecs/entity_members.hpp"
#include <array>
#include <cstddef>
#include <cstdint>

namespace edyn {

// Collision groups and masks: each bit is a group. Two bodies collide only when each one's
// group has a bit in common with the other's mask. Bodies without this component are in every
// group and collide with every group (the defaults below).
struct collision_filter {
    static constexpr std::uint64_t all_groups = ~std::uint64_t{0};

    std::uint64_t group{all_groups};
    std::uint64_t mask{all_groups};
};

// Entities a body never collides with, whatever their filters. Bounded so that the component
// stays a flat value that is cheap to copy across threads and the network; use collision
// groups for larger sets. Fill it through exclude_collision().
struct collision_exclusion {
    static constexpr std::size_t max_exclusions = 16;

    std::array<entity, max_exclusions> entities{};
    std::size_t num_entities{0};

    bool contains(entity other) const noexcept {
        for (std::size_t i = 0; i < num_entities; ++i) {
            if (entities[i] == other) return true;
        }
        return false;
    }
};

template<>
struct entity_members<collision_exclusion> {
    template<typename Fn>
    static void each(collision_exclusion &exclusion, Fn &&fn) {
        for (std::size_t i = 0; i < exclusion.num_entities; ++i)
            fn(exclusion.entities[i]);
    }
};

} // namespace edyn

#endif // EDYN_COLLISION_COLLISION_FILTER_HPP
