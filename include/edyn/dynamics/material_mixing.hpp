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

struct mesh_shape;
struct paged_mesh_shape;
struct shape_ref;

/// Default mixing of two friction coefficients: their geometric mean.
/// One slippery surface makes the contact slippery.
/// @param a First body's friction coefficient.
/// @param b Second body's friction coefficient.
/// @return `sqrt(a * b)`.
inline scalar mix_friction(scalar a, scalar b) noexcept { return std::sqrt(a * b); }
/// Default mixing of two coefficients of restitution: the larger (the bouncier body dominates).
/// @param a First body's coefficient of restitution.
/// @param b Second body's coefficient of restitution.
/// @return The larger of `a` and `b`.
inline scalar mix_restitution(scalar a, scalar b) noexcept { return std::max(a, b); }
/// Default mixing of two rolling friction coefficients (metres): the larger (the more
/// deformable body dominates).
/// @param a First body's rolling friction, in metres.
/// @param b Second body's rolling friction, in metres.
/// @return The larger of `a` and `b`.
inline scalar mix_roll_friction(scalar a, scalar b) noexcept { return std::max(a, b); }
/// Default mixing of two spinning friction coefficients (metres): the larger.
/// @param a First body's spinning friction, in metres.
/// @param b Second body's spinning friction, in metres.
/// @return The larger of `a` and `b`.
inline scalar mix_spin_friction(scalar a, scalar b) noexcept { return std::max(a, b); }
/// Default mixing of two contact stiffnesses (N/m): two springs in series.
/// A value of `large_scalar` or more stands for a rigid contact and leaves the other value.
/// @param a First body's stiffness, in N/m.
/// @param b Second body's stiffness, in N/m.
/// @return `a * b / (a + b)`, or the other value when one is rigid.
inline scalar mix_stiffness(scalar a, scalar b) noexcept {
    if (a >= large_scalar) return b;
    if (b >= large_scalar) return a;
    return a * b / (a + b);
}
/// Default mixing of two contact dampings (N·s/m): two dampers in series, as mix_stiffness.
/// @param a First body's damping, in N·s/m.
/// @param b Second body's damping, in N·s/m.
/// @return `a * b / (a + b)`, or the other value when one is `large_scalar`.
inline scalar mix_damping(scalar a, scalar b) noexcept { return mix_stiffness(a, b); }

/// Mixes two materials with the default mixing functions, property by property.
/// Friction is the geometric mean (one slippery surface makes the contact slippery);
/// restitution, rolling and spinning friction take the larger value (the bouncier or more
/// deformable body dominates); stiffness and damping combine as springs and dampers in series.
/// Pair overrides are not consulted: see get_mixed_material for that.
/// @param a First body's material.
/// @param b Second body's material.
/// @return The mixed material.
material_base mix_materials(const material_base &a, const material_base &b) noexcept;

/// Pair overrides made with insert_material_mixing, kept in the registry's context.
/// Created by the first insert_material_mixing call, erased by detach.
struct material_mix_table {
    /// Mixed material per pair of ids, the smaller id first.
    std::map<std::pair<material_id_type, material_id_type>, material_base> pairs;

    /// Looks up the override for a pair of ids, in either order.
    /// @param id0 One material id.
    /// @param id1 The other material id.
    /// @return The pair's mixed material, or null when the pair has no entry.
    const material_base *find(material_id_type id0, material_id_type id1) const;
};

/// Makes bodies whose materials have ids id0 and id1 (in either order) use `mixed` when they
/// touch, instead of the default mixing.
/// A later call for the same pair replaces the entry. An id may be paired with itself. Bodies
/// with either id are patched (`registry.patch<material>`), which wakes those asleep, so that
/// contacts at rest take the new values too. In asynchronous mode the table reaches the
/// simulation worker with the next update(), step_simulation() or wait_for_simulation().
/// @param registry The registry the bodies live in.
/// @param id0 One material id (material::id).
/// @param id1 The other material id.
/// @param mixed The material to use for contacts between the two.
/// @throws std::invalid_argument When either id is `invalid_material_id`, or when `mixed` is out
/// of the ranges make_rigidbody accepts (validate_material): a friction, rolling or spinning
/// friction that is negative, NaN or infinite, a restitution outside [0, 1], a stiffness that
/// is not positive or a negative damping. The table is left as it was then.
void insert_material_mixing(registry &registry, material_id_type id0, material_id_type id1,
                            const material_base &mixed);

/// The material used for a contact between bodies with materials `a` and `b`.
/// The pair's override when both have ids and insert_material_mixing gave the pair one,
/// otherwise mix_materials.
/// @param registry The registry holding the pair overrides.
/// @param a First body's material.
/// @param b Second body's material.
/// @return The mixed material.
material_base get_mixed_material(const registry &registry, const material &a, const material &b);

/// The same with the pair overrides given: for loops over many contacts, which find the table
/// once (`registry.ctx().find<material_mix_table>()`).
/// @param table The pair overrides; null when there are none.
/// @param a First body's material.
/// @param b Second body's material.
/// @return The mixed material.
material_base get_mixed_material(const material_mix_table *table, const material &a, const material &b);

/// Whether contact points on a shape may each have a material of their own, which
/// get_point_material then gives them: a triangle mesh with per-vertex friction or restitution,
/// or a paged mesh (whose pages tell when loaded); no other shape.
/// @param shape The shape.
/// @return Whether per-point materials may apply to points on it.
bool has_point_materials(const mesh_shape &shape);
/// @copydoc has_point_materials(const mesh_shape &)
bool has_point_materials(const paged_mesh_shape &shape);
/// Every other shape: its points take the bodies' materials.
/// @param shape The shape.
/// @return False.
template<typename Shape>
bool has_point_materials([[maybe_unused]] const Shape &shape) {
    return false;
}

/// The material at one contact point of bodies `a` and `b`.
/// A pair override when one exists; otherwise each mesh body's friction and restitution
/// interpolated at the point from the vertices of its triangle (the point's feature names it),
/// then mixed as usual.
/// @param registry The registry the bodies live in; both must have a material.
/// @param a The manifold's first body.
/// @param b The manifold's second body.
/// @param point The contact point, with its features and object-space pivots.
/// @return The material for that point.
material_base get_point_material(const registry &registry, entity a, entity b, const contact_point &point);

/// The same for loops over many contacts, which gather what it reads once: the pair overrides
/// (null when there are none) and each body's material and shape.
/// @param table The pair overrides; null when there are none.
/// @param mat_a The first body's material.
/// @param shape_a The first body's shape (get_shape_ref).
/// @param mat_b The second body's material.
/// @param shape_b The second body's shape.
/// @param point The contact point, with its features and object-space pivots.
/// @return The material for that point.
material_base get_point_material(const material_mix_table *table, const material &mat_a, shape_ref shape_a,
                                 const material &mat_b, shape_ref shape_b, const contact_point &point);

} // namespace edyn

#endif // EDYN_DYNAMICS_MATERIAL_MIXING_HPP
