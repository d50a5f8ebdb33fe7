#include "interest.hpp"
#include "edyn/constraints/constraint_links.hpp"
#include "edyn/dynamics/orientation.hpp"
#include "edyn/dynamics/position.hpp"
#include "edyn/dynamics/rigidbody.hpp"
#include "edyn/dynamics/shape_index.hpp"
#include "edyn/dynamics/tags.hpp"
#include "edyn/dynamics/visit_shape.hpp"
#include "edyn/networking/asset_ref.hpp"
#include "edyn/networking/networked_tag.hpp"
#include "edyn/shapes/plane_shape.hpp"
#include "edyn/shapes/shape_aabb.hpp"
#include "edyn/simulation/island.hpp"

namespace edyn::detail {

void recentre_on_owned(registry &registry, remote_client &rc) {
    if (!rc.aabb_follows_owned) return;
    auto sum = vector3_zero;
    auto count = 0;
    for (auto e : rc.owned_entities) {
        if (!registry.valid(e)) continue;
        if (auto *pos = registry.try_get<position>(e)) {
            sum = sum + *pos;
            ++count;
        }
    }
    if (count == 0) return;
    auto centre = sum / scalar(count);
    auto half = (rc.aabb_of_interest.max - rc.aabb_of_interest.min) * scalar(0.5);
    rc.aabb_of_interest = {centre - half, centre + half};
}

namespace {

// Adds the networked constraints that join `e`, the bodies they hold, and so on through the
// moving ones: the joints of a registry whose islands live in an asynchronous worker (the
// islands of this one hold them already). A static body joins what hangs from it to nothing.
void add_joined(const registry &registry, entity e, entity_set &out) {
    auto pending = std::vector<entity>{e};
    auto joints = std::vector<constraint_ref>{};
    while (!pending.empty()) {
        auto body = pending.back();
        pending.pop_back();
        joints.clear();
        constraints_of(registry, body, joints);
        for (auto &joint : joints) {
            if (!registry.all_of<networked_tag>(joint.constraint) || !out.insert(joint.constraint)) continue;
            for (auto other : joint.body) {
                if (!registry.valid(other) || !registry.all_of<networked_tag>(other) || !out.insert(other))
                    continue;
                if (!registry.all_of<static_tag>(other)) pending.push_back(other);
            }
        }
    }
}

} // namespace

void add_with_island(const registry &registry, entity e, entity_set &out) {
    out.insert(e);
    add_joined(registry, e, out);
    auto *resident = registry.try_get<island_resident>(e);
    if (!resident || !registry.valid(resident->island_entity)) return;
    auto *isl = registry.try_get<island>(resident->island_entity);
    if (!isl) return;
    for (auto node : isl->nodes)
        if (registry.all_of<networked_tag>(node)) out.insert(node);
    for (auto edge : isl->edges) {
        if (!registry.all_of<networked_tag>(edge)) continue;
        out.insert(edge);
        if (auto *ends = registry.try_get<island_edge>(edge)) {
            for (auto body : ends->body)
                if (registry.valid(body) && registry.all_of<networked_tag>(body)) out.insert(body);
        }
    }
}

// A body's bounding box at its present transform (in asynchronous mode the main registry's AABB
// component does not follow the worker's motion), all space for a plane, a point for an entity
// without a shape.
void gather_interest_boxes(const registry &registry, std::vector<std::pair<entity, AABB>> &out) {
    out.clear();
    for (auto [e, pos] : registry.view<networked_tag, position>().each()) {
        auto box = AABB{pos, pos};
        if (registry.all_of<plane_shape>(e)) {
            // Unbounded, and few: every client has the planes.
            box = AABB{vector3_one * -plane_aabb_half_size, vector3_one * plane_aabb_half_size};
        } else if (registry.all_of<shape_index, orientation>(e)) {
            auto &orn = registry.get<orientation>(e);
            auto origin = get_rigidbody_origin(registry, e);
            box = visit_shape(registry, e, [&](const auto &shape) { return shape_aabb(shape, origin, orn); });
        }
        out.emplace_back(e, box);
    }
}

void collect_interest(const registry &registry, const std::vector<std::pair<entity, AABB>> &boxes,
                      const AABB &aabb, entity_set &out) {
    for (auto &[e, box] : boxes) {
        if (!intersect(aabb, box) || out.contains(e)) continue;
        if (registry.all_of<static_tag>(e))
            out.insert(e);
        else
            add_with_island(registry, e, out);
    }
}

void add_assets(const registry &registry, entity_set &interest) {
    auto assets = std::vector<entity>{};
    for (auto e : interest.entities()) {
        auto *member = registry.try_get<asset_member>(e);
        if (member && registry.valid(member->asset_entity) &&
            registry.all_of<asset_ref>(member->asset_entity))
            assets.push_back(member->asset_entity);
    }
    for (auto asset : assets) {
        if (!interest.insert(asset)) continue;
        for (auto &[index, e] : registry.get<asset_ref>(asset).entities)
            if (registry.valid(e)) interest.insert(e);
    }
}

} // namespace edyn::detail
