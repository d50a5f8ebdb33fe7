#ifndef EDYN_DYNAMICS_MATERIAL_MIXING_HPP
#define EDYN_DYNAMICS_MATERIAL_MIXING_HPP

#include "edyn/collision/contact_manifold.hpp"
#include "edyn/collision/contact_point.hpp"
#include "edyn/dynamics/material.hpp"
#include "edyn/ecs/registry.hpp"
#include <cmath>
#include <map>
#include <optional>
#include <utility>

namespace edyn {

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
/// A later call for the same pair replaces the entry. An id may be paired with itself. In
/// asynchronous mode the table reaches the simulation worker with the next update(),
/// step_simulation() or wait_for_simulation().
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

/// Whether either body may have contact points each with their own material.
/// True when a body is a triangle mesh with per-vertex friction or restitution, or a paged mesh
/// (whose pages tell when loaded); its points then get their material from get_point_material.
/// @param registry The registry the bodies live in.
/// @param a First body.
/// @param b Second body.
/// @return Whether per-point materials may apply to this pair.
bool has_per_vertex_material(const registry &registry, entity a, entity b);

/// Whether the points of `manifold` may each have their own material: the manifold's
/// `point_materials` once the narrowphase has worked it out, else has_per_vertex_material() of
/// its bodies (a manifold the narrowphase has not collided yet).
/// @param registry The registry the manifold's bodies live in.
/// @param manifold The manifold.
/// @return Whether per-point materials may apply to the manifold's points.
bool has_per_vertex_material(const registry &registry, const contact_manifold &manifold);

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

} // namespace edyn

#endif // EDYN_DYNAMICS_MATERIAL_MIXING_HPP
