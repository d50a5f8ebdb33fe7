#ifndef EDYN_DYNAMICS_MATERIAL_HPP
#define EDYN_DYNAMICS_MATERIAL_HPP

#include "edyn/math/scalar.hpp"
#include <cstdint>
#include <limits>

namespace edyn {

/// Surface properties of a pair in contact, or of one body before mixing.
/// A body's own values live in its material component; two bodies' values are combined by the
/// functions of material_mixing.hpp, or replaced by a pair entry of insert_material_mixing.
/// make_rigidbody refuses values outside the ranges given below.
struct material_base {
    /// Coulomb friction coefficient, in [0, inf); default 0.5.
    scalar friction{scalar(0.5)};
    /// Coefficient of restitution, in [0, 1]; default 0 (no bounce).
    scalar restitution{0};
    /// Torque per unit of normal force (weight) against rolling, in metres; default 0.
    /// Applied only to shapes that roll (spheres, capsules, and cylinders about their axis): a
    /// real coefficient of rolling resistance times the rolling radius.
    scalar roll_friction{0};
    /// Torque per unit of normal force against spinning about the contact normal, in metres;
    /// default 0.
    scalar spin_friction{0};
    /// Contact stiffness of the whole contact, shared by its points, in N/m.
    /// `large_scalar`, the default, means a rigid contact: the solver's global contact_hertz and
    /// contact_damping_ratio (contact_solver_settings, in settings::contact) apply. A finite
    /// stiffness makes the contact a spring that a load F compresses by F / stiffness; its
    /// damping is `damping` or, left at `large_scalar`, the global damping ratio. Two bodies'
    /// values combine in series (material_mixing.hpp). The spring's frequency is capped like the
    /// global one (a quarter of the sub-step rate), so a stiffer material is as rigid as the
    /// default. Must be positive.
    scalar stiffness{large_scalar};
    /// Contact damping of the whole contact, in N·s/m; default `large_scalar` (the global
    /// damping ratio applies).
    /// Used only with a finite `stiffness`: `damping` alone, with an infinite stiffness, has no
    /// effect. Must not be negative.
    scalar damping{large_scalar};

    /// Compares every property exactly.
    /// @return Whether both materials have the same values.
    bool operator==(const material_base &) const = default;
};

/// Checks that a material's values are in the ranges material_base gives; make_rigidbody and
/// insert_material_mixing call it, so that both accept the same materials.
/// @param function Name of the calling function, put at the start of the message.
/// @param name Name of the material argument, put before each field's name ("material" gives
/// "material.friction").
/// @param m The material.
/// @throws std::invalid_argument "<function>: <name>.<field> must be ..., got <value>", when the
/// friction, roll_friction or spin_friction is negative or not finite, the restitution is
/// outside [0, 1], the stiffness is not positive, or the damping is negative (NaN fails each).
void validate_material(const char *function, const char *name, const material_base &m);

/// Numeric id of a material, for pair overrides with insert_material_mixing.
using material_id_type = std::uint32_t;
/// The id of a material that has none (the default of material::id).
/// Bodies without an id are always mixed with the default mixing functions.
inline constexpr material_id_type invalid_material_id = std::numeric_limits<material_id_type>::max();

/// Component: a body's material, set from rigidbody_def::material by make_rigidbody.
/// Its surface properties (friction, restitution, roll_friction, spin_friction, stiffness,
/// damping) are the members it inherits from material_base. Sensors have none. Pairs of ids can
/// have their mixed material overridden with insert_material_mixing. Change it with `replace`
/// or `patch` so that the simulation sees it.
struct material : material_base {
    /// Id for pair overrides; `invalid_material_id` (the default) when the material has none.
    material_id_type id{invalid_material_id};

    /// Compares every property and the id exactly.
    /// @return Whether both materials have the same values and id.
    bool operator==(const material &) const = default;
};

} // namespace edyn

#endif // EDYN_DYNAMICS_MATERIAL_HPP
