#include "edyn/simulation/settings.hpp"
#include "../shapes/invalid_argument.hpp"
#include "edyn/dynamics/body_limits.hpp"
#include <cmath>

namespace edyn {

namespace {

// Checks of one settings object, each naming the field it refuses.
struct settings_check {
    const char *function;

    [[noreturn]] void refuse(const char *field, const std::string &rule, const auto &value) const {
        detail::throw_invalid_argument(function, ": settings::", field, " must be ", rule, ", got ", value);
    }

    void count(const char *field, unsigned value, unsigned min, unsigned max) const {
        if (value < min || value > max) refuse(field, detail::concat("in [", min, ", ", max, "]"), value);
    }

    // At least 0 and finite.
    void not_negative(const char *field, scalar value) const {
        if (!(value >= 0 && std::isfinite(value))) refuse(field, "finite and not negative", value);
    }

    // At least 0; infinity stands for no bound.
    void bound(const char *field, scalar value) const {
        if (!(value >= 0)) refuse(field, "at least 0 (infinity for none)", value);
    }

    void in(const char *field, scalar value, scalar min, scalar max, bool open_min = false) const {
        if (!(value <= max && (open_min ? value > min : value >= min)))
            refuse(field, detail::concat("in ", open_min ? "(" : "[", min, ", ", max, "]"), value);
    }
};

} // namespace

void validate_settings(const settings &s, const char *function) {
    auto check = settings_check{function};
    check.in("fixed_dt", s.fixed_dt, min_fixed_dt, max_fixed_dt);
    if (!isfinite(s.gravity) || !(length(s.gravity) <= max_gravity))
        check.refuse("gravity", detail::concat("finite and at most ", max_gravity, " m/s^2 long"), s.gravity);
    check.count("num_substeps", s.num_substeps, 1, max_solver_substeps);
    check.count("num_relax_iterations", s.num_relax_iterations, 0, max_solver_iterations);
    check.count("num_restitution_iterations", s.num_restitution_iterations, 0, max_solver_iterations);
    check.count("num_individual_restitution_iterations", s.num_individual_restitution_iterations, 0,
                max_solver_iterations);
    check.count("max_steps_per_update", s.max_steps_per_update, 1, max_steps_per_update_limit);
    check.in("max_linear_speed", s.max_linear_speed, 0, max_linear_speed_limit, true);
    check.not_negative("sleep_linear_velocity", s.sleep_linear_velocity);
    check.not_negative("sleep_angular_velocity", s.sleep_angular_velocity);
    check.bound("time_to_sleep", s.time_to_sleep);

    auto &c = s.contact;
    check.not_negative("contact.contact_hertz", c.contact_hertz);
    check.not_negative("contact.friction_anchor_hertz", c.friction_anchor_hertz);
    check.not_negative("contact.contact_damping_ratio", c.contact_damping_ratio);
    check.in("contact.max_hertz_ratio", c.max_hertz_ratio, 0, 1, true);
    check.not_negative("contact.max_push_out_velocity", c.max_push_out_velocity);
    check.not_negative("contact.restitution_threshold", c.restitution_threshold);

    auto &j = s.joint;
    check.not_negative("joint.joint_hertz", j.joint_hertz);
    check.not_negative("joint.joint_damping_ratio", j.joint_damping_ratio);
    check.in("joint.max_hertz_ratio", j.max_hertz_ratio, 0, 1, true);
    check.not_negative("joint.restitution_threshold", j.restitution_threshold);
    check.in("joint.position_projection", j.position_projection, 0, 1);
    check.count("joint.position_projection_iterations", j.position_projection_iterations, 0,
                max_solver_iterations);
    check.bound("joint.max_projected_gap", j.max_projected_gap);
    check.bound("joint.max_correction_speed", j.max_correction_speed);
}

} // namespace edyn
