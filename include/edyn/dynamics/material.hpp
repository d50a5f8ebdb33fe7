#ifndef EDYN_DYNAMICS_MATERIAL_HPP
#define EDYN_DYNAMICS_MATERIAL_HPP

#include "edyn/math/scalar.hpp"
#include <cstdint>
#include <limits>

namespace edyn {

// Surface properties of a pair in contact, or of one body before mixing.
struct material_base {
    // Coulomb coefficient, in [0, inf).
    scalar friction{scalar(0.5)};
    // Coefficient of restitution, in [0, 1].
    scalar restitution{0};
    // Torque per unit of normal force (weight) against rolling, in metres.
    scalar roll_friction{0};
    // Torque per unit of normal force against spinning about the contact normal, in metres.
    scalar spin_friction{0};
    // Contact stiffness (N/m) and damping (Ns/m) of the whole contact, shared by its points.
    // large_scalar, the default, means a rigid contact: the solver's global contact_hertz and
    // contact_damping_ratio (contact_solver_settings, in settings::contact) apply. A finite
    // stiffness makes the contact a spring that a load F compresses by F / stiffness; its
    // damping is `damping` or, left at large_scalar, the global damping ratio. Two bodies'
    // values combine in series (material_mixing.hpp). The spring's frequency is capped like the
    // global one (a quarter of the sub-step rate), so a stiffer material is as rigid as the
    // default. `damping` alone, with an infinite stiffness, has no effect.
    scalar stiffness{large_scalar};
    scalar damping{large_scalar};

    bool operator==(const material_base &) const = default;
};

using material_id_type = std::uint32_t;
// Bodies without an id are always mixed with the default mixing functions.
inline constexpr material_id_type invalid_material_id = std::numeric_limits<material_id_type>::max();

// A body's material. Pairs of ids can have their mixed material overridden with
// insert_material_mixing.
struct material : material_base {
    material_id_type id{invalid_material_id};

    bool operator==(const material &) const = default;
};

} // namespace edyn

#endif // EDYN_DYNAMICS_MATERIAL_HPP
