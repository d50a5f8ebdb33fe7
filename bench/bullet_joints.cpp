#include "bullet_joints.hpp"
#include "to_bullet.hpp"
#include <algorithm>
#include <btBulletDynamicsCommon.h>
#include <cmath>
#include <map>
#include <stdexcept>
#include <unordered_map>

namespace edyn_bench {

namespace {

btTransform frame(const joint_desc &j, int i) { return btTransform(to_bt(j.basis[i]), to_bt(j.pivot[i])); }

edyn::matrix3x3 rotate_columns(const edyn::quaternion &q, const edyn::matrix3x3 &m) {
    return edyn::matrix3x3_columns(edyn::rotate(q, m.column(0)), edyn::rotate(q, m.column(1)),
                                   edyn::rotate(q, m.column(2)));
}

using index_map = std::unordered_map<edyn::entity, std::size_t>;

std::size_t index_of(const index_map &indices, edyn::entity e) {
    auto it = indices.find(e);
    if (it == indices.end())
        throw std::invalid_argument("edyn-bench: a joint holds a body Bullet does not have");
    return it->second;
}

joint_desc describe_hinge(const index_map &indices, const edyn::hinge_constraint &c) {
    joint_desc j;
    j.type = joint_desc::kind::hinge;
    for (int i = 0; i < 2; ++i) {
        j.body[i] = index_of(indices, c.body[i]);
        j.pivot[i] = c.pivot[i];
        // Bullet's hinge turns about z and measures its angle from x towards y; edyn's about the
        // first column, from the second towards the third: the same turn, columns rotated.
        const auto &f = c.frame[i];
        j.basis[i] = edyn::matrix3x3_columns(f.column(1), f.column(2), f.column(0));
    }
    j.limit[0] = double(c.angle_min);
    j.limit[1] = double(c.angle_max);
    j.friction_torque = double(c.friction_torque);
    return j;
}

joint_desc describe_swing(const edyn::registry &registry, const index_map &indices,
                          const edyn::cvjoint_constraint &cv, const edyn::cone_constraint &cone) {
    if (std::abs(cv.twist_min + cv.twist_max) >
        edyn::scalar(1e-6) * std::max(edyn::scalar(1), cv.twist_max)) {
        throw std::invalid_argument("edyn-bench: Bullet's cone twist joints need symmetric twist limits");
    }
    joint_desc j;
    j.type = joint_desc::kind::cone_twist;
    for (int i = 0; i < 2; ++i) {
        j.body[i] = index_of(indices, cv.body[i]);
        j.pivot[i] = cv.pivot[i];
    }
    // Bullet's cone is about body A's x axis, which swings onto body B's x axis: A's frame is
    // edyn's cone frame and B's x axis points from the joint to the point the cone holds.
    j.basis[0] = cone.frame;
    const auto &qa = registry.get<edyn::orientation>(cv.body[0]);
    const auto &qb = registry.get<edyn::orientation>(cv.body[1]);
    auto tip = edyn::normalize(cone.pivot[1] - cv.pivot[1]);
    auto axis_world = edyn::rotate(qa, cone.frame.column(0));
    auto tip_world = edyn::rotate(qb, tip);
    // B's frame is A's swung along the shortest arc onto the tip's direction as the scene was
    // built, so that Bullet's twist starts at zero, as edyn's does.
    auto b_world = rotate_columns(edyn::shortest_arc(axis_world, tip_world), rotate_columns(qa, cone.frame));
    j.basis[1] = rotate_columns(edyn::conjugate(qb), b_world);
    j.limit[0] = double(cone.span_angle[0]);
    j.limit[1] = double(cone.span_angle[1]);
    j.limit[2] = double(cv.twist_max);
    return j;
}

} // namespace

scene_joints describe_joints(const edyn::registry &registry, const std::vector<edyn::entity> &bodies) {
    index_map indices;
    for (std::size_t i = 0; i < bodies.size(); ++i)
        indices.emplace(bodies[i], i);

    scene_joints scene;
    for (auto e : in_creation_order(registry.view<edyn::hinge_constraint>())) {
        scene.joints.push_back(describe_hinge(indices, registry.get<edyn::hinge_constraint>(e)));
    }
    std::map<std::pair<edyn::entity, edyn::entity>, edyn::entity> cones;
    for (auto e : registry.view<edyn::cone_constraint>()) {
        const auto &cone = registry.get<edyn::cone_constraint>(e);
        cones.emplace(std::make_pair(cone.body[0], cone.body[1]), e);
    }
    for (auto e : in_creation_order(registry.view<edyn::cvjoint_constraint>())) {
        const auto &cv = registry.get<edyn::cvjoint_constraint>(e);
        auto it = cones.find({cv.body[0], cv.body[1]});
        if (it == cones.end()) throw std::invalid_argument("edyn-bench: a CV joint without a cone");
        scene.joints.push_back(
            describe_swing(registry, indices, cv, registry.get<edyn::cone_constraint>(it->second)));
        cones.erase(it);
    }
    if (!cones.empty()) throw std::invalid_argument("edyn-bench: a cone without a CV joint");

    for (std::size_t i = 0; i < bodies.size(); ++i) {
        const auto *exclusion = registry.try_get<edyn::collision_exclusion>(bodies[i]);
        if (!exclusion) continue;
        for (std::size_t k = 0; k < exclusion->num_entities; ++k) {
            auto other = index_of(indices, exclusion->entities[k]);
            if (i < other) scene.exclusions.emplace_back(i, other);
        }
    }
    return scene;
}

bullet_joints::bullet_joints(btDiscreteDynamicsWorld &world, const std::vector<btRigidBody *> &bodies,
                             const scene_joints &joints, double dt)
    : world(world) {
    for (auto [a, b] : joints.exclusions) {
        bodies[a]->setIgnoreCollisionCheck(bodies[b], true);
        bodies[b]->setIgnoreCollisionCheck(bodies[a], true);
    }
    for (const auto &j : joints.joints) {
        auto &a = *bodies[j.body[0]], &b = *bodies[j.body[1]];
        if (j.type == joint_desc::kind::hinge) {
            auto hinge = std::make_unique<btHingeConstraint>(a, b, frame(j, 0), frame(j, 1));
            // Bullet measures B's turn seen from A the other way round: its angle is edyn's negated.
            hinge->setLimit(btScalar(-j.limit[1]), btScalar(-j.limit[0]));
            // A motor held at zero speed whose impulse is capped is Bullet's way to friction.
            if (j.friction_torque > 0) {
                hinge->enableAngularMotor(true, 0, btScalar(j.friction_torque * dt));
            }
            constraints.push_back(std::move(hinge));
        } else {
            auto cone = std::make_unique<btConeTwistConstraint>(a, b, frame(j, 0), frame(j, 1));
            cone->setLimit(btScalar(j.limit[0]), btScalar(j.limit[1]), btScalar(j.limit[2]));
            constraints.push_back(std::move(cone));
        }
        // Bodies held by a joint touch at it: edyn's rag dolls exclude those pairs too.
        world.addConstraint(constraints.back().get(), true);
    }
}

bullet_joints::~bullet_joints() {
    for (auto &c : constraints)
        world.removeConstraint(c.get());
}

double bullet_joints::worst_error() const {
    double worst = 0;
    for (const auto &c : constraints) {
        btTransform frame_a, frame_b;
        if (auto *hinge = dynamic_cast<const btHingeConstraint *>(c.get())) {
            frame_a = hinge->getAFrame();
            frame_b = hinge->getBFrame();
        } else {
            auto *cone = static_cast<const btConeTwistConstraint *>(c.get());
            frame_a = cone->getAFrame();
            frame_b = cone->getBFrame();
        }
        auto pa = c->getRigidBodyA().getCenterOfMassTransform() * frame_a.getOrigin();
        auto pb = c->getRigidBodyB().getCenterOfMassTransform() * frame_b.getOrigin();
        worst = std::max(worst, double((pa - pb).length()));
    }
    return worst;
}

} // namespace edyn_bench
