#include "edyn/simulation/narrowphase.hpp"
#include "edyn/collision/collide.hpp"
#include "edyn/collision/manifold_update.hpp"
#include "edyn/collision/shape_epoch.hpp"
#include "edyn/dynamics/material_mixing.hpp"
#include "edyn/dynamics/orientation.hpp"
#include "edyn/dynamics/rigidbody.hpp"
#include "edyn/dynamics/tags.hpp"
#include "edyn/dynamics/velocity.hpp"
#include "edyn/dynamics/visit_shape.hpp"
#include "edyn/parallel/parallel_for.hpp"
#include "edyn/simulation/contact_events.hpp"
#include "edyn/simulation/settings.hpp"

namespace edyn {

namespace {

// Records a manifold's events in the order documented in contact_events.hpp.
void record_events(contact_events &events, entity manifold, const contact_point_changes &changes) {
    using kind = contact_events::kind;
    if (changes.contact_started()) events.pending.push_back({kind::started, manifold, 0});
    for (std::uint32_t i = 0; i < changes.num_created; ++i) {
        events.pending.push_back({kind::point_created, manifold, changes.created[i]});
    }
    for (std::uint32_t i = 0; i < changes.num_destroyed; ++i) {
        events.pending.push_back({kind::point_destroyed, manifold, changes.destroyed[i]});
    }
    if (changes.contact_ended()) events.pending.push_back({kind::ended, manifold, 0});
}

void set_material(contact_point &cp, const material_base &mixed) {
    cp.friction = mixed.friction;
    cp.restitution = mixed.restitution;
    cp.roll_friction = mixed.roll_friction;
    cp.spin_friction = mixed.spin_friction;
    cp.stiffness = mixed.stiffness;
    cp.damping = mixed.damping;
}

// Mixed material values are stored on new points for the program to read; the solver mixes
// again every step so that material changes apply at once.
void fill_materials(const registry &registry, contact_manifold &manifold,
                    const contact_point_changes &changes) {
    auto *matA = registry.try_get<material>(manifold.body[0]);
    auto *matB = registry.try_get<material>(manifold.body[1]);
    if (!matA || !matB) return;
    // Per-vertex materials of a mesh: every point, every step, as points move over the mesh.
    if (has_per_vertex_material(registry, manifold)) {
        for (std::uint32_t i = 0; i < manifold.num_points; ++i) {
            auto &cp = manifold.point[manifold.ids[i]];
            set_material(cp, get_point_material(registry, manifold.body[0], manifold.body[1], cp));
        }
        return;
    }
    if (changes.num_created == 0) return;
    auto mixed = get_mixed_material(registry, *matA, *matB);
    for (std::uint32_t i = 0; i < changes.num_created; ++i)
        set_material(manifold.point[changes.created[i]], mixed);
}

bool is_resting(const registry &registry, entity body) {
    return registry.any_of<static_tag, sleeping_tag>(body);
}

std::uint32_t shape_epoch_of(const registry &registry, entity body) {
    auto *epoch = registry.try_get<shape_epoch>(body);
    return epoch ? epoch->value : 0;
}

// Upper bound of how fast any two points of the bodies approach each other.
scalar approach_speed(const registry &registry, entity a, entity b) {
    auto motion = [&](entity e, vector3 &v) {
        auto *lv = registry.try_get<linvel>(e);
        auto *av = registry.try_get<angvel>(e);
        auto *aabb = registry.try_get<AABB>(e);
        if (!lv || !av) return scalar(0);
        v = *lv;
        return aabb ? length(*av) * length(aabb_half_extents(*aabb)) : scalar(0);
    };
    vector3 vA = vector3_zero, vB = vector3_zero;
    auto spinA = motion(a, vA), spinB = motion(b, vB);
    return length(vA - vB) + spinA + spinB;
}

// Closest points of one manifold's pair, the manifold updated in place. Reads the registry and
// writes only the manifold, so that manifolds can be processed at once on several threads.
contact_point_changes collide_manifold(const registry &registry, contact_manifold &manifold, scalar dt) {
    auto a = manifold.body[0], b = manifold.body[1];
    // Only pairs with a dynamic body interact, and two resting bodies stay as they are.
    if (!registry.any_of<dynamic_tag>(a) && !registry.any_of<dynamic_tag>(b)) return {};
    if (is_resting(registry, a) && is_resting(registry, b)) return {};
    if (!registry.all_of<shape_index>(a) || !registry.all_of<shape_index>(b)) return {};

    auto &ornA = registry.get<orientation>(a);
    auto &ornB = registry.get<orientation>(b);
    manifold_transforms tf{get_rigidbody_origin(registry, a), ornA, get_rigidbody_origin(registry, b), ornB};
    // Points are looked for as far as the bodies can travel towards each other in a step,
    // so that the solver can stop them at the surface instead of inside it.
    auto approach = approach_speed(registry, a, b) * dt;
    manifold.separation_threshold = contact_breaking_threshold + approach;
    shape_epoch_pair epochs{shape_epoch_of(registry, a), shape_epoch_of(registry, b)};
    // Worked out once, and again only when a shape changed: the bodies' shapes are not looked up
    // for it every step. (A pair that skips the steps above has no moving body: its points, if
    // any, stay as they are until one moves, which brings it here.)
    auto &materials = manifold.point_materials;
    if (!materials.known || materials.shape_epochs != epochs) {
        materials.per_vertex = has_per_vertex_material(registry, a, b);
        materials.shape_epochs = epochs;
        materials.known = true;
    }
    if (can_reuse_contacts(manifold, tf, approach, epochs)) {
        return refresh_contact_manifold(manifold, tf);
    }
    collision_context ctx{tf.posA, tf.ornA, tf.posB, tf.ornB, manifold.separation_threshold};
    collision_result result;
    visit_shape(registry, a, [&](const auto &shapeA) {
        visit_shape(registry, b, [&](const auto &shapeB) {
            using A = std::decay_t<decltype(shapeA)>;
            using B = std::decay_t<decltype(shapeB)>;
            if constexpr (!(is_static_only_shape_v<A> && is_static_only_shape_v<B>)) {
                collide(shapeA, shapeB, ctx, result);
            }
        });
    });
    auto shapes_changed = manifold.last_collide.valid && manifold.last_collide.shape_epochs != epochs;
    auto changes = update_contact_manifold(manifold, tf, result, shapes_changed);
    remember_collide(manifold, tf, epochs);
    return changes;
}

// Manifolds per parallel range: below this many, collision runs on the calling thread.
constexpr std::size_t manifolds_per_task = 64;

} // namespace

void run_narrowphase(registry &registry, world_state &world) {
    auto &events = registry.ctx().emplace<contact_events>();
    bool record = events.has_listeners();

    world.manifolds.clear();
    for (auto e : registry.view<contact_manifold>(exclude<sleeping_tag>))
        world.manifolds.push_back(e);
    // The view yields the newest manifold first; solving in creation order is the natural and
    // reproducible order.
    std::reverse(world.manifolds.begin(), world.manifolds.end());

    // Collision first, each manifold on its own (in parallel when a scheduler is there), and the
    // materials of its new points...
    auto dt = registry.ctx().get<settings>().fixed_dt;
    auto &manifold_pool = registry.storage<contact_manifold>();
    world.manifold_changes.resize(world.manifolds.size());
    auto collide_one = [&](std::size_t i) {
        auto &manifold = manifold_pool.get(world.manifolds[i]);
        auto &changes = world.manifold_changes[i];
        changes = collide_manifold(registry, manifold, dt);
        fill_materials(registry, manifold, changes);
    };
    parallel_for(world.scheduler.get(), std::size_t(0), world.manifolds.size(), manifolds_per_task,
                 collide_one);

    // ...then what the registry shares, in the manifolds' order: events and islands. Only the
    // manifolds whose points came or went have any.
    for (std::size_t i = 0; i < world.manifolds.size(); ++i) {
        auto &changes = world.manifold_changes[i];
        if (changes.num_created == 0 && changes.num_destroyed == 0) continue;
        auto manifold_entity = world.manifolds[i];
        if (record) record_events(events, manifold_entity, changes);

        if (changes.contact_started()) {
            auto &manifold = manifold_pool.get(manifold_entity);
            world.islands.link_edge(registry, manifold_entity, manifold.body[0], manifold.body[1]);
        } else if (changes.contact_ended()) {
            world.islands.unlink_edge(registry, manifold_entity);
        }
    }
}

} // namespace edyn
