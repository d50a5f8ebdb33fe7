#include "edyn/simulation/narrowphase.hpp"
#include "edyn/collision/collide.hpp"
#include "edyn/collision/manifold_update.hpp"
#include "edyn/collision/shape_epoch.hpp"
#include "edyn/config/assert.hpp"
#include "edyn/config/prefetch.hpp"
#include "edyn/dynamics/material_mixing.hpp"
#include "edyn/dynamics/orientation.hpp"
#include "edyn/dynamics/rigidbody.hpp"
#include "edyn/dynamics/tags.hpp"
#include "edyn/dynamics/velocity.hpp"
#include "edyn/dynamics/visit_shape.hpp"
#include "edyn/parallel/parallel_for.hpp"
#include "edyn/shapes/shape_bounding_radius.hpp"
#include "edyn/shapes/shape_extent.hpp"
#include "edyn/simulation/contact_events.hpp"
#include "edyn/simulation/settings.hpp"
#include <algorithm>
#include <cmath>
#include <type_traits>
#include <utility>

namespace edyn {

namespace {

// Records a manifold's events in the order documented in contact_events.hpp.
void record_events(contact_events &events, entity manifold, const contact_point_changes &changes) {
    using kind = contact_events::kind;
    if (changes.contact_started()) events.pending.push_back({kind::started, manifold, 0});
    // Destroyed before created: a new point may take the slot a point removed in the same step
    // freed, and its id must be left alive.
    for (std::uint32_t i = 0; i < changes.num_destroyed; ++i) {
        events.pending.push_back({kind::point_destroyed, manifold, changes.destroyed[i]});
    }
    for (std::uint32_t i = 0; i < changes.num_created; ++i) {
        events.pending.push_back({kind::point_created, manifold, changes.created[i]});
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
void fill_materials(const world_state &world, const material_mix_table *mix_table, contact_manifold &manifold,
                    const contact_point_changes &changes) {
    auto &bodyA = world.collision_bodies[to_index(manifold.body[0])];
    auto &bodyB = world.collision_bodies[to_index(manifold.body[1])];
    // Most manifolds have no new point and no per-vertex material: they read nothing more.
    auto per_vertex = bodyA.point_materials || bodyB.point_materials;
    if (changes.num_created == 0 && !per_vertex) return;
    auto *matA = world.contact_bodies[to_index(manifold.body[0])].mat;
    auto *matB = world.contact_bodies[to_index(manifold.body[1])].mat;
    if (!matA || !matB) return;
    // Per-vertex materials of a mesh: every point, every step, as points move over the mesh.
    if (per_vertex) {
        for (std::uint32_t i = 0; i < manifold.num_points; ++i) {
            auto &cp = manifold.point[manifold.ids[i]];
            set_material(cp, get_point_material(mix_table, *matA, bodyA.shape(), *matB, bodyB.shape(), cp));
        }
        return;
    }
    auto mixed = get_mixed_material(mix_table, *matA, *matB);
    for (std::uint32_t i = 0; i < changes.num_created; ++i)
        set_material(manifold.point[changes.created[i]], mixed);
}

// How a shape resists rolling (world_state::rolling).
template<typename Shape>
world_state::rolling rolling_of(const Shape &shape) {
    using rolling = world_state::rolling;
    if constexpr (std::is_same_v<Shape, sphere_shape> || std::is_same_v<Shape, capsule_shape>) {
        return rolling::both_tangents;
    } else if constexpr (std::is_same_v<Shape, cylinder_shape>) {
        return static_cast<rolling>(static_cast<int>(rolling::about_x) + static_cast<int>(shape.axis));
    } else {
        return rolling::none;
    }
}

// What collide_manifold and the contacts' gathering read of a body, from the registry and its
// AABB component: its collision_body, and its contact_body into `contact`.
world_state::collision_body collision_body_of(const registry &registry, entity e, const AABB &aabb,
                                              world_state::contact_body &contact) {
    world_state::collision_body body;
    body.dynamic = registry.all_of<dynamic_tag>(e);
    body.resting = registry.any_of<static_tag, sleeping_tag>(e);
    contact = {};
    contact.mat = registry.try_get<material>(e);
    if (auto *epoch = registry.try_get<shape_epoch>(e)) body.shape_epoch = epoch->value;
    if (!registry.all_of<shape_index>(e)) {
        if (auto *centre = registry.try_get<position>(e)) contact.centre = *centre;
        return body;
    }
    auto shape = get_shape_ref(registry, e);
    body.shape_component = shape.shape;
    body.shape_kind = static_cast<std::uint8_t>(shape.index);
    visit_shape(shape, [&](const auto &s) {
        body.bounding_radius = shape_bounding_radius(s);
        body.point_materials = has_point_materials(s);
        contact.rolls = rolling_of(s);
    });
    body.orientation = registry.get<orientation>(e);
    auto &centre = registry.get<position>(e); // of mass
    contact.centre = centre;
    body.origin = rigidbody_origin(centre, body.orientation, registry.try_get<center_of_mass>(e));
    // An upper bound of how fast any of its points moves: its centre of mass's speed, and the
    // spin times the farthest a point of the shape lies from that centre.
    auto *lv = registry.try_get<linvel>(e);
    auto *av = registry.try_get<angvel>(e);
    if (lv && av) {
        body.linvel = *lv;
        body.spin_reach =
            length(*av) * shape_reach(aabb, centre, body.bounding_radius, distance(body.origin, centre));
    }
    return body;
}

// Whether the shapes of a and b lie farther apart than `threshold`, by their bounding spheres,
// their AABBs or their extents along the line between their origins (false when none shows it).
bool shapes_apart(const world_state &world, entity a, entity b, const manifold_transforms &tf,
                  scalar threshold) {
    auto &bodyA = world.collision_bodies[to_index(a)];
    auto &bodyB = world.collision_bodies[to_index(b)];
    // (A shape without a bound has large_scalar, and the sum is then infinite.)
    auto reach = bodyA.bounding_radius + bodyB.bounding_radius + threshold;
    auto offset = tf.posB - tf.posA;
    auto distance_sqr = length_sqr(offset);
    if (distance_sqr > reach * reach) return true;
    auto &aabbA = world.collision_aabbs[to_index(a)];
    auto &aabbB = world.collision_aabbs[to_index(b)];
    if (!intersect(inset(aabbA, vector3_one * threshold), aabbB)) return true;
    // The gap along the line between the origins, each shape's support taken towards the other:
    // a separating axis that suits round and long shapes lying side by side, which the bounding
    // sphere and a turned shape's AABB hold loosely.
    if (!(distance_sqr > epsilon * epsilon)) return false;
    auto distance = std::sqrt(distance_sqr);
    auto dir = offset / distance;
    auto extentA =
        visit_shape(bodyA.shape(), [&](const auto &shape) { return shape_extent(shape, tf.ornA, dir); });
    auto extentB =
        visit_shape(bodyB.shape(), [&](const auto &shape) { return shape_extent(shape, tf.ornB, -dir); });
    return distance - extentA - extentB > threshold;
}

// Closest points of one manifold's pair, the manifold updated in place. Reads what was gathered
// of the bodies and writes only the manifold, so that manifolds can be processed at once on
// several threads.
contact_point_changes collide_manifold(const world_state &world, contact_manifold &manifold, scalar dt) {
    auto a = manifold.body[0], b = manifold.body[1];
    // Every manifold is the broadphase's, between two bodies with proxies.
    EDYN_ASSERT(std::max(to_index(a), to_index(b)) < world.collision_bodies.size());
    auto &bodyA = world.collision_bodies[to_index(a)];
    auto &bodyB = world.collision_bodies[to_index(b)];
    // Only pairs with a dynamic body interact, and two resting bodies stay as they are.
    if (!bodyA.dynamic && !bodyB.dynamic) return {};
    if (bodyA.resting && bodyB.resting) return {};
    if (!bodyA.shape_component || !bodyB.shape_component) return {};

    manifold_transforms tf{bodyA.origin, bodyA.orientation, bodyB.origin, bodyB.orientation};
    // Points are looked for as far as the bodies can travel towards each other in a step,
    // so that the solver can stop them at the surface instead of inside it.
    auto approach = (length(bodyA.linvel - bodyB.linvel) + bodyA.spin_reach + bodyB.spin_reach) * dt;
    manifold.separation_threshold = contact_breaking_threshold + approach;
    shape_epoch_pair epochs{bodyA.shape_epoch, bodyB.shape_epoch};
    if (can_reuse_contacts(manifold, tf, approach, epochs)) {
        return refresh_contact_manifold(manifold, tf);
    }
    // A pair without points whose shapes lie farther apart than the threshold gets none now
    // either; three bounds show it without collide(): the spheres about the origins that hold the
    // shapes, the AABBs, each of which holds its body's shape where the last step left it, and
    // the shapes' extents along the line between their origins. (Most pairs of a large heap are
    // such neighbours, which the broadphase's fat boxes keep together long after their shapes
    // parted.)
    if (manifold.num_points == 0 && shapes_apart(world, a, b, tf, manifold.separation_threshold)) {
        remember_collide(manifold, tf, epochs);
        return {};
    }
    collision_context ctx{tf.posA, tf.ornA, tf.posB, tf.ornB, manifold.separation_threshold};
    collision_result result;
    auto one_point = false;
    visit_shape(bodyA.shape(), [&](const auto &shapeA) {
        visit_shape(bodyB.shape(), [&](const auto &shapeB) {
            using A = std::decay_t<decltype(shapeA)>;
            using B = std::decay_t<decltype(shapeB)>;
            if constexpr (!(is_static_only_shape_v<A> && is_static_only_shape_v<B>)) {
                collide(shapeA, shapeB, ctx, result);
            }
            one_point = touches_at_one_point_v<A, B>;
        });
    });
    auto shapes_changed = manifold.last_collide.valid && manifold.last_collide.shape_epochs != epochs;
    auto changes = update_contact_manifold(manifold, tf, result, shapes_changed, one_point);
    remember_collide(manifold, tf, epochs);
    return changes;
}

// Manifolds per parallel range: below this many, collision runs on the calling thread.
constexpr std::size_t manifolds_per_task = 64;
// Pool slots per block when the manifolds awake are listed: a fixed size, so that the blocks
// and the list are the same on any number of threads.
constexpr std::uint32_t listed_per_block = 1024;
// Bodies per parallel range when their collision_body is gathered.
constexpr std::size_t bodies_per_task = 256;
// How many manifolds ahead collision asks for a manifold's bodies, after asking for the manifold
// itself twice as far ahead.
constexpr std::size_t prefetch_distance = 8;

// The manifolds of bodies awake, in the pool's order (oldest first where none was destroyed):
// the natural and reproducible order. With nothing asleep, that is the pool itself.
void list_awake_manifolds(registry &registry, world_state &world) {
    auto &manifold_pool = registry.storage<contact_manifold>();
    auto &sleeping = registry.storage<sleeping_tag>();
    const entity *pooled = manifold_pool.data();
    // They are listed on the scheduler's threads, the pool cut into blocks: each block counts
    // its manifolds awake, and lists them after those of the blocks before it. (Resized from
    // last step's size, neither cleared nor assigned: growth stays geometric, so that a growing
    // world soon stops reallocating.)
    auto pool_size = static_cast<std::uint32_t>(manifold_pool.size());
    auto num_blocks = (pool_size + listed_per_block - 1) / listed_per_block;
    auto awake = [&](std::uint32_t slot) { return sleeping.empty() || !sleeping.contains(pooled[slot]); };
    auto slots_of = [&](std::uint32_t block) {
        auto first = block * listed_per_block;
        return std::pair{first, std::min(pool_size, first + listed_per_block)};
    };
    auto &block_first = world.manifold_block_first;
    block_first.resize(num_blocks + 1);
    block_first[0] = 0;
    parallel_for(world.step_scheduler, 0u, num_blocks, 1, [&](std::uint32_t block) {
        auto [first, last] = slots_of(block);
        std::uint32_t count = 0;
        for (auto slot = first; slot < last; ++slot)
            count += awake(slot) ? 1 : 0;
        block_first[block + 1] = count;
    });
    for (std::uint32_t block = 0; block < num_blocks; ++block)
        block_first[block + 1] += block_first[block];
    auto num_manifolds = std::size_t(block_first[num_blocks]);
    world.manifolds.resize(num_manifolds);
    world.manifold_slots.resize(num_manifolds);
    parallel_for(world.step_scheduler, 0u, num_blocks, 1, [&](std::uint32_t block) {
        auto [first, last] = slots_of(block);
        auto next = block_first[block];
        for (auto slot = first; slot < last; ++slot) {
            if (!awake(slot)) continue;
            world.manifolds[next] = pooled[slot];
            world.manifold_slots[next] = slot;
            ++next;
        }
    });
}

// What the manifolds read of their bodies, body by body.
void gather_collision_bodies(const registry &registry, world_state &world) {
    auto &proxies = world.broadphase;
    std::size_t index_bound = 0;
    for (std::size_t i = 0; i < proxies.num_proxies(); ++i)
        index_bound = std::max(index_bound, std::size_t(to_index(proxies.proxy_body(i))) + 1);
    if (world.collision_bodies.size() < index_bound) {
        world.collision_bodies.resize(index_bound);
        world.collision_aabbs.resize(index_bound);
        world.contact_bodies.resize(index_bound);
    }
    parallel_for(world.step_scheduler, std::size_t(0), proxies.num_proxies(), bodies_per_task,
                 [&](std::size_t i) {
                     auto e = proxies.proxy_body(i);
                     // Every body with a proxy has an AABB component (the broadphase reads it).
                     auto &aabb = world.collision_aabbs[to_index(e)];
                     aabb = registry.get<AABB>(e);
                     world.collision_bodies[to_index(e)] =
                         collision_body_of(registry, e, aabb, world.contact_bodies[to_index(e)]);
                 });
}

// Collision, each manifold on its own (in parallel when a scheduler is there), and the materials
// of its new points.
void collide_manifolds(registry &registry, world_state &world) {
    auto &manifold_pool = registry.storage<contact_manifold>();
    auto num_manifolds = world.manifolds.size();
    auto dt = registry.ctx().get<settings>().fixed_dt;
    auto *mix_table = registry.ctx().find<material_mix_table>();
    world.manifold_changes.resize(num_manifolds);
    world.manifold_live_slots.resize(num_manifolds);
    world.pool_live_slots.resize(manifold_pool.size());
    auto collide_one = [&](std::size_t i) {
        // The manifolds lie in storage order, their bodies anywhere. A manifold twice the
        // distance ahead is asked for now: its first two lines hold what every visit reads...
        if (i + 2 * prefetch_distance < num_manifolds) {
            prefetch(&manifold_pool.value_at(world.manifold_slots[i + 2 * prefetch_distance]),
                     offsetof(contact_manifold, point));
        }
        // ...so that, by the time it is the distance ahead, its bodies can be read off it and
        // asked for, with the point slots that were live after the last step (each point's
        // first two lines are what a refresh reads and writes). Which points are live now is
        // not read off the manifold, since another thread may be colliding it.
        if (i + prefetch_distance < num_manifolds) {
            auto slot = world.manifold_slots[i + prefetch_distance];
            auto &ahead = manifold_pool.value_at(slot);
            prefetch(&world.collision_bodies[to_index(ahead.body[0])], sizeof(world_state::collision_body));
            prefetch(&world.collision_bodies[to_index(ahead.body[1])], sizeof(world_state::collision_body));
            auto live = world.pool_live_slots[slot];
            for (std::size_t k = 0; k < contact_manifold::max_contacts; ++k) {
                if (live & (1u << k)) prefetch(&ahead.point[k], 2 * cache_line_size);
            }
        }
        auto &manifold = manifold_pool.value_at(world.manifold_slots[i]);
        auto &changes = world.manifold_changes[i];
        changes = collide_manifold(world, manifold, dt);
        fill_materials(world, mix_table, manifold, changes);
        std::uint8_t live = 0;
        for (std::uint32_t k = 0; k < manifold.num_points; ++k)
            live |= static_cast<std::uint8_t>(1u << manifold.ids[k]);
        if (changes.num_created > 0 || changes.num_destroyed > 0) live |= world_state::points_changed_bit;
        world.manifold_live_slots[i] = live;
    };
    parallel_for(world.step_scheduler, std::size_t(0), num_manifolds, manifolds_per_task, collide_one);
}

// In the manifolds' order, the live slots for the next step's look-ahead and what the registry
// shares: events and islands. Only the manifolds whose points came or went have any of the
// latter, and a byte each says which those are: their changes, written on the other threads,
// are read for them alone.
void publish_changes(registry &registry, world_state &world) {
    auto &events = registry.ctx().emplace<contact_events>();
    bool record = events.has_listeners();
    auto &manifold_pool = registry.storage<contact_manifold>();
    for (std::size_t i = 0; i < world.manifolds.size(); ++i) {
        auto live = world.manifold_live_slots[i];
        world.pool_live_slots[world.manifold_slots[i]] = live & ~world_state::points_changed_bit;
        if (!(live & world_state::points_changed_bit)) continue;
        auto &changes = world.manifold_changes[i];
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

} // namespace

// What sleeps is not in the narrowphase's list of manifolds, and a kinematic body is in no
// island: each moving kinematic body wakes the bodies joined to it, and asks the broadphase for
// the bodies whose fat boxes overlap its own (every pair with a manifold) to wake those it touches.
void wake_bodies_on_moving_kinematics(registry &registry, world_state &world) {
    auto &touching = world.kinematic_touching;
    touching.clear();
    for (auto [e, v, w] : registry.view<kinematic_tag, linvel, angvel>().each()) {
        if (v == vector3_zero && w == vector3_zero) continue;
        world.islands.wake_joined_to(registry, e);
        if (!world.broadphase.contains(e)) continue;
        world.broadphase.query(world.broadphase.get_fat_aabb(e), [&, body = e](entity other) {
            auto manifold = other == body ? null : world.broadphase.get_manifold(body, other);
            if (manifold != null && registry.get<contact_manifold>(manifold).num_points > 0)
                touching.push_back(other);
        });
    }
    for (auto other : touching)
        world.islands.wake_entity(registry, other);
}

void run_narrowphase(registry &registry, world_state &world) {
    list_awake_manifolds(registry, world);
    gather_collision_bodies(registry, world);
    collide_manifolds(registry, world);
    publish_changes(registry, world);
}

} // namespace edyn
