#ifndef EDYN_ECS_ENTITY_ALLOCATOR_HPP
#define EDYN_ECS_ENTITY_ALLOCATOR_HPP

#include "edyn/ecs/entity.hpp"
#include <algorithm>
#include <cstddef>
#include <stdexcept>
#include <vector>

namespace edyn {

/// Hands out entity ids for a registry: which ids are alive, which indices are free and which
/// version each free index gives next. Knows nothing of components.
///
/// Freed indices are reused most recently freed first, with the version bumped, so a stale
/// handle never equals a live entity (until the 12-bit version wraps around). Applications
/// normally use it through `registry`.
class entity_allocator {
    using index_type = entity_traits::value_type;
    static constexpr index_type free_index = entity_traits::index_mask;

public:
    /// Unsigned integer type for counts of entities and slots.
    using size_type = std::size_t;

    /// Hands out a new entity, reusing the most recently freed index (with its bumped version)
    /// when there is one.
    /// @return The new entity, valid until released.
    /// @throws std::length_error When all 2^20 - 1 indices are in use.
    entity create() {
        if (!free_list.empty()) {
            const auto idx = free_list.back();
            free_list.pop_back();
            const auto e = make_entity(idx, to_version(slots[idx]));
            slots[idx] = e;
            return e;
        }
        const auto idx = static_cast<index_type>(slots.size());
        if (idx >= entity_traits::max_entities) {
            throw std::length_error("registry::create: all entity indices are in use");
        }
        slots.push_back(make_entity(idx, 0));
        return slots.back();
    }

    /// Hands out `hint` itself if its index is free (whatever its version), otherwise behaves as
    /// `create()`. Indices between the current size and the hint's index become free. Used to
    /// recreate the entities of a snapshot with the same ids.
    /// @param hint The entity wanted; null means no preference.
    /// @return `hint`, or a new entity when its index was taken.
    /// @throws std::length_error When `create()` is needed and all indices are in use.
    entity create(entity hint) {
        if (hint == null) {
            return create();
        }
        const auto idx = to_index(hint);
        if (idx >= slots.size()) {
            // Allocate first, so that nothing below throws.
            if (slots.capacity() <= idx) {
                slots.reserve(std::max<std::size_t>(idx + 1, 2 * slots.capacity()));
            }
            reserve_release(idx + 1);
            while (slots.size() < idx) {
                const auto gap = static_cast<index_type>(slots.size());
                slots.push_back(make_entity(free_index, 0));
                free_pos[gap] = static_cast<index_type>(free_list.size());
                free_list.push_back(gap);
            }
            slots.push_back(hint);
            return hint;
        }
        if (to_index(slots[idx]) == free_index) {
            const auto pos = free_pos[idx];
            const auto moved = free_list.back();
            free_list[pos] = moved;
            free_pos[moved] = pos;
            free_list.pop_back();
            slots[idx] = hint;
            return hint;
        }
        return create();
    }

    /// Whether `e` is alive: its slot is in use with exactly this version.
    /// @param e Any entity, null and stale ones included.
    /// @return False for null, stale and never-created entities.
    [[nodiscard]] bool valid(entity e) const noexcept {
        const auto idx = to_index(e);
        return idx < slots.size() && slots[idx] == e;
    }

    /// The version of the slot of `e` now (for a free slot, the version it gives next).
    /// @param e Any entity; only its index is used.
    /// @return The slot's version, or 0 for an index never handed out.
    [[nodiscard]] entity_traits::value_type current(entity e) const noexcept {
        const auto idx = to_index(e);
        return idx < slots.size() ? to_version(slots[idx]) : 0;
    }

    /// Number of entities alive.
    /// @return Slots in use.
    [[nodiscard]] size_type alive() const noexcept { return slots.size() - free_list.size(); }

    /// Number of slots, alive or free: every index handed out so far is below it.
    /// @return One more than the highest index handed out, or 0.
    [[nodiscard]] size_type size() const noexcept { return slots.size(); }

    /// The entity alive at an index, for walking every entity.
    /// @param idx Slot index; precondition: `idx < size()`.
    /// @return The entity alive at `idx`, or null when the slot is free.
    [[nodiscard]] entity at(size_type idx) const noexcept {
        const auto e = slots[idx];
        return to_index(e) == idx ? e : entity(null);
    }

    /// Allocates what freeing any of the current entities needs, so that a `release` that
    /// follows without new slots in between cannot throw. Done here rather than on every
    /// `create` to keep creation a single push_back.
    /// @throws std::bad_alloc When memory runs out.
    void reserve_release() { reserve_release(slots.size()); }

    /// Frees `e`, bumping the version of its slot so that `e` is no longer valid.
    /// @param e The entity to free; precondition: `valid(e)` (not checked).
    /// @throws std::bad_alloc When memory runs out, unless `reserve_release()` was called since
    /// the last new slot.
    void release(entity e) {
        reserve_release();
        const auto idx = to_index(e);
        slots[idx] = make_entity(free_index, to_version(e) + 1);
        free_pos[idx] = static_cast<index_type>(free_list.size());
        free_list.push_back(idx);
    }

private:
    void reserve_release(std::size_t count) {
        if (free_pos.size() < count) {
            free_pos.resize(std::max(count, 2 * free_pos.size()));
        }
        if (free_list.capacity() < count) {
            free_list.reserve(std::max(count, 2 * free_list.capacity()));
        }
    }

    // Slot `i` holds the entity alive at index `i`, or, when free, the null index and the
    // version the next entity there gets.
    std::vector<entity> slots;
    std::vector<index_type> free_list; // free indices, most recently freed last
    std::vector<index_type> free_pos;  // by index: position in `free_list` while free; sized
                                       // on first need, so it may be shorter than `slots`
};

} // namespace edyn

#endif // EDYN_ECS_ENTITY_ALLOCATOR_HPP
