#include "edyn/collision/should_collide.hpp"
#include "edyn/ecs/registry.hpp"
#include <stdexcept>
#include <string>

namespace edyn {

namespace {

// The registry context variable holding the current filter function.
struct should_collide_context {
    should_collide_func_t func;
};

} // namespace

bool should_collide_default(const registry &registry, entity first, entity second) {
    auto groupA = collision_filter::all_groups, maskA = collision_filter::all_groups;
    auto groupB = collision_filter::all_groups, maskB = collision_filter::all_groups;

    if (auto *filter = registry.try_get<collision_filter>(first)) {
        groupA = filter->group;
        maskA = filter->mask;
    }
    if (auto *filter = registry.try_get<collision_filter>(second)) {
        groupB = filter->group;
        maskB = filter->mask;
    }
    if ((groupA & maskB) == 0 || (groupB & maskA) == 0) return false;

    if (auto *excl = registry.try_get<collision_exclusion>(first); excl && excl->contains(second))
        return false;
    if (auto *excl = registry.try_get<collision_exclusion>(second); excl && excl->contains(first))
        return false;
    return true;
}

void exclude_collision(registry &registry, entity first, entity second) {
    for (auto e : {first, second}) {
        if (!registry.valid(e)) {
            throw std::invalid_argument("exclude_collision: " + detail::describe(e) + " is not valid");
        }
    }
    if (first == second) {
        throw std::invalid_argument("exclude_collision: an entity cannot exclude itself (" +
                                    detail::describe(first) + ")");
    }

    // Build both new lists before touching the registry, so that a full list changes nothing.
    collision_exclusion lists[2];
    entity others[2] = {second, first};
    entity owners[2] = {first, second};
    bool changed[2] = {false, false};

    for (int i = 0; i < 2; ++i) {
        if (auto *existing = registry.try_get<collision_exclusion>(owners[i])) {
            // Entities destroyed since they were excluded (a gun's spent bullets) leave the list
            // here, so that they do not fill it.
            for (std::size_t j = 0; j < existing->num_entities; ++j) {
                auto excluded = existing->entities[j];
                if (registry.valid(excluded))
                    lists[i].entities[lists[i].num_entities++] = excluded;
                else
                    changed[i] = true;
            }
        }
        if (lists[i].contains(others[i])) continue;
        if (lists[i].num_entities == collision_exclusion::max_exclusions) {
            throw std::invalid_argument("exclude_collision: collision_exclusion of " +
                                        detail::describe(owners[i]) + " is full (max_exclusions " +
                                        std::to_string(collision_exclusion::max_exclusions) + ")");
        }
        lists[i].entities[lists[i].num_entities++] = others[i];
        changed[i] = true;
    }

    for (int i = 0; i < 2; ++i) {
        if (changed[i]) registry.emplace_or_replace<collision_exclusion>(owners[i], lists[i]);
    }
}

void set_should_collide(registry &registry, should_collide_func_t func) {
    if (func == nullptr) {
        throw std::invalid_argument("set_should_collide: func must not be null");
    }
    registry.ctx().emplace_or_replace<should_collide_context>(func);
}

void reset_should_collide(registry &registry) noexcept { registry.ctx().erase<should_collide_context>(); }

should_collide_func_t get_should_collide(const registry &registry) noexcept {
    if (auto *ctx = registry.ctx().find<should_collide_context>()) return ctx->func;
    return &should_collide_default;
}

} // namespace edyn
