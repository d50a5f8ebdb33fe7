#ifndef EDYN_BENCH_BULLET_JOINTS_HPP
#define EDYN_BENCH_BULLET_JOINTS_HPP

// Joints for the Bullet side of edyn-bench, read from the registry the shared scene builders
// filled, and the joint error both engines report as the stability of jointed scenes.

#include <algorithm>
#include <cstddef>
#include <edyn/edyn.hpp>
#include <memory>
#include <utility>
#include <vector>

class btDiscreteDynamicsWorld;
class btRigidBody;
class btTypedConstraint;

namespace edyn_bench {

// One Bullet joint. Bodies are indices into the entity list given to describe_joints; pivots
// and bases are in each body's object space, whose origin is its centre of mass (describe_bodies
// refuses offset centres of mass). Bases are Bullet's constraint frames: the hinge turns about
// their z axis, the cone twist twists about their x axis.
struct joint_desc {
    enum class kind { hinge, cone_twist };
    kind type{kind::hinge};
    std::size_t body[2]{0, 0};
    edyn::vector3 pivot[2]{edyn::vector3_zero, edyn::vector3_zero};
    edyn::matrix3x3 basis[2]{edyn::matrix3x3_identity, edyn::matrix3x3_identity};
    // Hinge: lowest and highest angle. Cone twist: swing span towards the frame's y axis, towards
    // its z axis, and the twist span (each side). Radians.
    double limit[3]{0, 0, 0};
    // Hinge only: the torque opposing rotation about the axis (Nm).
    double friction_torque{0};
};

// Views list the newest entity first. Bullet solves its constraints in the order they were added
// and Gauss-Seidel converges differently depending on that order, so Bullet gets the bodies and
// joints of each kind in the order the scene builders made them, as a program building the scene
// directly in Bullet would add them (the ground first, a chain from its anchor down).
template<typename View>
std::vector<edyn::entity> in_creation_order(const View &view) {
    std::vector<edyn::entity> entities(view.begin(), view.end());
    std::reverse(entities.begin(), entities.end());
    return entities;
}

struct scene_joints {
    std::vector<joint_desc> joints;
    // Pairs of bodies that must not collide (edyn's collision_exclusion), as indices.
    std::vector<std::pair<std::size_t, std::size_t>> exclusions;
};

// Hinges become btHingeConstraint; a CV joint and the cone between the same two bodies (a rag
// doll's swing joints) become one btConeTwistConstraint. Throws std::invalid_argument for a
// joint Bullet's scenes cannot express (a cone without its CV joint, asymmetric twist limits).
scene_joints describe_joints(const edyn::registry &registry, const std::vector<edyn::entity> &bodies);

// The joints added to a Bullet world, removed from it when destroyed (before the world).
class bullet_joints {
public:
    bullet_joints(btDiscreteDynamicsWorld &world, const std::vector<btRigidBody *> &bodies,
                  const scene_joints &joints, double dt);
    ~bullet_joints();
    bullet_joints(const bullet_joints &) = delete;
    bullet_joints &operator=(const bullet_joints &) = delete;

    bool empty() const noexcept { return constraints.empty(); }
    // As edyn::scenes::max_pivot_separation, for these Bullet joints.
    double worst_error() const;

private:
    btDiscreteDynamicsWorld &world;
    std::vector<std::unique_ptr<btTypedConstraint>> constraints;
};

} // namespace edyn_bench

#endif // EDYN_BENCH_BULLET_JOINTS_HPP
