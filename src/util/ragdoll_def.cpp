#include "edyn/util/ragdoll.hpp"
#include "ragdoll_validate.hpp"

namespace edyn {

namespace {

// Segment lengths as fractions of standing height, from the segment-length diagram in Winter's
// "Biomechanics and Motor Control of Human Movement" (after Drillis and Contini): ankle 0.039,
// knee 0.285, hip 0.530, shoulder 0.818 and chin 0.870 of the height above the floor; upper
// arm 0.186, forearm 0.146, hand 0.108, foot 0.152 long and 0.055 wide. The trunk between hip
// and shoulder (0.288) is split at the waist into a lower part of 0.100 and an upper of 0.188.
// The standing chain foot + shank + thigh + lower and upper trunk + neck + head adds up to 1.
// Breadths and thicknesses are our estimates of an average adult's, chosen so that neighbouring
// limbs do not overlap when standing.
constexpr scalar ankle_height = scalar(0.039);
constexpr scalar leg_lower_length = scalar(0.246);
constexpr scalar leg_upper_length = scalar(0.245);
constexpr scalar torso_lower_length = scalar(0.100);
constexpr scalar torso_upper_length = scalar(0.188);
constexpr scalar neck_length = scalar(0.052);
constexpr scalar head_length = scalar(0.130);

// Mass fractions of total body mass from Dempster's cadaver study as tabulated by Winter: hand
// 0.006, forearm 0.016, upper arm 0.028, foot 0.0145, shank 0.0465, thigh 0.100, head and neck
// 0.081, thorax 0.216, abdomen 0.139, pelvis 0.142. The head and neck are split 0.061 / 0.020,
// the lower torso is abdomen and pelvis, each shoulder takes 0.010 of the thorax and each arm
// twist 0.004 of its forearm, so that the parts still add up to the whole body.
constexpr scalar head_fraction = scalar(0.061);
constexpr scalar neck_fraction = scalar(0.020);
constexpr scalar shoulder_fraction = scalar(0.020);
constexpr scalar torso_upper_fraction = scalar(0.216) - 2 * shoulder_fraction;
constexpr scalar torso_lower_fraction = scalar(0.139) + scalar(0.142);
constexpr scalar arm_upper_fraction = scalar(0.028);
constexpr scalar arm_twist_fraction = scalar(0.004);
constexpr scalar arm_lower_fraction = scalar(0.016) - arm_twist_fraction;
constexpr scalar hand_fraction = scalar(0.006);
constexpr scalar leg_upper_fraction = scalar(0.100);
constexpr scalar leg_lower_fraction = scalar(0.0465);
constexpr scalar foot_fraction = scalar(0.0145);

} // namespace

ragdoll_def make_ragdoll_def_from_simple(const ragdoll_simple_def &simple) {
    detail::validate_ragdoll_def("make_ragdoll_def_from_simple", simple);
    const auto h = simple.height, m = simple.weight;
    ragdoll_def def;
    def.head_size = vector3{head_length, scalar(0.087), scalar(0.110)} * h;
    def.neck_size = vector3{neck_length, scalar(0.065), scalar(0.065)} * h;
    def.torso_upper_size = vector3{torso_upper_length, scalar(0.200), scalar(0.110)} * h;
    def.torso_lower_size = vector3{torso_lower_length, scalar(0.180), scalar(0.100)} * h;
    // The collar bone, from the sternum to the shoulder joint.
    def.shoulder_size = vector3{scalar(0.080), scalar(0.020), scalar(0.020)} * h;
    def.arm_upper_size = vector3{scalar(0.186), scalar(0.050), scalar(0.050)} * h;
    def.arm_lower_size = vector3{scalar(0.146), scalar(0.040), scalar(0.040)} * h;
    def.arm_twist_size = vector3{scalar(0.146), scalar(0.030), scalar(0.030)} * h;
    def.hand_size = vector3{scalar(0.108), scalar(0.055), scalar(0.020)} * h;
    def.leg_upper_size = vector3{leg_upper_length, scalar(0.080), scalar(0.080)} * h;
    def.leg_lower_size = vector3{leg_lower_length, scalar(0.055), scalar(0.055)} * h;
    def.foot_size = vector3{scalar(0.152), scalar(0.055), ankle_height} * h;

    def.head_mass = head_fraction * m;
    def.neck_mass = neck_fraction * m;
    def.torso_upper_mass = torso_upper_fraction * m;
    def.torso_lower_mass = torso_lower_fraction * m;
    def.shoulder_mass = shoulder_fraction * m;
    def.arm_upper_mass = arm_upper_fraction * m;
    def.arm_lower_mass = arm_lower_fraction * m;
    def.arm_twist_mass = arm_twist_fraction * m;
    def.hand_mass = hand_fraction * m;
    def.leg_upper_mass = leg_upper_fraction * m;
    def.leg_lower_mass = leg_lower_fraction * m;
    def.foot_mass = foot_fraction * m;

    static_cast<ragdoll_placement &>(def) = simple;
    return def;
}

} // namespace edyn
