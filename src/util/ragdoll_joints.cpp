#include "ragdoll_joints.hpp"
#include "edyn/collision/should_collide.hpp"
#include "edyn/constraints/cone_constraint.hpp"
#include "edyn/constraints/cvjoint_constraint.hpp"
#include "edyn/constraints/hinge_constraint.hpp"
#include "edyn/constraints/make_constraint.hpp"
#include "edyn/dynamics/rigidbody.hpp"
#include "edyn/math/math.hpp"
#include "ragdoll_sides.hpp"
#include <cmath>

namespace edyn::detail {

namespace {

// A swing-and-twist joint: the child's bone leaves the joint along `bone` (rag doll space); it
// twists about that direction within +-twist and swings within a cone about `cone_axis`, opening
// by span0 towards the side of `span0_towards` and by span1 across it. The cone holds the
// child's `tip`, a point along the bone away from the joint. `friction` (Nm, for an 80 kg body
// 1.8 m tall) opposes both twisting and bending.
struct swing_joint {
    vector3 joint, bone, tip;
    scalar twist;
    vector3 cone_axis, span0_towards;
    scalar span0, span1;
    scalar friction;
};

matrix3x3 cone_frame(const vector3 &axis, const vector3 &towards) {
    auto a = normalize(axis);
    auto b = normalize(project_plane(towards, a));
    return matrix3x3_columns(a, b, cross(a, b));
}

// Friction in the joints stands for the tone of the muscles around them: without it a rag doll
// lying in a heap keeps a limb swinging and never sleeps. It grows with the weight and size of
// the limbs it slows (mass times length), and stays well below the torque of a limb's own weight
// so that limbs still fall limp.
scalar friction_scale(const ragdoll_def &d) {
    auto side = d.shoulder_mass + d.arm_upper_mass + d.arm_lower_mass + d.arm_twist_mass + d.hand_mass +
                d.leg_upper_mass + d.leg_lower_mass + d.foot_mass;
    auto mass = d.head_mass + d.neck_mass + d.torso_upper_mass + d.torso_lower_mass + 2 * side;
    auto height = d.foot_size.z + d.leg_lower_size.x + d.leg_upper_size.x + d.torso_lower_size.x +
                  d.torso_upper_size.x + d.neck_size.x + d.head_size.x;
    return mass * height / (80 * scalar(1.8));
}

struct joint_maker {
    registry &reg;
    const ragdoll_def &def;
    std::vector<entity> &created;
    scalar friction_scale;

    vector3 centre(entity body) const {
        return rotate(conjugate(def.orientation), get_rigidbody_origin(reg, body) - def.position);
    }

    void swing(entity parent, entity child, const swing_joint &j, entity &cvjoint, entity &cone) {
        auto pc = centre(parent), cc = centre(child);
        cvjoint = make_constraint<cvjoint_constraint>(reg, parent, child, [&](cvjoint_constraint &c) {
            c.pivot[0] = j.joint - pc;
            c.pivot[1] = j.joint - cc;
            c.set_axes(j.bone, j.bone);
            c.twist_min = -to_radians(j.twist);
            c.twist_max = to_radians(j.twist);
            // A locked twist needs no friction.
            if (j.twist > 0) c.twist_friction_torque = j.friction * friction_scale;
            c.bend_friction_torque = j.friction * friction_scale;
        });
        created.push_back(cvjoint);
        cone = make_constraint<cone_constraint>(reg, parent, child, [&](cone_constraint &c) {
            c.pivot[0] = j.joint - pc;
            c.pivot[1] = j.tip - cc;
            c.frame = cone_frame(j.cone_axis, j.span0_towards);
            c.span_angle[0] = to_radians(j.span0);
            c.span_angle[1] = to_radians(j.span1);
        });
        created.push_back(cone);
    }

    // A hinge about `axis`, its angle growing as the child turns counterclockwise about it.
    entity hinge(entity parent, entity child, const vector3 &joint, const vector3 &axis, scalar min_deg,
                 scalar max_deg, scalar friction) {
        auto pc = centre(parent), cc = centre(child);
        auto e = make_constraint<hinge_constraint>(reg, parent, child, [&](hinge_constraint &c) {
            c.pivot[0] = joint - pc;
            c.pivot[1] = joint - cc;
            c.set_axes(axis, axis);
            c.angle_min = to_radians(min_deg);
            c.angle_max = to_radians(max_deg);
            c.friction_torque = friction * friction_scale;
        });
        created.push_back(e);
        return e;
    }
};

vector3 tilt(const vector3 &axis, const vector3 &towards, scalar degrees) {
    return normalize(axis + towards * std::tan(to_radians(degrees)));
}

// The joints of one side. Angles in degrees: anatomical ranges of motion, rounded, each cone
// tilted towards the side where its joint goes further so that one span covers both ways.
void make_side_joints(joint_maker &m, ragdoll_entities &e, const ragdoll_side_layout &s,
                      const ragdoll_side_members &p) {
    const vector3 out{s.sign, 0, 0}, up = vector3_y, down = -vector3_y, forward = vector3_z;
    auto shoulder = e.*p.shoulder, arm_upper = e.*p.arm_upper, arm_lower = e.*p.arm_lower;
    auto arm_twist = e.*p.arm_twist, hand = e.*p.hand;
    auto leg_upper = e.*p.leg_upper, leg_lower = e.*p.leg_lower, foot = e.*p.foot;
    // Collar bone: raised 30, lowered 10, pushed forward or back 20, turned about itself 15.
    m.swing(e.torso_upper, shoulder,
            {s.clavicle_joint, out, s.shoulder_joint, 15, tilt(out, up, 10), up, 20, 20, scalar(1.5)},
            e.*p.clavicle_cvjoint, e.*p.clavicle_cone);
    // Shoulder joint: the cone points down and forward of the T pose so that it holds the arm
    // hanging at the side (60 degrees from its axis) and stretched out (about 50) but not far
    // behind the back.
    auto shoulder_axis =
        normalize(out + down * std::tan(to_radians(30)) + forward * std::tan(to_radians(40)));
    m.swing(shoulder, arm_upper, {s.shoulder_joint, out, s.elbow, 60, shoulder_axis, up, 65, 80, scalar(1.5)},
            e.*p.shoulder_cvjoint, e.*p.shoulder_cone);
    // Elbow: bends forward 145, overstretches 5. Turning the left forearm forward is clockwise
    // about +y, the right one's counterclockwise.
    e.*p.elbow_hinge = m.hinge(arm_upper, arm_lower, s.elbow, {0, -s.sign, 0}, -5, 145, scalar(0.8));
    // Forearm twist (pronation and supination), about the forearm, from its centre.
    e.*p.arm_twist_hinge = m.hinge(arm_lower, arm_twist, s.arm_lower, out, -80, 80, scalar(0.3));
    // Wrist: the twist is the forearm's, so it is locked; bends 70 up or down, 25 sideways.
    m.swing(arm_twist, hand, {s.wrist, out, s.fingertips, 0, out, up, 70, 25, scalar(0.2)},
            e.*p.wrist_cvjoint, e.*p.wrist_cone);
    // Hip: flexes 115, extends 25 (a cone 70 wide tilted 45 forward), abducts 45 and adducts 25
    // (35 wide, tilted 10 out); the thigh turns 40 about itself.
    auto hip_axis = normalize(down + forward * std::tan(to_radians(45)) + out * std::tan(to_radians(10)));
    m.swing(e.torso_lower, leg_upper, {s.hip, down, s.knee, 40, hip_axis, forward, 70, 35, 3},
            e.*p.hip_cvjoint, e.*p.hip_cone);
    // Knee: flexes backwards 140 (counterclockwise about +x), overstretches 5.
    e.*p.knee_hinge = m.hinge(leg_upper, leg_lower, s.knee, vector3_x, -5, 140, scalar(1.5));
    // Ankle: the cone holds a point below the ankle, which moves back as the toes point down
    // (50) and forward as they lift (20), sideways as the sole turns in or out (25). The foot
    // turns 25 about the shin.
    m.swing(leg_lower, foot,
            {s.ankle, down, s.below_ankle, 25, tilt(down, -forward, 15), forward, 35, 25, scalar(0.6)},
            e.*p.ankle_cvjoint, e.*p.ankle_cone);
    // Parts touching at a joint, the hand at the lower arm through the arm twist. The upper arm
    // stands off the upper torso and may collide with it.
    exclude_collision(m.reg, arm_upper, arm_lower);
    exclude_collision(m.reg, arm_lower, hand);
    exclude_collision(m.reg, e.torso_lower, leg_upper);
    exclude_collision(m.reg, leg_upper, leg_lower);
    exclude_collision(m.reg, leg_lower, foot);
}

} // namespace

void make_ragdoll_joints(registry &registry, const ragdoll_def &def, const ragdoll_layout &l,
                         ragdoll_entities &e, std::vector<entity> &created) {
    joint_maker m{registry, def, created, friction_scale(def)};
    const auto up = vector3_y, forward = vector3_z;
    // Spine: bends forward 45, back 25, sideways 25, twists 30.
    m.swing(e.torso_lower, e.torso_upper,
            {l.waist, up, l.torso_top, 30, tilt(up, forward, 10), forward, 35, 25, 6}, e.spine_cvjoint,
            e.spine_cone);
    // Neck and head: together they bend forward 60, back 50, sideways 45 and turn 80.
    m.swing(e.torso_upper, e.neck,
            {l.torso_top, up, l.neck_top, 35, tilt(up, forward, 5), forward, 30, 25, scalar(1.5)},
            e.neck_cvjoint, e.neck_cone);
    m.swing(e.neck, e.head, {l.neck_top, up, l.crown, 45, up, forward, 25, 20, scalar(0.8)}, e.head_cvjoint,
            e.head_cone);
    exclude_collision(registry, e.torso_lower, e.torso_upper);
    exclude_collision(registry, e.torso_upper, e.neck);
    exclude_collision(registry, e.neck, e.head);

    for (int side : {0, 1})
        make_side_joints(m, e, l.side[side], ragdoll_sides[side]);
}

} // namespace edyn::detail
