#ifndef EDYN_UTIL_RAGDOLL_HPP
#define EDYN_UTIL_RAGDOLL_HPP

#include "edyn/ecs/registry.hpp"
#include "edyn/math/quaternion.hpp"
#include "edyn/math/vector3.hpp"
#include <array>
#include <cstddef>
#include <cstdint>

namespace edyn {

/// Where a rag doll stands and what its surface is like: shared by both definitions and applied
/// to every body part.
struct ragdoll_placement {
    /// The point on the floor between its feet, in world space (m; default the origin). It
    /// stands along +y of `orientation`, facing its +z, its left hand towards its +x, in a T pose
    /// (arms along its +x and -x, palms down).
    vector3 position{vector3_zero};
    /// Orientation of the whole rag doll (x y z w); must be unit length (default identity).
    quaternion orientation{quaternion_identity};
    /// Friction coefficient of every body part's material, >= 0 (default 0.5).
    scalar friction{scalar(0.5)};
    /// Restitution of every body part's material, in [0, 1] (default 0).
    scalar restitution{0};
    /// Collision group of every body part (default all bits set).
    std::uint64_t collision_group{~std::uint64_t(0)};
    /// Collision mask of every body part (default all bits set).
    std::uint64_t collision_mask{~std::uint64_t(0)};
    /// When set, the rag doll's bodies never sleep (default false).
    bool sleeping_disabled{false};
};

/// A rag doll from two numbers; the proportions come from anthropometric tables (see
/// make_ragdoll_def_from_simple). Pass it to make_ragdoll directly, or turn it into a
/// ragdoll_def to adjust the parts.
struct ragdoll_simple_def : ragdoll_placement {
    scalar height{scalar(1.8)}; ///< Standing height in metres, > 0 (default 1.8).
    scalar weight{80};          ///< Mass in kg, > 0 (default 80).
};

/// Every body part of a rag doll, measured.
///
/// Sizes are full extents in metres: x is the length along the bone (joint to joint; head, neck
/// and torso: their height; hand: wrist to fingertips; foot: heel to toe), y the breadth (side to
/// side as the rag doll stands, its arms stretched out: for the hand, its width across the palm)
/// and z the thickness (front to back; hand and foot: palm to back, sole to instep). Limbs get
/// capsules of diameter min(y, z), the torso, hands and feet boxes. The shoulder (collar bone and
/// shoulder blade, from the top of the sternum to the shoulder joint) and the arm twist (the
/// forearm's turning bones) are amorphous: their size only sets their inertia. Masses in kg. The
/// sizes and masses of paired parts apply to both sides. Every size and mass starts at zero: fill
/// them, or start from make_ragdoll_def_from_simple. make_ragdoll requires each to be positive
/// and finite.
struct ragdoll_def : ragdoll_placement {
    vector3 head_size{vector3_zero};        ///< Head, a capsule: height, breadth, thickness (m).
    vector3 neck_size{vector3_zero};        ///< Neck, a capsule: height, breadth, thickness (m).
    vector3 torso_upper_size{vector3_zero}; ///< Upper torso, a box: height, breadth, thickness (m).
    vector3 torso_lower_size{vector3_zero}; ///< Lower torso, a box: height, breadth, thickness (m).
    /// Each shoulder, amorphous: length from the top of the sternum to the shoulder joint,
    /// breadth, thickness (m).
    vector3 shoulder_size{vector3_zero};
    vector3 arm_upper_size{vector3_zero}; ///< Each upper arm, a capsule: length, breadth, thickness (m).
    vector3 arm_lower_size{vector3_zero}; ///< Each forearm, a capsule: length, breadth, thickness (m).
    vector3 arm_twist_size{vector3_zero}; ///< Each arm twist, amorphous: length, breadth, thickness (m).
    /// Each hand, a box: wrist to fingertips, width across the palm, palm to back (m).
    vector3 hand_size{vector3_zero};
    vector3 leg_upper_size{vector3_zero}; ///< Each thigh, a capsule: length, breadth, thickness (m).
    vector3 leg_lower_size{vector3_zero}; ///< Each lower leg, a capsule: length, breadth, thickness (m).
    /// Each foot, a box: heel to toe, breadth, sole to instep (m).
    vector3 foot_size{vector3_zero};

    scalar head_mass{0};        ///< Mass of the head, in kg (default 0).
    scalar neck_mass{0};        ///< Mass of the neck, in kg (default 0).
    scalar torso_upper_mass{0}; ///< Mass of the upper torso, in kg (default 0).
    scalar torso_lower_mass{0}; ///< Mass of the lower torso, in kg (default 0).
    scalar shoulder_mass{0};    ///< Mass of each shoulder, in kg (default 0).
    scalar arm_upper_mass{0};   ///< Mass of each upper arm, in kg (default 0).
    scalar arm_lower_mass{0};   ///< Mass of each forearm, in kg (default 0).
    scalar arm_twist_mass{0};   ///< Mass of each arm twist, in kg (default 0).
    scalar hand_mass{0};        ///< Mass of each hand, in kg (default 0).
    scalar leg_upper_mass{0};   ///< Mass of each thigh, in kg (default 0).
    scalar leg_lower_mass{0};   ///< Mass of each lower leg, in kg (default 0).
    scalar foot_mass{0};        ///< Mass of each foot, in kg (default 0).
};

/// Fills a full rag doll definition from a height and a weight.
///
/// Segment lengths, breadths and mass fractions are those of an adult of the given height and
/// weight; the placement (position, orientation, material, collision filter, sleeping) is copied.
/// Edit the result, then pass it to make_ragdoll.
/// @param def The height, weight and placement.
/// @return The definition, every size and mass filled.
/// @throws std::invalid_argument Naming the field, for a non-positive or non-finite height or
/// weight, a non-finite position, a non-unit orientation, friction negative or not finite, or
/// restitution outside [0, 1].
ragdoll_def make_ragdoll_def_from_simple(const ragdoll_simple_def &def);

/// The rigid bodies and constraints of a rag doll, as make_ragdoll made them.
///
/// Joints with a swing limit are a CV joint (the pivot and the twist) and a cone (the swing);
/// knees, elbows and the forearm twist are hinges. Each constraint's body[0] is the part nearer
/// the lower torso. Use the entities to drive a skinned mesh's bones or to tune the joints'
/// limits. Every entity is null by default.
struct ragdoll_entities {
    entity head{null};        ///< The head's body.
    entity neck{null};        ///< The neck's body.
    entity torso_upper{null}; ///< The upper torso's body.
    entity torso_lower{null}; ///< The lower torso's body.
    /// The left shoulder's body (amorphous: collar bone and shoulder blade).
    entity shoulder_left{null}, shoulder_right{null}; ///< The right shoulder's body.
    /// The left upper arm's body.
    entity arm_upper_left{null}, arm_upper_right{null}; ///< The right upper arm's body.
    /// The left forearm's body.
    entity arm_lower_left{null}, arm_lower_right{null}; ///< The right forearm's body.
    /// The left arm twist's body (amorphous: the forearm's turning bones).
    entity arm_twist_left{null}, arm_twist_right{null}; ///< The right arm twist's body.
    /// The left hand's body.
    entity hand_left{null}, hand_right{null}; ///< The right hand's body.
    /// The left thigh's body.
    entity leg_upper_left{null}, leg_upper_right{null}; ///< The right thigh's body.
    /// The left lower leg's body.
    entity leg_lower_left{null}, leg_lower_right{null}; ///< The right lower leg's body.
    /// The left foot's body.
    entity foot_left{null}, foot_right{null}; ///< The right foot's body.

    /// CV joint of the spine, lower torso to upper torso.
    entity spine_cvjoint{null}, spine_cone{null}; ///< Cone (swing limit) of the spine.
    /// CV joint of the neck's base, upper torso to neck.
    entity neck_cvjoint{null}, neck_cone{null}; ///< Cone (swing limit) of the neck's base.
    /// CV joint of the head, neck to head.
    entity head_cvjoint{null}, head_cone{null}; ///< Cone (swing limit) of the head.
    /// Left CV joint of the collar bone at the sternum, upper torso to shoulder.
    entity clavicle_cvjoint_left{null}, clavicle_cvjoint_right{null}; ///< Right CV joint of the collar bone.
    /// Left cone (swing limit) of the collar bone at the sternum.
    entity clavicle_cone_left{null}, clavicle_cone_right{null}; ///< Right cone of the collar bone.
    /// Left CV joint of the shoulder, shoulder to upper arm.
    entity shoulder_cvjoint_left{null}, shoulder_cvjoint_right{null}; ///< Right CV joint of the shoulder.
    /// Left cone (swing limit) of the shoulder.
    entity shoulder_cone_left{null}, shoulder_cone_right{null}; ///< Right cone of the shoulder.
    /// Left elbow hinge, upper arm to forearm.
    entity elbow_hinge_left{null}, elbow_hinge_right{null}; ///< Right elbow hinge.
    /// Left hinge of the forearm's twist, forearm to arm twist, about the forearm's axis.
    entity arm_twist_hinge_left{null}, arm_twist_hinge_right{null}; ///< Right forearm twist hinge.
    /// Left CV joint of the wrist, arm twist to hand.
    entity wrist_cvjoint_left{null}, wrist_cvjoint_right{null}; ///< Right CV joint of the wrist.
    /// Left cone (swing limit) of the wrist.
    entity wrist_cone_left{null}, wrist_cone_right{null}; ///< Right cone of the wrist.
    /// Left CV joint of the hip, lower torso to thigh.
    entity hip_cvjoint_left{null}, hip_cvjoint_right{null}; ///< Right CV joint of the hip.
    /// Left cone (swing limit) of the hip.
    entity hip_cone_left{null}, hip_cone_right{null}; ///< Right cone of the hip.
    /// Left knee hinge, thigh to lower leg.
    entity knee_hinge_left{null}, knee_hinge_right{null}; ///< Right knee hinge.
    /// Left CV joint of the ankle, lower leg to foot.
    entity ankle_cvjoint_left{null}, ankle_cvjoint_right{null}; ///< Right CV joint of the ankle.
    /// Left cone (swing limit) of the ankle.
    entity ankle_cone_left{null}, ankle_cone_right{null}; ///< Right cone of the ankle.

    static constexpr std::size_t num_bodies = 20;      ///< The number of rigid bodies of a rag doll.
    static constexpr std::size_t num_constraints = 32; ///< The number of constraints of a rag doll.
    /// Every body, head first, in the order the members are declared.
    /// @return The body entities.
    std::array<entity, num_bodies> bodies() const noexcept;
    /// Every constraint, spine first, in the order the members are declared.
    /// @return The constraint entities.
    std::array<entity, num_constraints> constraints() const noexcept;
};

/// Creates a rag doll standing at `def.position`.
///
/// Makes its rigid bodies, joints with anatomical limits, and collision exclusions between the
/// parts that touch at a joint (through the amorphous shoulder and arm twist too). Everything is
/// validated before the first body is made: when it throws, nothing is created.
/// @param registry The registry to create the entities in.
/// @param def Sizes, masses and placement of every part.
/// @return The entities of the bodies and constraints.
/// @throws std::invalid_argument Naming the field, for a non-positive or non-finite size or mass, a
/// non-finite position, a non-unit orientation, friction negative or not finite, or restitution
/// outside [0, 1]; nothing is created then.
ragdoll_entities make_ragdoll(registry &registry, const ragdoll_def &def);
/// Creates a rag doll from a height and a weight: make_ragdoll with the definition
/// make_ragdoll_def_from_simple gives.
/// @param registry The registry to create the entities in.
/// @param def The height, weight and placement.
/// @return The entities of the bodies and constraints.
/// @throws std::invalid_argument Naming the field, for a non-positive or non-finite height or
/// weight, a non-finite position, a non-unit orientation, friction negative or not finite, or
/// restitution outside [0, 1]; nothing is created then.
ragdoll_entities make_ragdoll(registry &registry, const ragdoll_simple_def &def);

} // namespace edyn

#endif // EDYN_UTIL_RAGDOLL_HPP
