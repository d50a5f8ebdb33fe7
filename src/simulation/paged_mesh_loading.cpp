#include "edyn/simulation/paged_mesh_loading.hpp"
#include "edyn/collision/contact_manifold.hpp"
#include "edyn/dynamics/orientation.hpp"
#include "edyn/dynamics/position.hpp"
#include "edyn/dynamics/tags.hpp"
#include "edyn/dynamics/velocity.hpp"
#include "edyn/math/matrix3x3.hpp"
#include "edyn/math/transform.hpp"
#include "edyn/shapes/paged_mesh_shape.hpp"
#include "edyn/simulation/world.hpp"

namespace edyn {

namespace {

// Bounds of the world-space box `aabb` in the space of a body at (pos, orn).
AABB to_local(const AABB &aabb, const vector3 &pos, const quaternion &orn) {
    auto basis = to_matrix3x3(conjugate(orn));
    auto he = aabb_half_extents(aabb);
    auto extent = vector3{dot(abs(basis[0]), he), dot(abs(basis[1]), he), dot(abs(basis[2]), he)};
    auto center = to_object_space(aabb_center(aabb), pos, orn);
    return {center - extent, center + extent};
}

} // namespace

void update_paged_meshes(registry &registry, world_state &world) {
    auto step = world.step_count;
    auto dt = get_fixed_dt(registry);
    for (auto [e, shape] : registry.view<paged_mesh_shape>().each()) {
        if (!shape.trimesh || !registry.all_of<AABB>(e)) continue;
        auto &paged = *shape.trimesh;
        paged.collect();
        const auto &pos = registry.get<position>(e);
        const auto &orn = registry.get<orientation>(e);
        const auto &mesh_aabb = registry.get<AABB>(e);
        // Every body, whose reach ahead may overlap the mesh before its bounds do (a body flying
        // over a valley); a sleeping one, without speed, keeps the pages under it loaded, so that
        // a ray cast at it finds the ground it rests on.
        for (auto [other, aabb, v] : registry.view<AABB, linvel, dynamic_tag>().each()) {
            auto speed = length(v);
            auto lookahead = speed * paged.lookahead_time + contact_breaking_threshold;
            auto ahead = inset(aabb, vector3_one * lookahead);
            if (!intersect(ahead, mesh_aabb)) continue;
            auto local = to_local(aabb, pos, orn);
            paged.request(inset(local, vector3_one * lookahead), step, *world.background);
            // Pages the body can touch in this step: its bounds grown by the step's travel.
            paged.require(inset(local, vector3_one * (speed * dt + contact_breaking_threshold)), step);
        }
        paged.unload_unused(step);
    }
    world.background->release_finished();
}

} // namespace edyn
