#include "edyn/constraints/constraint_links.hpp"

namespace edyn {

namespace {

// Which side of `links` is `body`'s.
int side_of(const constraint_links &links, entity body) { return links.body[0] == body ? 0 : 1; }

} // namespace

void link_constraint(registry &registry, entity constraint, entity body0, entity body1) {
    if (auto *existing = registry.try_get<constraint_links>(constraint)) {
        ++existing->num_constraints;
        return;
    }
    constraint_links links;
    links.body[0] = body0;
    links.body[1] = body1;
    links.num_constraints = 1;
    for (int i = 0; i < 2; ++i) {
        auto body = links.body[i];
        if (!registry.valid(body) || (i == 1 && body == body0)) continue;
        if (!registry.all_of<constraint_list>(body)) registry.emplace<constraint_list>(body);
        auto &list = registry.get<constraint_list>(body);
        links.next[i] = list.first;
        if (list.first != null) {
            auto &head = registry.get<constraint_links>(list.first);
            head.prev[side_of(head, body)] = constraint;
        }
        list.first = constraint;
    }
    registry.emplace<constraint_links>(constraint, links);
}

void release_constraint(registry &registry, entity constraint) {
    auto *links = registry.try_get<constraint_links>(constraint);
    if (links == nullptr) return;
    if (--links->num_constraints == 0) registry.remove<constraint_links>(constraint);
}

void unlink_constraint(registry &registry, entity constraint) {
    auto &links = registry.get<constraint_links>(constraint);
    for (int i = 0; i < 2; ++i) {
        auto body = links.body[i];
        if (i == 1 && body == links.body[0]) continue;
        // The body's list may be gone already: destroying an entity removes its components in
        // the order of their pools.
        auto *list = registry.valid(body) ? registry.try_get<constraint_list>(body) : nullptr;
        if (list == nullptr) continue;
        if (links.prev[i] != null) {
            auto &prev = registry.get<constraint_links>(links.prev[i]);
            prev.next[side_of(prev, body)] = links.next[i];
        } else {
            list->first = links.next[i];
        }
        if (links.next[i] != null) {
            auto &next = registry.get<constraint_links>(links.next[i]);
            next.prev[side_of(next, body)] = links.prev[i];
        }
        links.next[i] = links.prev[i] = null;
    }
}

void constraints_of(const registry &registry, entity body, std::vector<constraint_ref> &out) {
    auto *list = registry.valid(body) ? registry.try_get<constraint_list>(body) : nullptr;
    if (list == nullptr) return;
    for (auto c = list->first; c != null;) {
        auto &links = registry.get<constraint_links>(c);
        out.push_back({c, {links.body[0], links.body[1]}});
        c = links.next[side_of(links, body)];
    }
}

void destroy_constraints_of(registry &registry, entity body) {
    std::vector<constraint_ref> refs;
    constraints_of(registry, body, refs);
    for (auto &ref : refs) {
        if (registry.valid(ref.constraint)) registry.destroy(ref.constraint);
    }
}

} // namespace edyn
