#ifndef EDYN_SRC_UTIL_RAGDOLL_LAYOUT_HPP
#define EDYN_SRC_UTIL_RAGDOLL_LAYOUT_HPP

#include "edyn/util/ragdoll.hpp"

// Where every body part and joint of a rag doll lies in its T pose, in the rag doll's own
// space: the floor between its feet at the origin, +y up, facing +z, its left towards +x. Every
// part starts with the rag doll's orientation, so these directions are also each part's object
// axes, and a pivot is a joint's position minus the part's centre.
namespace edyn::detail {

struct ragdoll_side_layout {
    // +1 on the left (+x), -1 on the right.
    scalar sign;
    // Centres of the parts; the arm twist shares the lower arm's.
    vector3 shoulder, arm_upper, arm_lower, hand, leg_upper, leg_lower, foot;
    // Joints: collar bone at the sternum, shoulder, elbow, wrist, hip, knee, ankle.
    vector3 clavicle_joint, shoulder_joint, elbow, wrist, hip, knee, ankle;
    // Tips the cones hold: fingertips, and a point below the ankle that the foot carries.
    vector3 fingertips, below_ankle;
};

struct ragdoll_layout {
    vector3 head, neck, torso_upper, torso_lower;
    // Waist (spine joint), top of the upper torso (neck joint), top of the neck (head joint),
    // crown of the head.
    vector3 waist, torso_top, neck_top, crown;
    ragdoll_side_layout side[2];
};

// Radius of the capsule of a limb of `size` (see ragdoll_def), kept below its length so that
// the capsule has a straight part.
scalar ragdoll_capsule_radius(const vector3 &size) noexcept;

ragdoll_layout make_ragdoll_layout(const ragdoll_def &def) noexcept;

} // namespace edyn::detail

#endif // EDYN_SRC_UTIL_RAGDOLL_LAYOUT_HPP
