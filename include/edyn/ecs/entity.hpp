#ifndef EDYN_ECS_ENTITY_HPP
#define EDYN_ECS_ENTITY_HPP

#include <cstdint>

namespace edyn {

// An entity identifier: the low 20 bits are the index of its slot in the registry, the high 12
// bits a version that is bumped every time the slot is freed, so that a handle kept past
// `destroy` no longer compares equal to the entity that later reuses the slot. The version
// wraps around after 4096 reuses of one slot (as EnTT's does). `std::hash<entity>` works: the
// standard library hashes enumerations by their underlying value.
enum class entity : std::uint32_t {};

struct entity_traits {
    using value_type = std::uint32_t;
    static constexpr unsigned index_bits = 20;
    static constexpr unsigned version_bits = 12;
    static constexpr value_type index_mask = (value_type{1} << index_bits) - 1;
    static constexpr value_type version_mask = (value_type{1} << version_bits) - 1;
    // The all-ones index is reserved for `null`, so a registry holds at most this many slots.
    static constexpr value_type max_entities = index_mask;
};

[[nodiscard]] constexpr entity_traits::value_type to_integral(entity e) noexcept {
    return static_cast<entity_traits::value_type>(e);
}

[[nodiscard]] constexpr entity_traits::value_type to_index(entity e) noexcept {
    return to_integral(e) & entity_traits::index_mask;
}

// EnTT's name for the index part.
[[nodiscard]] constexpr entity_traits::value_type to_entity(entity e) noexcept { return to_index(e); }

[[nodiscard]] constexpr entity_traits::value_type to_version(entity e) noexcept {
    return to_integral(e) >> entity_traits::index_bits;
}

[[nodiscard]] constexpr entity make_entity(entity_traits::value_type index,
                                           entity_traits::value_type version) noexcept {
    return entity{(index & entity_traits::index_mask) |
                  ((version & entity_traits::version_mask) << entity_traits::index_bits)};
}

// The type of `edyn::null`. Like EnTT's, it compares equal to any entity whose index is the
// reserved all-ones index, whatever its version, and converts to the all-ones entity.
struct null_t {
    [[nodiscard]] constexpr operator entity() const noexcept { return entity{~entity_traits::value_type{}}; }

    [[nodiscard]] friend constexpr bool operator==(null_t, null_t) noexcept { return true; }

    // C++20 rewrites `e == null`, `null != e` and `e != null` in terms of this one.
    [[nodiscard]] friend constexpr bool operator==(null_t, entity e) noexcept {
        return to_index(e) == entity_traits::index_mask;
    }
};

inline constexpr null_t null{};

} // namespace edyn

#endif // EDYN_ECS_ENTITY_HPP
