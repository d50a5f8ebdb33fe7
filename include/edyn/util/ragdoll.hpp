#ifndef EDYN_UTIL_RAGDOLL_HPP
#define EDYN_UTIL_RAGDOLL_HPP

#include "edyn/ecs/registry.hpp"
#include "edyn/math/quaternion.hpp"
#include "edyn/math/vector3.hpp"
#include <array>
#include <cstddef>
#include <cstdint>

namespace edyn {

// Where a rag doll stands and what its surface is like: shared by both definitions and
// applied to every body part.
struct ragdoll_placement {
    // The point on the floor between its feet. It stands along +y of `orientation`, facing its
    // +z, its left hand towards its +x, in a T pose (arms along its +x and -x, palms down).
    vector3 position{vector3_zero};
    quaternion orientation{quaternion_identity};
    // Surface material of every body part: friction >= 0, restitution in [0, 1].
    scalar friction{scalar(0.5)};
    scalar restitution{0};
    std::uint64_t collision_group{~std::uint64_t(0)};
    std::uint64_t collision_mask{~std::uint64_t(0)};
    bool sleeping_disabled{false};
};

// A rag doll from two numbers; the proportions come from anthropometric tables (see
// make_ragdoll_def_from_simple).
struct ragdoll_simple_def : ragdoll_placement {
    // Standing height in metres and mass in kg.
    scalar height{scalar(1.8)};
    scalar weight{80};
};

// Every body part of a rag doll, measured. Sizes are full extents in metres: x is the length
// along the bone (joint to joint; head, neck and torso: their height; hand: wrist to
// fingertips; foot: heel to toe), y the breadth (side to side as the rag doll stands, its arms
// stretched out: for the hand, its width across the palm) and z the thickness (front to back;
// hand and foot: palm to back, sole to instep). Limbs get capsules of diameter min(y, z), the
// torso, hands and feet boxes. The shoulder (collar bone and shoulder blade, from the top of the
// sternum to the shoulder joint) and the arm twist (the forearm's turning bones) are amorphous:
// their size only sets their inertia. Masses in kg. Every size and mass starts at zero: fill
// them, or start from make_ragdoll_def_from_simple.
struct ragdoll_def : ragdoll_placement {
    vector3 head_size{vector3_zero};
    vector3 neck_size{vector3_zero};
    vector3 torso_upper_size{vector3_zero};
    vector3 torso_lower_size{vector3_zero};
    vector3 shoulder_size{vector3_zero};
    vector3 arm_upper_size{vector3_zero};
    vector3 arm_lower_size{vector3_zero};
    vector3 arm_twist_size{vector3_zero};
    vector3 hand_size{vector3_zero};
    vector3 leg_upper_size{vector3_zero};
    vector3 leg_lower_size{vector3_zero};
    vector3 foot_size{vector3_zero};

    scalar head_mass{0};
    scalar neck_mass{0};
    scalar torso_upper_mass{0};
    scalar torso_lower_mass{0};
    scalar shoulder_mass{0};
    scalar arm_upper_mass{0};
    scalar arm_lower_mass{0};
    scalar arm_twist_mass{0};
    scalar hand_mass{0};
    scalar leg_upper_mass{0};
    scalar leg_lower_mass{0};
    scalar foot_mass{0};
};

// Segment lengths, breadths and mass fractions of an adult of the given height and weight.
// Throws std::invalid_argument naming the field for a non-positive or non-finite height or
// weight, a non-unit orientation, friction or restitution out of range.
ragdoll_def make_ragdoll_def_from_simple(const ragdoll_simple_def &def);

// The rigid bodies and constraints of a rag doll. Joints with a swing limit are a CV joint (the
// pivot and the twist) and a cone (the swing); knees, elbows and the forearm twist are hinges.
// Each constraint's body[0] is the part nearer the lower torso.
struct ragdoll_entities {
    entity head{null};
    entity neck{null};
    entity torso_upper{null};
    entity torso_lower{null};
    entity shoulder_left{null}, shoulder_right{null};
    entity arm_upper_left{null}, arm_upper_right{null};
    entity arm_lower_left{null}, arm_lower_right{null};
    entity arm_twist_left{null}, arm_twist_right{null};
    entity hand_left{null}, hand_right{null};
    entity leg_upper_left{null}, leg_upper_right{null};
    entity leg_lower_left{null}, leg_lower_right{null};
    entity foot_left{null}, foot_right{null};

    // Lower torso to upper torso.
    entity spine_cvjoint{null}, spine_cone{null};
    // Upper torso to neck, neck to head.
    entity neck_cvjoint{null}, neck_cone{null};
    entity head_cvjoint{null}, head_cone{null};
    // Upper torso to shoulder (the collar bone's joint at the sternum).
    entity clavicle_cvjoint_left{null}, clavicle_cvjoint_right{null};
    entity clavicle_cone_left{null}, clavicle_cone_right{null};
    // Shoulder to upper arm.
    entity shoulder_cvjoint_left{null}, shoulder_cvjoint_right{null};
    entity shoulder_cone_left{null}, shoulder_cone_right{null};
    // Upper arm to lower arm.
    entity elbow_hinge_left{null}, elbow_hinge_right{null};
    // Lower arm to arm twist, about the forearm's axis.
    entity arm_twist_hinge_left{null}, arm_twist_hinge_right{null};
    // Arm twist to hand.
    entity wrist_cvjoint_left{null}, wrist_cvjoint_right{null};
    entity wrist_cone_left{null}, wrist_cone_right{null};
    // Lower torso to upper leg.
    entity hip_cvjoint_left{null}, hip_cvjoint_right{null};
    entity hip_cone_left{null}, hip_cone_right{null};
    // Upper leg to lower leg.
    entity knee_hinge_left{null}, knee_hinge_right{null};
    // Lower leg to foot.
    entity ankle_cvjoint_left{null}, ankle_cvjoint_right{null};
    entity ankle_cone_left{null}, ankle_cone_right{null};

    static constexpr std::size_t num_bodies = 20;
    static constexpr std::size_t num_constraints = 32;
    // Every body, head first.
    std::array<entity, num_bodies> bodies() const noexcept;
    // Every constraint, spine first.
    std::array<entity, num_constraints> constraints() const noexcept;
};

// Creates the rag doll standing at def.position: bodies, joints with anatomical limits, and
// collision exclusions between the parts that touch at a joint (through the amorphous shoulder
// and arm twist too). Throws std::invalid_argument naming the field for a non-positive or
// non-finite size or mass, a non-unit orientation, friction or restitution out of range;
// nothing is created then.
ragdoll_entities make_ragdoll(registry &registry, const ragdoll_def &def);
ragdoll_entities make_ragdoll(registry &registry, const ragdoll_simple_def &def);

} // namespace edyn

#endif // EDYN_UTIL_RAGDOLL_HPP
