#include "ragdoll_layout.hpp"
#include <algorithm>

namespace edyn::detail {

scalar ragdoll_capsule_radius(const vector3 &size) noexcept {
    return std::min(std::min(size.y, size.z) / 2, size.x * scalar(0.4));
}

namespace {

ragdoll_side_layout make_side(const ragdoll_def &def, const ragdoll_layout &body, scalar sign) {
    ragdoll_side_layout s;
    s.sign = sign;
    const vector3 out{sign, 0, 0};
    // The shoulder joint stands off the ribcage by the upper arm's radius and a little more, so
    // that the arm hangs beside the torso without touching it.
    auto arm_radius = ragdoll_capsule_radius(def.arm_upper_size);
    auto shoulder_x = def.torso_upper_size.y / 2 + arm_radius * scalar(1.2);
    s.shoulder_joint = {sign * shoulder_x, body.torso_top.y - arm_radius, 0};
    s.clavicle_joint = s.shoulder_joint - out * def.shoulder_size.x;
    s.shoulder = (s.clavicle_joint + s.shoulder_joint) / 2;
    s.elbow = s.shoulder_joint + out * def.arm_upper_size.x;
    s.wrist = s.elbow + out * def.arm_lower_size.x;
    s.fingertips = s.wrist + out * def.hand_size.x;
    s.arm_upper = (s.shoulder_joint + s.elbow) / 2;
    s.arm_lower = (s.elbow + s.wrist) / 2;
    s.hand = (s.wrist + s.fingertips) / 2;

    // The thighs hang flush with the sides of the lower torso, kept apart from each other.
    auto thigh_radius = ragdoll_capsule_radius(def.leg_upper_size);
    auto hip_x = std::max(def.torso_lower_size.y / 2 - thigh_radius, thigh_radius * scalar(1.1));
    auto ankle_y = def.foot_size.z;
    s.ankle = {sign * hip_x, ankle_y, 0};
    s.knee = s.ankle + vector3{0, def.leg_lower_size.x, 0};
    s.hip = s.knee + vector3{0, def.leg_upper_size.x, 0};
    s.leg_upper = (s.hip + s.knee) / 2;
    s.leg_lower = (s.knee + s.ankle) / 2;
    // The sole is on the floor and the ankle above a point a quarter of the foot from the heel.
    s.foot = {sign * hip_x, ankle_y / 2, def.foot_size.x / 4};
    s.below_ankle = s.ankle - vector3{0, def.foot_size.x / 2, 0};
    return s;
}

} // namespace

ragdoll_layout make_ragdoll_layout(const ragdoll_def &def) noexcept {
    ragdoll_layout l;
    auto hip_y = def.foot_size.z + def.leg_lower_size.x + def.leg_upper_size.x;
    l.waist = {0, hip_y + def.torso_lower_size.x, 0};
    l.torso_top = l.waist + vector3{0, def.torso_upper_size.x, 0};
    l.neck_top = l.torso_top + vector3{0, def.neck_size.x, 0};
    l.crown = l.neck_top + vector3{0, def.head_size.x, 0};
    l.torso_lower = {0, hip_y + def.torso_lower_size.x / 2, 0};
    l.torso_upper = (l.waist + l.torso_top) / 2;
    l.neck = (l.torso_top + l.neck_top) / 2;
    l.head = (l.neck_top + l.crown) / 2;
    l.side[0] = make_side(def, l, 1);
    l.side[1] = make_side(def, l, -1);
    return l;
}

} // namespace edyn::detail
