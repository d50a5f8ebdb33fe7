#ifndef EDYN_SRC_CONSTRAINTS_CONTACT_BUNDLE_SOLVER_HPP
#define EDYN_SRC_CONSTRAINTS_CONTACT_BUNDLE_SOLVER_HPP

// The contact solver's passes over four or eight constraints at once (see contact_bundle), and
// the packing that makes the bundles (contact_bundle_packing.cpp). Each lane computes exactly
// what the one-at-a-time passes in contact_solver.cpp compute for its constraint, operation for
// operation, so that bundling changes no result.

#include "../math/wide_scalar.hpp"
#include "edyn/constraints/contact_solver.hpp"
#include <cstdint>
#include <span>

namespace edyn::detail {

// Whether a constraint goes into a bundle: those with points, without spinning or rolling
// friction and without a material spring. (A lane without points is an empty lane.)
bool is_bundled(const contact_solver_constraint &c) noexcept;

// The static side of a contact (see fixed_side): the side whose body is static_solver_body.
inline fixed_side fixed_side_of(const contact_solver_constraint &c) noexcept {
    if (c.body[1] == static_solver_body) return fixed_side::b;
    if (c.body[0] == static_solver_body) return fixed_side::a;
    return fixed_side::none;
}

// What the packing reads of a constraint, in one byte (contact_solver_set::pack_keys), so that
// its part on the calling thread reads a byte per constraint instead of the constraint: the
// bucket it is sorted into (fixed side, then point count, most first) or unbundled_key, and
// bouncy_key when it has restitution.
inline constexpr std::uint8_t unbundled_key = 3 * (contact_solver_constraint::max_points + 1);
inline constexpr std::uint8_t bucket_key_mask = 0x1f;
inline constexpr std::uint8_t bouncy_key = 0x20;
static_assert(unbundled_key <= bucket_key_mask && (bucket_key_mask & bouncy_key) == 0);
std::uint8_t pack_key(const contact_solver_constraint &c) noexcept;

// Whether prepare_contacts() leaves constraint k's tangents, rows and masses to the bundle
// packing, which makes them side by side in the bundle: a coloured constraint (the overflow past
// the colours is solved one at a time) that goes in a bundle, unless it bounces (the restitution
// solver reads its points' rows). Read off the constraint's pack_keys entry, which must be set.
inline bool rows_made_in_bundle(const contact_solver_set &contacts, std::uint32_t k) noexcept {
    auto key = contacts.pack_keys[k];
    return !contacts.colour_begin.empty() && k < contacts.colour_begin.back() &&
           (key & bucket_key_mask) != unbundled_key && !(key & bouncy_key);
}

// Packs each colour's bundled constraints contact_bundle_lanes to a bundle, contacts of one
// fixed side to a bundle, most points first, and lists the others in `singles`; fills the
// bundles' slots from the points, making their rows and masses side by side. Call once the
// points are prepared and every constraint's pack_keys entry is set.
void pack_contact_bundles(contact_solver_set &contacts, std::span<const solver_body> bodies,
                          task_scheduler *scheduler);

// The lanes of a bundle that have a point in its slot s.
inline wide_mask slot_mask(const contact_bundle &bundle, std::uint32_t s) {
    return wide_set(scalar(s)) < wide_from_counts(bundle.num_points);
}

// Asks for the cache line of each of the bundle's bodies that its passes read and write (the
// first of solver_body's two), so that it is on its way while the bundle before is solved.
void prefetch_bundle_bodies(const contact_solver_set &contacts, std::uint32_t bundle,
                            std::span<const solver_body> bodies) noexcept;

// Applies the bundle's impulses to its bodies (warm starting).
void warm_start_bundle(contact_solver_set &contacts, std::uint32_t bundle, std::span<solver_body> bodies);

// What one solve pass shares with every bundle.
struct bundle_pass {
    scalar inv_h;    // 1 / the sub-step.
    softness rigid;  // The rigid contacts' softness for the sub-step.
    softness anchor; // The friction anchors' softness for the sub-step.
    scalar max_push_out_velocity;
    bool use_bias;  // The biased pass, or the relax pass.
    scalar elapsed; // From the start of the step to the middle of the sub-step (s).
};

// One pass of normal and friction rows over the bundle's points.
void solve_bundle(contact_solver_set &contacts, std::uint32_t bundle, std::span<solver_body> bodies,
                  const bundle_pass &pass);

// Adds the bundle's impulses of the sub-step to its step totals.
void accumulate_bundle_impulses(contact_solver_set &contacts, std::uint32_t bundle);

// Copies the bundle's impulses and step totals back into its constraints' points and totals.
void unpack_bundle_impulses(contact_solver_set &contacts, std::uint32_t bundle);

} // namespace edyn::detail

#endif // EDYN_SRC_CONSTRAINTS_CONTACT_BUNDLE_SOLVER_HPP
