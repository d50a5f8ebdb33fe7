#ifndef EDYN_ECS_ENTITY_MAP_HPP
#define EDYN_ECS_ENTITY_MAP_HPP

#include "edyn/ecs/entity.hpp"
#include <vector>

namespace edyn {

// Entities of one registry mapped to those of another, indexed by the source entity's index
// (entities are dense, so this is an array look-up); a stale source (another version at that
// index) maps to null.
class entity_map {
public:
    entity find(entity source) const noexcept {
        auto i = to_index(source);
        if (i >= slots.size() || slots[i].source != source) return null;
        return slots[i].target;
    }
    void insert(entity source, entity target) {
        auto i = to_index(source);
        if (i >= slots.size()) slots.resize(std::size_t(i) + 1);
        slots[i] = {source, target};
    }
    void erase(entity source) noexcept {
        auto i = to_index(source);
        if (i < slots.size() && slots[i].source == source) slots[i] = {};
    }
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
