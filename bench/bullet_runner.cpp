// The Bullet side of edyn-bench. The scene is read from a registry filled by the same builders
// edyn runs (scenes/), so both engines get the same bodies at the same places, with the same
// masses, inertias and materials. Bullet then runs as its users usually set it up for games:
// btDiscreteDynamicsWorld, btDbvtBroadphase, btSequentialImpulseConstraintSolver with 10
// iterations, one 1/60 s step per stepSimulation call (no sub-steps). Point constraints become
// btPoint2PointConstraint with the same pivots; hinges, CV joints and cones are converted in
// bullet_joints.cpp, which also excludes from collision the pairs edyn excludes. Convex
// polyhedra become btConvexHullShape over the same vertices (with Bullet's default collision
// margin of 4 cm around them, as its users have them); triangle meshes a btBvhTriangleMeshShape
// over the same vertices and triangles, with Bullet's internal edge utility, which plays the
// part of edyn's inactive edges (contacts on an edge between two triangles lying flat or
// concave take the triangle's normal).
#include "bench.hpp"
#include "bullet_joints.hpp"
#include "to_bullet.hpp"
#include <BulletCollision/CollisionDispatch/btInternalEdgeUtility.h>
#include <algorithm>
#include <btBulletDynamicsCommon.h>
#include <chrono>
#include <cmath>
#include <edyn/dynamics/visit_shape.hpp>
#include <malloc.h>
#include <memory>
#include <optional>
#include <stdexcept>
#include <unordered_map>
#include <variant>

namespace edyn_bench {

namespace {

// A rigid body as both engines describe it.
struct body_desc {
    edyn::entity entity{edyn::null};
    // None for a static anchor that only holds joints, or a rag doll's shoulder or arm twist
    // (they touch nothing).
    std::optional<edyn::shapes_variant_t> shape;
    bool is_static{false};
    double mass{0};
    edyn::vector3 inertia{}; // principal moments, object axes
    double friction{0};
    double restitution{0};
    edyn::vector3 position{};
    edyn::quaternion orientation{edyn::quaternion_identity};
};

// A ball joint between bodies[body[0]] and bodies[body[1]], pivots relative to each origin.
struct joint_desc {
    std::size_t body[2]{0, 0};
    edyn::vector3 pivot[2]{};
};

struct scene_desc {
    std::vector<body_desc> bodies;
    std::vector<joint_desc> joints;
    scene_joints other_joints; // hinges, CV joints and cones, and the collision exclusions
    std::size_t tracked_index{static_cast<std::size_t>(-1)};
};

template<typename... T>
std::size_t count_constraints(const edyn::registry &registry, edyn::constraint_type_list<T...>) {
    return (registry.view<T>().size() + ...);
}

void describe_constraints(edyn::registry &registry,
                          const std::unordered_map<edyn::entity, std::size_t> &index, scene_desc &scene) {
    auto points = registry.view<edyn::point_constraint>();
    auto converted = points.size() + registry.view<edyn::hinge_constraint>().size() +
                     registry.view<edyn::cvjoint_constraint>().size() +
                     registry.view<edyn::cone_constraint>().size();
    if (count_constraints(registry, edyn::constraint_types{}) != converted) {
        throw std::invalid_argument(
            "edyn-bench: only point, hinge, CV joint and cone constraints are supported");
    }
    for (auto e : in_creation_order(points)) {
        const auto &c = points.get<edyn::point_constraint>(e);
        if (c.friction_torque != 0) {
            throw std::invalid_argument("edyn-bench: point constraints with friction are not supported");
        }
        joint_desc joint;
        for (int i = 0; i < 2; ++i) {
            joint.body[i] = index.at(c.body[i]);
            joint.pivot[i] = c.pivot[i];
        }
        scene.joints.push_back(joint);
    }
    std::vector<edyn::entity> entities;
    for (const auto &body : scene.bodies)
        entities.push_back(body.entity);
    scene.other_joints = describe_joints(registry, entities);
}

scene_desc describe_scene(edyn::registry &registry, edyn::entity tracked) {
    scene_desc scene;
    std::unordered_map<edyn::entity, std::size_t> index;
    for (auto e : in_creation_order(registry.view<edyn::rigidbody_tag>())) {
        if (registry.all_of<edyn::center_of_mass>(e)) {
            throw std::invalid_argument("edyn-bench: bodies with an offset centre of mass are not supported");
        }
        body_desc desc;
        desc.entity = e;
        if (registry.all_of<edyn::shape_index>(e)) {
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
        if (e == tracked) scene.tracked_index = scene.bodies.size();
        index.emplace(e, scene.bodies.size());
        scene.bodies.push_back(std::move(desc));
    }
    describe_constraints(registry, index, scene);
    return scene;
}

// The arrays a btBvhTriangleMeshShape reads through its btTriangleIndexVertexArray, which
// copies none of them, and its internal edge information.
struct bt_mesh_data {
    std::vector<btScalar> vertices; // x, y, z of each vertex
    std::vector<int> indices;       // three per triangle
    btTriangleIndexVertexArray array;
    btTriangleInfoMap edge_info;
};

// A triangle mesh as Bullet's static concave mesh. Both engines' triangles face the side from
// which their vertices run counter-clockwise (Bullet's btTriangleShape normal is
// (v1 - v0) x (v2 - v0), as edyn's is), so the indices are kept in edyn's order.
std::unique_ptr<btCollisionShape> make_bt_mesh(const edyn::triangle_mesh &mesh,
                                               std::vector<std::shared_ptr<void>> &owned) {
    auto data = std::make_shared<bt_mesh_data>();
    auto vertices = mesh.get_vertices();
    auto indices = mesh.get_indices();
    data->vertices.reserve(vertices.size() * 3);
    for (const auto &v : vertices)
        data->vertices.insert(data->vertices.end(), {btScalar(v.x), btScalar(v.y), btScalar(v.z)});
    data->indices.assign(indices.begin(), indices.end());
    btIndexedMesh part;
    part.m_numTriangles = static_cast<int>(data->indices.size() / 3);
    part.m_triangleIndexBase = reinterpret_cast<const unsigned char *>(data->indices.data());
    part.m_triangleIndexStride = 3 * sizeof(int);
    part.m_numVertices = static_cast<int>(vertices.size());
    part.m_vertexBase = reinterpret_cast<const unsigned char *>(data->vertices.data());
    part.m_vertexStride = 3 * sizeof(btScalar);
    part.m_indexType = PHY_INTEGER;
    part.m_vertexType = sizeof(btScalar) == sizeof(double) ? PHY_DOUBLE : PHY_FLOAT;
    data->array.addIndexedMesh(part, PHY_INTEGER);
    auto shape = std::make_unique<btBvhTriangleMeshShape>(&data->array, true, true);
    btGenerateInternalEdgeInfo(shape.get(), &data->edge_info);
    owned.push_back(std::move(data));
    return shape;
}

// Bullet calls this for each new contact point of a body with CF_CUSTOM_MATERIAL_CALLBACK (the
// mesh). A convex-concave pair's manifold always has the convex body first and the mesh's
// triangle second.
bool adjust_internal_edge_contacts(btManifoldPoint &cp, const btCollisionObjectWrapper *wrapper0, int, int,
                                   const btCollisionObjectWrapper *wrapper1, int part1, int index1) {
    btAdjustInternalEdgeContacts(cp, wrapper1, wrapper0, part1, index1);
    return false;
}

std::unique_ptr<btCollisionShape> make_bt_shape(const edyn::shapes_variant_t &shape,
                                                std::vector<std::shared_ptr<void>> &owned) {
    return std::visit(
        [&owned](const auto &s) -> std::unique_ptr<btCollisionShape> {
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
            } else if constexpr (std::is_same_v<T, edyn::polyhedron_shape>) {
                auto hull = std::make_unique<btConvexHullShape>();
                for (const auto &v : s.mesh->vertices)
                    hull->addPoint(to_bt(v), false);
                hull->recalcLocalAabb();
                return hull;
            } else if constexpr (std::is_same_v<T, edyn::mesh_shape>) {
                return make_bt_mesh(*s.trimesh, owned);
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
        for (auto &joint : joints)
            world.removeConstraint(joint.get());
        for (std::size_t i = 0; i < bodies.size(); ++i) {
            if (in_world[i]) world.removeRigidBody(bodies[i].get());
        }
    }

    bullet_world(const bullet_world &) = delete;
    bullet_world &operator=(const bullet_world &) = delete;

    btRigidBody *add(const body_desc &desc) {
        // A shapeless anchor stays out of the world: the joints read its transform, and the
        // solver treats every body of zero mass as fixed. A shapeless moving body is in the
        // world with no collision group or mask, which keeps it out of every pair.
        auto &shape = shapes.emplace_back(desc.shape ? make_bt_shape(*desc.shape, owned)
                                                     : std::make_unique<btEmptyShape>());
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
        if (desc.shape && std::holds_alternative<edyn::mesh_shape>(*desc.shape)) {
            body->setCollisionFlags(body->getCollisionFlags() |
                                    btCollisionObject::CF_CUSTOM_MATERIAL_CALLBACK);
            gContactAddedCallback = adjust_internal_edge_contacts;
        }
        in_world.push_back(desc.shape.has_value() || !desc.is_static);
        if (desc.shape) {
            world.addRigidBody(body.get());
        } else if (!desc.is_static) {
            world.addRigidBody(body.get(), 0, 0);
        }
        return body.get();
    }

    void add(const joint_desc &desc) {
        auto &a = *bodies.at(desc.body[0]), &b = *bodies.at(desc.body[1]);
        auto &joint = joints.emplace_back(
            std::make_unique<btPoint2PointConstraint>(a, b, to_bt(desc.pivot[0]), to_bt(desc.pivot[1])));
        world.addConstraint(joint.get());
    }

    // The largest distance between the two pivots of any joint, in m.
    double max_joint_error() const {
        double worst = 0;
        for (const auto &joint : joints) {
            auto a = joint->getRigidBodyA().getCenterOfMassTransform() * joint->getPivotInA();
            auto b = joint->getRigidBodyB().getCenterOfMassTransform() * joint->getPivotInB();
            worst = std::max(worst, double((a - b).length()));
        }
        return worst;
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
    std::vector<std::shared_ptr<void>> owned; // what the shapes point into; outlives them
    std::vector<std::unique_ptr<btCollisionShape>> shapes;
    std::vector<std::unique_ptr<btRigidBody>> bodies;
    std::vector<bool> in_world;
    std::vector<std::unique_ptr<btPoint2PointConstraint>> joints;
};

} // namespace

run_result run_bullet(const scene_spec &spec) {
    run_result result;
    result.scene = spec.scene;
    result.engine = "bullet";
    result.stability_metric = stability_metric(spec.scene);

    scene_desc scene;
    edyn::vector3 gravity{};
    double dt = 0;
    {
        edyn::registry registry;
        // Only the scene's description is read from it, so nothing needs a worker.
        edyn::attach(registry, edyn::init_config{edyn::execution_mode::sequential});
        auto tracked = build_scene(registry, spec);
        scene = describe_scene(registry, tracked);
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
    std::vector<btRigidBody *> bt_bodies, dynamic_bodies;
    for (std::size_t i = 0; i < scene.bodies.size(); ++i) {
        auto *body = world.add(scene.bodies[i]);
        bt_bodies.push_back(body);
        if (i == scene.tracked_index) tracked = body;
        if (!scene.bodies[i].is_static) {
            ++result.bodies;
            dynamic_bodies.push_back(body);
        }
    }
    for (const auto &joint : scene.joints)
        world.add(joint);
    bullet_joints other_joints(world.dynamics_world(), bt_bodies, scene.other_joints, dt);
    btVector3 tracked_start = tracked ? tracked->getWorldTransform().getOrigin() : btVector3(0, 0, 0);
    scene = {};

    auto joints = tracks_joint_error(spec.scene);
    auto joint_error = [&] { return std::max(world.max_joint_error(), other_joints.worst_error()); };
    double worst_joint_error = joints ? joint_error() : 0;
    std::vector<double> step_ms;
    step_ms.reserve(spec.steps);
    for (unsigned i = 0; i < spec.steps; ++i) {
        auto start = std::chrono::steady_clock::now();
        world.step(dt);
        auto end = std::chrono::steady_clock::now();
        step_ms.push_back(std::chrono::duration<double, std::milli>(end - start).count());
        if (joints) worst_joint_error = std::max(worst_joint_error, joint_error());
    }

    auto stats = summarize_steps(step_ms, spec.warmup);
    result.steps = spec.steps;
    result.measured = stats.measured;
    result.median_ms = stats.median_ms;
    result.p95_ms = stats.p95_ms;
    auto [points, deepest] = world.contacts();
    result.contacts = points;
    if (joints) {
        result.stability = worst_joint_error;
    } else if (spec.scene == "mesh") {
        std::vector<edyn::vector3> centres;
        for (auto *body : dynamic_bodies) {
            const auto &o = body->getCenterOfMassPosition();
            centres.push_back({edyn::scalar(o.x()), edyn::scalar(o.y()), edyn::scalar(o.z())});
        }
        result.stability = count_below_terrain(centres);
    } else if (tracked) {
        result.stability = double((tracked->getWorldTransform().getOrigin() - tracked_start).length());
    } else {
        result.stability = deepest;
    }
    result.ok = true;
    return result;
}

} // namespace edyn_bench
