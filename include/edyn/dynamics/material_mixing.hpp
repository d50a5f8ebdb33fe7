#ifndef EDYN_DYNAMICS_MATERIAL_MIXING_HPP
#define EDYN_DYNAMICS_MATERIAL_MIXING_HPP

#include "edyn/collision/contact_point.hpp"
#include "edyn/dynamics/material.hpp"
#include "edyn/ecs/registry.hpp"
#include <cmath>
#include <map>
#include <optional>
#include <utility>

namespace edyn {

// Default mixing of two bodies' materials when no pair entry exists. Friction is the geometric
// mean (one slippery surface makes the contact slippery); restitution, rolling and spinning
// friction take the larger value (the bouncier or more deformable body dominates); stiffness
// and damping combine as springs and dampers in series.
inline scalar mix_friction(scalar a, scalar b) noexcept { return std::sqrt(a * b); }
inline scalar mix_restitution(scalar a, scalar b) noexcept { return std::max(a, b); }
inline scalar mix_roll_friction(scalar a, scalar b) noexcept { return std::max(a, b); }
inline scalar mix_spin_friction(scalar a, scalar b) noexcept { return std::max(a, b); }
inline scalar mix_stiffness(scalar a, scalar b) noexcept {
    if (a >= large_scalar) return b;
    if (b >= large_scalar) return a;
    return a * b / (a + b);
}
inline scalar mix_damping(scalar a, scalar b) noexcept { return mix_stiffness(a, b); }

material_base mix_materials(const material_base &a, const material_base &b) noexcept;

// Pair overrides, kept in the registry's context.
struct material_mix_table {
    std::map<std::pair<material_id_type, material_id_type>, material_base> pairs;

    const material_base *find(material_id_type id0, material_id_type id1) const;
};

// Makes bodies whose materials have ids id0 and id1 (in either order) use `mixed` when they touch,
// instead of the default mixing. Throws std::invalid_argument for invalid_material_id or values
// out of range.
void insert_material_mixing(registry &registry, material_id_type id0, material_id_type id1,
                            const material_base &mixed);

// The material used for a contact between bodies with materials a and b.
material_base get_mixed_material(const registry &registry, const material &a, const material &b);

// Whether either body is a triangle mesh with per-vertex friction or restitution, so that its
// contact points each have their own material (get_point_material).
bool has_per_vertex_material(const registry &registry, entity a, entity b);

// The material at one contact point of bodies a and b: a pair override when one exists;
// otherwise each mesh body's friction and restitution interpolated at the point from the
// vertices of its triangle (the point's feature names it), then mixed as usual.
material_base get_point_material(const registry &registry, entity a, entity b, const contact_point &point);

} // namespace edyn

#endif // EDYN_DYNAMICS_MATERIAL_MIXING_HPP
