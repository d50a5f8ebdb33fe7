#include "edyn/dynamics/material.hpp"
#include "../shapes/invalid_argument.hpp"
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>

namespace edyn {

namespace {

using detail::concat;

} // namespace

void validate_material(const char *function, const char *name, const material_base &m) {
    auto fail = [&](const char *field, const std::string &problem) {
        throw std::invalid_argument(std::string(function) + ": " + name + "." + field + " " + problem);
    };
    if (!(m.friction >= 0) || !std::isfinite(m.friction))
        fail("friction", "must be in [0, inf), got " + concat(m.friction));
    if (!(m.restitution >= 0 && m.restitution <= 1))
        fail("restitution", "must be in [0, 1], got " + concat(m.restitution));
    if (!(m.roll_friction >= 0) || !std::isfinite(m.roll_friction))
        fail("roll_friction", "must be in [0, inf), got " + concat(m.roll_friction));
    if (!(m.spin_friction >= 0) || !std::isfinite(m.spin_friction))
        fail("spin_friction", "must be in [0, inf), got " + concat(m.spin_friction));
    if (!(m.stiffness > 0)) fail("stiffness", "must be positive, got " + concat(m.stiffness));
    if (!(m.damping >= 0)) fail("damping", "must be non-negative, got " + concat(m.damping));
}

} // namespace edyn
