#include "ragdoll_validate.hpp"
#include "../shapes/invalid_argument.hpp"
#include <cmath>
#include <utility>

namespace edyn::detail {

namespace {

void check_positive(const char *function, const char *field, scalar value) {
    if (!positive_finite(value)) {
        throw_invalid_argument(function, ": ", field, " must be positive and finite, got ", value);
    }
}

void check_positive(const char *function, const char *field, const vector3 &value) {
    if (!positive_finite(value.x) || !positive_finite(value.y) || !positive_finite(value.z)) {
        throw_invalid_argument(function, ": ", field, " must have positive, finite components, got ", value);
    }
}

void validate_placement(const char *function, const ragdoll_placement &def) {
    if (!isfinite(def.position)) {
        throw_invalid_argument(function, ": position must be finite, got ", def.position);
    }
    if (!isfinite(def.orientation) || !is_unit(def.orientation)) {
        throw_invalid_argument(function, ": orientation must be a finite unit quaternion, got ",
                               def.orientation, " of length ", length(def.orientation));
    }
    if (!(def.friction >= 0) || !std::isfinite(def.friction)) {
        throw_invalid_argument(function, ": friction must be in [0, inf), got ", def.friction);
    }
    if (!(def.restitution >= 0 && def.restitution <= 1)) {
        throw_invalid_argument(function, ": restitution must be in [0, 1], got ", def.restitution);
    }
}

} // namespace

void validate_ragdoll_def(const char *function, const ragdoll_simple_def &def) {
    check_positive(function, "height", def.height);
    check_positive(function, "weight", def.weight);
    validate_placement(function, def);
}

void validate_ragdoll_def(const char *function, const ragdoll_def &def) {
    const std::pair<const char *, const vector3 *> sizes[]{{"head_size", &def.head_size},
                                                           {"neck_size", &def.neck_size},
                                                           {"torso_upper_size", &def.torso_upper_size},
                                                           {"torso_lower_size", &def.torso_lower_size},
                                                           {"shoulder_size", &def.shoulder_size},
                                                           {"arm_upper_size", &def.arm_upper_size},
                                                           {"arm_lower_size", &def.arm_lower_size},
                                                           {"arm_twist_size", &def.arm_twist_size},
                                                           {"hand_size", &def.hand_size},
                                                           {"leg_upper_size", &def.leg_upper_size},
                                                           {"leg_lower_size", &def.leg_lower_size},
                                                           {"foot_size", &def.foot_size}};
    for (auto [field, size] : sizes)
        check_positive(function, field, *size);
    const std::pair<const char *, scalar> masses[]{{"head_mass", def.head_mass},
                                                   {"neck_mass", def.neck_mass},
                                                   {"torso_upper_mass", def.torso_upper_mass},
                                                   {"torso_lower_mass", def.torso_lower_mass},
                                                   {"shoulder_mass", def.shoulder_mass},
                                                   {"arm_upper_mass", def.arm_upper_mass},
                                                   {"arm_lower_mass", def.arm_lower_mass},
                                                   {"arm_twist_mass", def.arm_twist_mass},
                                                   {"hand_mass", def.hand_mass},
                                                   {"leg_upper_mass", def.leg_upper_mass},
                                                   {"leg_lower_mass", def.leg_lower_mass},
                                                   {"foot_mass", def.foot_mass}};
    for (auto [field, mass] : masses)
        check_positive(function, field, mass);
    validate_placement(function, def);
}

} // namespace edyn::detail
