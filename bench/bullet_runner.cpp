// The Bullet side of edyn-bench. The scene is read from a registry filled by the same builders
// edyn runs (scenes/), so both engines get the same bodies at the same places, with the same
// masses, inertias and materials. Bullet then runs as its users usually set it up for games:
// btDiscreteDynamicsWorld, btDbvtBroadphase, btSequentialImpulseConstraintSolver with 10
// iterations, one 1/60 s step per stepSimulation call (no sub-steps).
#include "bench.hpp"
#include "bullet_joints.hpp"
#include <algorithm>
#include <btBulletDynamicsCommon.h>
#include <chrono>
#include <cmath>
#include <edyn/dynamics/visit_shape.hpp>
#include <malloc.h>
#include <memory>
#include <stdexcept>
#include <variant>

namespace edyn_bench {

namespace {

// A rigid body as both engines describe it.
struct body_desc {
    edyn::entity entity{edyn::null};
    edyn::shapes_variant_t shape;
    bool amorphous{false}; // no shape: a rag doll's shoulder or arm twist
    bool is_static{false};
    double mass{0};
    edyn::vector3 inertia{}; // principal moments, object axes
    double friction{0};
    double restitution{0};
    edyn::vector3 position{};
    edyn::quaternion orientation{edyn::quaternion_identity};
};

std::vector<body_desc> describe_bodies(edyn::registry &registry, edyn::entity tracked,
                                       std::size_t &tracked_index) {
    std::vector<body_desc> bodies;
    tracked_index = static_cast<std::size_t>(-1);
    for (auto e : registry.view<edyn::rigidbody_tag>()) {
        if (registry.all_of<edyn::center_of_mass>(e)) {
            throw std::invalid_argument("edyn-bench: bodies with an offset centre of mass are not supported");
        }
        body_desc desc;
        desc.entity = e;
        desc.amorphous = !registry.all_of<edyn::shape_index>(e);
        if (!desc.amorphous) {
            desc.shape =
                edyn::visit_shape(registry, e, [](const auto &s) { return edyn::shapes_variant_t{s}; });
        }
        desc.is_static = registry.all_of<edyn::static_tag>(e);
        if (!desc.is_static) {
            desc.mass = double(registry.get<edyn::mass>(e).s);
            const auto &inertia = registry.get<edyn::inertia>(e);
            auto off_diagonal = std::abs(inertia[0][1]) + std::abs(inertia[0][2]) + std::abs(inertia[1][2]);
            if (off_diagonal > edyn::scalar(1e-6) * (inertia[0][0] + inertia[1][1] + inertia[2][2])) {
                throw std::invalid_argument("edyn-bench: only bodies with diagonal inertia are supported");
            }
            desc.inertia = {inertia[0][0], inertia[1][1], inertia[2][2]};
        }
        if (auto *material = registry.try_get<edyn::material>(e)) {
            desc.friction = double(material->friction);
            desc.restitution = double(material->restitution);
        }
        desc.position = registry.get<edyn::position>(e);
        desc.orientation = registry.get<edyn::orientation>(e);
        if (e == tracked) tracked_index = bodies.size();
        bodies.push_back(std::move(desc));
    }
    return bodies;
}

btVector3 to_bt(const edyn::vector3 &v) { return {btScalar(v.x), btScalar(v.y), btScalar(v.z)}; }

std::unique_ptr<btCollisionShape> make_bt_shape(const edyn::shapes_variant_t &shape) {
    return std::visit(
        [](const auto &s) -> std::unique_ptr<btCollisionShape> {
            using T = std::decay_t<decltype(s)>;
            if constexpr (std::is_same_v<T, edyn::plane_shape>) {
                return std::make_unique<btStaticPlaneShape>(to_bt(s.normal), btScalar(s.constant));
            } else if constexpr (std::is_same_v<T, edyn::sphere_shape>) {
                return std::make_unique<btSphereShape>(btScalar(s.radius));
            } else if constexpr (std::is_same_v<T, edyn::box_shape>) {
                return std::make_unique<btBoxShape>(to_bt(s.half_extents));
            } else if constexpr (std::is_same_v<T, edyn::capsule_shape>) {
                auto r = btScalar(s.radius), h = btScalar(2 * s.half_length);
                switch (s.axis) {
                case edyn::coordinate_axis::x:
                    return std::make_unique<btCapsuleShapeX>(r, h);
                case edyn::coordinate_axis::y:
                    return std::make_unique<btCapsuleShape>(r, h);
                default:
                    return std::make_unique<btCapsuleShapeZ>(r, h);
                }
            } else if constexpr (std::is_same_v<T, edyn::cylinder_shape>) {
                auto r = btScalar(s.radius), h = btScalar(s.half_length);
                switch (s.axis) {
                case edyn::coordinate_axis::x:
                    return std::make_unique<btCylinderShapeX>(btVector3(h, r, r));
                case edyn::coordinate_axis::y:
                    return std::make_unique<btCylinderShape>(btVector3(r, h, r));
                default:
                    return std::make_unique<btCylinderShapeZ>(btVector3(r, r, h));
                }
            } else {
                throw std::invalid_argument("edyn-bench: a shape the Bullet scenes do not support");
            }
        },
        shape);
}

// A Bullet world with the objects it needs, destroyed in the right order.
class bullet_world {
public:
    bullet_world(const edyn::vector3 &gravity, bool sleeping)
        : sleeping(sleeping)
        , dispatcher(&configuration)
        , world(&dispatcher, &broadphase, &solver, &configuration) {
        world.setGravity(to_bt(gravity));
        world.getSolverInfo().m_numIterations = 10;
    }

    ~bullet_world() {
        for (auto &body : bodies)
            world.removeRigidBody(body.get());
    }

    bullet_world(const bullet_world &) = delete;
    bullet_world &operator=(const bullet_world &) = delete;

    btRigidBody *add(const body_desc &desc) {
        auto &shape = shapes.emplace_back(desc.amorphous ? std::make_unique<btEmptyShape>()
                                                         : make_bt_shape(desc.shape));
        btTransform transform;
        transform.setOrigin(to_bt(desc.position));
        transform.setRotation(btQuaternion(btScalar(desc.orientation.x), btScalar(desc.orientation.y),
                                           btScalar(desc.orientation.z), btScalar(desc.orientation.w)));
        auto mass = desc.is_static ? btScalar(0) : btScalar(desc.mass);
        btRigidBody::btRigidBodyConstructionInfo info(mass, nullptr, shape.get(), to_bt(desc.inertia));
        info.m_startWorldTransform = transform;
        // Bullet multiplies the two bodies' friction where edyn takes their geometric mean:
        // giving Bullet the square root of each makes every pair's friction the same as edyn's.
        info.m_friction = btScalar(std::sqrt(desc.friction));
        // Restitution mixes differently too (Bullet multiplies, edyn takes the larger); the
        // benchmark scenes have none, where both agree.
        info.m_restitution = btScalar(desc.restitution);
        auto &body = bodies.emplace_back(std::make_unique<btRigidBody>(info));
        if (!sleeping && !desc.is_static) body->setActivationState(DISABLE_DEACTIVATION);
        if (desc.amorphous) {
            // Nothing to collide with: no filter group or mask keeps it out of every pair.
            world.addRigidBody(body.get(), 0, 0);
        } else {
            world.addRigidBody(body.get());
        }
        return body.get();
    }

    void step(double dt) { world.stepSimulation(btScalar(dt), 0); }

    btDiscreteDynamicsWorld &dynamics_world() noexcept { return world; }

    // Contact points in every manifold and the deepest penetration among them.
    std::pair<std::size_t, double> contacts() {
        std::size_t points = 0;
        double deepest = 0;
        auto count = dispatcher.getNumManifolds();
        for (int i = 0; i < count; ++i) {
            auto *manifold = dispatcher.getManifoldByIndexInternal(i);
            points += static_cast<std::size_t>(manifold->getNumContacts());
            for (int j = 0; j < manifold->getNumContacts(); ++j) {
                deepest = std::max(deepest, -double(manifold->getContactPoint(j).getDistance()));
            }
        }
        return {points, deepest};
    }

private:
    bool sleeping;
    btDefaultCollisionConfiguration configuration;
    btCollisionDispatcher dispatcher;
    btDbvtBroadphase broadphase;
    btSequentialImpulseConstraintSolver solver;
    btDiscreteDynamicsWorld world;
    std::vector<std::unique_ptr<btCollisionShape>> shapes;
    std::vector<std::unique_ptr<btRigidBody>> bodies;
};

} // namespace

run_result run_bullet(const scene_spec &spec) {
    run_result result;
    result.scene = spec.scene;
    result.engine = "bullet";
    result.stability_metric = stability_metric(spec.scene);

    std::vector<body_desc> bodies;
    scene_joints joints;
    std::size_t tracked_index = 0;
    edyn::vector3 gravity{};
    double dt = 0;
    {
        edyn::registry registry;
        edyn::attach(registry);
        auto tracked = build_scene(registry, spec);
        bodies = describe_bodies(registry, tracked, tracked_index);
        std::vector<edyn::entity> entities;
        for (const auto &desc : bodies)
            entities.push_back(desc.entity);
        joints = describe_joints(registry, entities);
        gravity = edyn::get_gravity(registry);
        dt = double(edyn::get_fixed_dt(registry));
        edyn::detach(registry);
    }
    // The edyn registry that described the scene is gone: give its memory back so that the
    // peak counts Bullet's own.
    malloc_trim(0);
    reset_peak_rss();

    bullet_world world(gravity, spec.sleeping);
    btRigidBody *tracked = nullptr;
    std::vector<btRigidBody *> bt_bodies;
    for (std::size_t i = 0; i < bodies.size(); ++i) {
        auto *body = world.add(bodies[i]);
        bt_bodies.push_back(body);
        if (i == tracked_index) tracked = body;
        if (!bodies[i].is_static) ++result.bodies;
    }
    bullet_joints bt_joints(world.dynamics_world(), bt_bodies, joints, dt);
    joints = {};
    double worst_joint = 0;
    btVector3 tracked_start = tracked ? tracked->getWorldTransform().getOrigin() : btVector3(0, 0, 0);
    bodies.clear();
    bodies.shrink_to_fit();

    std::vector<double> step_ms;
    step_ms.reserve(spec.steps);
    for (unsigned i = 0; i < spec.steps; ++i) {
        auto start = std::chrono::steady_clock::now();
        world.step(dt);
        auto end = std::chrono::steady_clock::now();
        step_ms.push_back(std::chrono::duration<double, std::milli>(end - start).count());
        if (!bt_joints.empty()) worst_joint = std::max(worst_joint, bt_joints.worst_error());
    }

    auto stats = summarize_steps(step_ms, spec.warmup);
    result.steps = spec.steps;
    result.measured = stats.measured;
    result.median_ms = stats.median_ms;
    result.p95_ms = stats.p95_ms;
    auto [points, deepest] = world.contacts();
    result.contacts = points;
    if (tracked) {
        result.stability = double((tracked->getWorldTransform().getOrigin() - tracked_start).length());
    } else if (!bt_joints.empty()) {
        result.stability = worst_joint;
    } else {
        result.stability = deepest;
    }
    result.ok = true;
    return result;
}

} // namespace edyn_bench
