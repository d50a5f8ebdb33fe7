#ifndef EDYN_CONSTRAINTS_CONTACT_BUNDLE_HPP
#define EDYN_CONSTRAINTS_CONTACT_BUNDLE_HPP

#include "edyn/dynamics/solver_body.hpp"
#include <cstdint>

namespace edyn {

/// Number of contact constraints a bundle holds side by side, one per lane: eight in a build with
/// the CMake option EDYN_AVX2 (solved with AVX2 instructions), four otherwise (SSE2 on x86-64).
/// Lanes are independent, so both give the same results bit for bit.
#ifdef EDYN_AVX2
inline constexpr std::size_t contact_bundle_lanes = 8;
#else
inline constexpr std::size_t contact_bundle_lanes = 4;
#endif

/// Which body of a contact is the static body (static_solver_body), whose terms the contact's
/// rows leave out: it never moves, its velocities and motion since the step began are zero.
/// A contact against a static body, the commonest kind on the ground or a terrain, then does
/// about half the work. The one-at-a-time passes and the bundles both follow it, so that a
/// contact gives the same bits in either.
enum class fixed_side : std::uint8_t {
    none, ///< Both bodies count (neither is the static body).
    a,    ///< Body A is the static body.
    b     ///< Body B is the static body.
};

/// Contact constraints of one colour packed side by side, lane by lane (contact_bundle_lanes of
/// them), so that the contact solver works on all of them at once with vector instructions (see
/// contact_solver_set). They share no body that moves, so solving them together is solving them
/// one after another.
/// Built by prepare_contacts() for the constraints without spinning or rolling friction and
/// without a material spring; the others are solved one at a time.
struct contact_bundle {
    /// Index of each lane's constraint in contact_solver_set::constraints; a lane past the end
    /// of its colour has no constraint and `num_points` 0.
    std::uint32_t constraint[contact_bundle_lanes]{};
    /// Each lane's two bodies, indices into the solver bodies; an empty lane has the static body.
    solver_body_index body[2][contact_bundle_lanes]{};
    /// Each lane's number of points, 0 to contact_solver_constraint::max_points.
    std::uint32_t num_points[contact_bundle_lanes]{};
    /// Bit i set when lane i's body A (`moves_a`) or body B (`moves_b`) moves: only those are
    /// written back; a body that does not move is read by many lanes and changed by none.
    /// This member is body A's bits.
    std::uint32_t moves_a{0};
    std::uint32_t moves_b{0}; ///< Bit i set when lane i's body B moves.
    /// Index of the bundle's first point slot in contact_solver_set::bundle_slots.
    std::uint32_t first_slot{0};
    /// Number of point slots: the most points any lane has.
    std::uint32_t num_slots{0};
    /// Number of slots every lane fills: the fewest points any non-empty lane has, or 0 when
    /// a lane is empty. Slots from here on are masked lane by lane.
    std::uint32_t full_slots{0};
    scalar friction[contact_bundle_lanes]{}; ///< Each lane's friction coefficient.
    /// Each lane's held side (contact_solver_constraint::held) as a count: 0 none, 1 body A,
    /// 2 body B. Empty lanes and bundles with a static side hold none.
    std::uint32_t held[contact_bundle_lanes]{};
    /// Whether any lane holds a side: the relax pass then works out which lanes part.
    bool holds{false};
    /// The static side of every lane's contact (a bundle holds contacts of one kind; its empty
    /// lanes have the static body on both sides).
    edyn::fixed_side fixed_side{edyn::fixed_side::none};
};

/// The k-th point of every lane of a contact_bundle: what the solver's passes read and write,
/// as in contact_solver_point, with the lanes side by side. A vector is stored as its x, y and z
/// arrays; a row as its four vectors angularA, angularB, inv_angularA, inv_angularB.
struct contact_bundle_slot {
    scalar rA[3][contact_bundle_lanes];     ///< Point on A relative to A's centre of mass (m).
    scalar rB[3][contact_bundle_lanes];     ///< Point on B relative to B's centre of mass (m).
    scalar normal[3][contact_bundle_lanes]; ///< Unit contact normal, from B towards A.
    /// The two unit tangents.
    scalar tangent[2][3][contact_bundle_lanes];
    /// See contact_solver_point::adjusted_separation (m).
    scalar adjusted_separation[contact_bundle_lanes];
    /// See contact_solver_point::adjusted_anchor_gap (m).
    scalar adjusted_anchor_gap[3][contact_bundle_lanes];
    /// See contact_solver_point::path_acceleration (m/s^2).
    scalar path_acceleration[3][contact_bundle_lanes];
    scalar normal_mass[contact_bundle_lanes];     ///< Effective mass along the normal (kg).
    scalar tangent_mass[2][contact_bundle_lanes]; ///< Effective mass along each tangent (kg).
    scalar normal_impulse[contact_bundle_lanes];  ///< Normal impulse of the sub-step (N s).
    /// Friction impulse of the sub-step along each tangent (N s).
    scalar tangent_impulse[2][contact_bundle_lanes];
    /// The normal row's angular parts: angularA, angularB, inv_angularA, inv_angularB.
    scalar normal_row[4][3][contact_bundle_lanes];
    /// The tangent rows' angular parts, each as `normal_row`.
    scalar tangent_row[2][4][3][contact_bundle_lanes];
};

/// The step totals of a contact_bundle_slot's impulses, kept apart from the slot, which the
/// solver's passes read, as contact_point_totals is kept apart from contact_solver_point.
struct contact_bundle_totals {
    /// Sum over the step's sub-steps of the normal impulse (N s).
    scalar normal_impulse[contact_bundle_lanes];
    /// Sum over the step's sub-steps of the friction impulse along each tangent (N s).
    scalar tangent_impulse[2][contact_bundle_lanes];
};

} // namespace edyn

#endif // EDYN_CONSTRAINTS_CONTACT_BUNDLE_HPP
