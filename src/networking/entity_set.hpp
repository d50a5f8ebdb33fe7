#ifndef EDYN_SRC_NETWORKING_ENTITY_SET_HPP
#define EDYN_SRC_NETWORKING_ENTITY_SET_HPP

#include "edyn/ecs/entity.hpp"
#include <cstdint>
#include <vector>

namespace edyn {

// A set of entities with constant-time membership and iteration in insertion order (removal
// moves the last one into the hole), so that what is built from it does not depend on hashing.
class entity_set {
public:
    bool contains(entity e) const noexcept {
        auto i = to_index(e);
        return i < slots.size() && slots[i].e == e;
    }
    bool insert(entity e) {
        if (contains(e)) return false;
        auto i = to_index(e);
        if (i >= slots.size()) slots.resize(std::size_t(i) + 1);
        slots[i] = {e, std::uint32_t(list.size())};
        list.push_back(e);
        return true;
    }
    bool erase(entity e) noexcept {
        if (!contains(e)) return false;
        auto i = to_index(e);
        auto position = slots[i].position;
        auto last = list.back();
        list[position] = last;
        slots[to_index(last)].position = position;
        list.pop_back();
        slots[i] = {};
        return true;
    }
    void clear() noexcept {
        for (auto e : list)
            slots[to_index(e)] = {};
        list.clear();
    }
    const std::vector<entity> &entities() const noexcept { return list; }
    std::size_t size() const noexcept { return list.size(); }

private:
    struct slot {
        entity e{null};
        std::uint32_t position{0};
    };
    std::vector<slot> slots;
    std::vector<entity> list;
};

} // namespace edyn

#endif // EDYN_SRC_NETWORKING_ENTITY_SET_HPP
