#ifndef EDYN_SRC_UTIL_RAGDOLL_SIDES_HPP
#define EDYN_SRC_UTIL_RAGDOLL_SIDES_HPP

#include "edyn/util/ragdoll.hpp"

// The members of ragdoll_entities that come in left and right pairs, so that one function can
// build either side.
namespace edyn::detail {

struct ragdoll_side_members {
    using member = entity ragdoll_entities::*;
    member shoulder, arm_upper, arm_lower, arm_twist, hand, leg_upper, leg_lower, foot;
    member clavicle_cvjoint, clavicle_cone, shoulder_cvjoint, shoulder_cone, elbow_hinge, arm_twist_hinge,
        wrist_cvjoint, wrist_cone, hip_cvjoint, hip_cone, knee_hinge, ankle_cvjoint, ankle_cone;
};

using re = ragdoll_entities;

inline constexpr ragdoll_side_members ragdoll_sides[2]{{&re::shoulder_left,
                                                        &re::arm_upper_left,
                                                        &re::arm_lower_left,
                                                        &re::arm_twist_left,
                                                        &re::hand_left,
                                                        &re::leg_upper_left,
                                                        &re::leg_lower_left,
                                                        &re::foot_left,
                                                        &re::clavicle_cvjoint_left,
                                                        &re::clavicle_cone_left,
                                                        &re::shoulder_cvjoint_left,
                                                        &re::shoulder_cone_left,
                                                        &re::elbow_hinge_left,
                                                        &re::arm_twist_hinge_left,
                                                        &re::wrist_cvjoint_left,
                                                        &re::wrist_cone_left,
                                                        &re::hip_cvjoint_left,
                                                        &re::hip_cone_left,
                                                        &re::knee_hinge_left,
                                                        &re::ankle_cvjoint_left,
                                                        &re::ankle_cone_left},
                                                       {&re::shoulder_right,
                                                        &re::arm_upper_right,
                                                        &re::arm_lower_right,
                                                        &re::arm_twist_right,
                                                        &re::hand_right,
                                                        &re::leg_upper_right,
                                                        &re::leg_lower_right,
                                                        &re::foot_right,
                                                        &re::clavicle_cvjoint_right,
                                                        &re::clavicle_cone_right,
                                                        &re::shoulder_cvjoint_right,
                                                        &re::shoulder_cone_right,
                                                        &re::elbow_hinge_right,
                                                        &re::arm_twist_hinge_right,
                                                        &re::wrist_cvjoint_right,
                                                        &re::wrist_cone_right,
                                                        &re::hip_cvjoint_right,
                                                        &re::hip_cone_right,
                                                        &re::knee_hinge_right,
                                                        &re::ankle_cvjoint_right,
                                                        &re::ankle_cone_right}};

} // namespace edyn::detail

#endif // EDYN_SRC_UTIL_RAGDOLL_SIDES_HPP
