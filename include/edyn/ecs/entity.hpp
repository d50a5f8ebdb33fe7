#ifndef EDYN_ECS_ENTITY_HPP
#define EDYN_ECS_ENTITY_HPP

#include <cstdint>

namespace edyn {

/// An entity identifier, handed out by `registry::create`.
///
/// The low 20 bits are the index of its slot in the registry, the high 12 bits a version that is
/// bumped every time the slot is freed, so that a handle kept past `destroy` no longer compares
/// equal to the entity that later reuses the slot. The version wraps around after 4096 reuses of
/// one slot (as EnTT's does). `std::hash<entity>` works: the standard library hashes enumerations
/// by their underlying value. An entity is only meaningful in the registry that created it; the
/// asynchronous worker and network peers translate entities through an `entity_map`.
enum class entity : std::uint32_t {};

/// Layout of the bits of an `entity`: how many hold the index and how many the version.
struct entity_traits {
    /// Underlying integer type of `entity`.
    using value_type = std::uint32_t;
    /// Number of low bits that hold the index of the entity's slot.
    static constexpr unsigned index_bits = 20;
    /// Number of high bits that hold the version of the entity's slot.
    static constexpr unsigned version_bits = 12;
    /// Mask of the index bits (applied to the integral value of an entity).
    static constexpr value_type index_mask = (value_type{1} << index_bits) - 1;
    /// Mask of the version once shifted down by `index_bits`.
    static constexpr value_type version_mask = (value_type{1} << version_bits) - 1;
    /// Largest number of slots a registry holds, 2^20 - 1: the all-ones index is reserved for
    /// `null`.
    static constexpr value_type max_entities = index_mask;
};

/// The integral value of an entity, index and version together.
/// @param e Any entity, null included.
/// @return The 32 bits of `e` as an unsigned integer.
[[nodiscard]] constexpr entity_traits::value_type to_integral(entity e) noexcept {
    return static_cast<entity_traits::value_type>(e);
}

/// The index part of an entity: the position of its slot in the registry.
/// @param e Any entity, null included (whose index is `entity_traits::index_mask`).
/// @return The low `entity_traits::index_bits` bits of `e`.
[[nodiscard]] constexpr entity_traits::value_type to_index(entity e) noexcept {
    return to_integral(e) & entity_traits::index_mask;
}

/// The index part of an entity, under EnTT's name; the same as `to_index`.
/// @param e Any entity.
/// @return The index of `e`.
[[nodiscard]] constexpr entity_traits::value_type to_entity(entity e) noexcept { return to_index(e); }

/// The version part of an entity: how many times its slot had been freed when it was created
/// (modulo 4096).
/// @param e Any entity.
/// @return The high `entity_traits::version_bits` bits of `e`, shifted down.
[[nodiscard]] constexpr entity_traits::value_type to_version(entity e) noexcept {
    return to_integral(e) >> entity_traits::index_bits;
}

/// Builds an entity from an index and a version, for tests, serialisation and entity hints
/// (`registry::create(entity)`). Excess bits of either value are dropped.
/// @param index Slot index; only its low `entity_traits::index_bits` bits are kept.
/// @param version Version; only its low `entity_traits::version_bits` bits are kept.
/// @return The entity with that index and version.
[[nodiscard]] constexpr entity make_entity(entity_traits::value_type index,
                                           entity_traits::value_type version) noexcept {
    return entity{(index & entity_traits::index_mask) |
                  ((version & entity_traits::version_mask) << entity_traits::index_bits)};
}

/// The type of `edyn::null`.
///
/// Like EnTT's, it compares equal to any entity whose index is the reserved all-ones index,
/// whatever its version, and converts to the all-ones entity.
struct null_t {
    /// Converts to the entity whose bits are all ones (index and version).
    /// @return The all-ones entity.
    [[nodiscard]] constexpr operator entity() const noexcept { return entity{~entity_traits::value_type{}}; }

    /// Every null equals every other null.
    /// @return Always true.
    [[nodiscard]] friend constexpr bool operator==(null_t, null_t) noexcept { return true; }

    /// Whether `e` is null, that is, has the reserved all-ones index, whatever its version. C++20
    /// rewrites `e == null`, `null != e` and `e != null` in terms of this one.
    /// @param e The entity to test.
    /// @return True when the index of `e` is `entity_traits::index_mask`.
    [[nodiscard]] friend constexpr bool operator==(null_t, entity e) noexcept {
        return to_index(e) == entity_traits::index_mask;
    }
};

/// The null entity: no entity of any registry equals it, so it marks "no entity" in components
/// and return values (`if (e == edyn::null)`).
inline constexpr null_t null{};

} // namespace edyn

#endif // EDYN_ECS_ENTITY_HPP
