#ifndef EDYN_ECS_ENTITY_MAP_HPP
#define EDYN_ECS_ENTITY_MAP_HPP

#include "edyn/ecs/entity.hpp"
#include <stdexcept>
#include <vector>

namespace edyn {

/// Entities of one registry mapped to those of another, as the asynchronous worker and network
/// peers need to translate entity-valued members (see `entity_members`).
///
/// It is indexed by the source entity's index (entities are dense, so this is an array look-up);
/// a stale source (another version at that index) maps to null. It maps one way only: keep a
/// second map for the reverse direction.
class entity_map {
public:
    /// The entity that `source` maps to.
    /// @param source An entity of the source registry.
    /// @return The mapped entity, or null when `source` (with this exact version) has no entry.
    entity find(entity source) const noexcept {
        auto i = to_index(source);
        if (i >= slots.size() || slots[i].source != source) return null;
        return slots[i].target;
    }
    /// The source entity whose entry is at `source`'s index, whatever its version.
    /// @param source An entity of the source registry.
    /// @return The entry's source (`source` itself, or another version at its index), or null
    /// when that index has no entry.
    entity source_at(entity source) const noexcept {
        auto i = to_index(source);
        return i < slots.size() ? slots[i].source : null;
    }
    /// Maps `source` to `target`, replacing any entry at the same index (whatever its version).
    /// @param source An entity of the source registry; not null.
    /// @param target The entity of the other registry it stands for.
    /// @throws std::invalid_argument When `source` is null (its index would grow the map to 2^20
    /// entries); the map is left as it was.
    void insert(entity source, entity target) {
        if (source == null) {
            throw std::invalid_argument("entity_map::insert: source must not be null");
        }
        auto i = to_index(source);
        if (i >= slots.size()) slots.resize(std::size_t(i) + 1);
        slots[i] = {source, target};
    }
    /// Removes the entry of `source`; does nothing if it has none (or a stale one).
    /// @param source An entity of the source registry.
    void erase(entity source) noexcept {
        auto i = to_index(source);
        if (i < slots.size() && slots[i].source == source) slots[i] = {};
    }
    /// Removes every entry.
    void clear() noexcept { slots.clear(); }

private:
    struct slot {
        entity source{null};
        entity target{null};
    };
    std::vector<slot> slots;
};

} // namespace edyn

#endif // EDYN_ECS_ENTITY_MAP_HPP
