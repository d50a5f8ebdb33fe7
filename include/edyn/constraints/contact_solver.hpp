#ifndef EDYN_CONSTRAINTS_CONTACT_SOLVER_HPP
#define EDYN_CONSTRAINTS_CONTACT_SOLVER_HPP

#include "edyn/collision/contact_manifold.hpp"
#include "edyn/constraints/contact_bundle.hpp"
#include "edyn/dynamics/solver_body.hpp"
#include "edyn/parallel/stage_queue.hpp"
#include "edyn/parallel/task_scheduler.hpp"
#include <array>
#include <cstdint>
#include <span>
#include <vector>

namespace edyn {

/// A velocity constraint row along the unit direction d at offsets rA, rB: its angular parts and
/// those parts premultiplied by each body's inverse inertia, computed once per step so that the
/// iterations apply and measure impulses with dot products and no matrix products.
struct contact_row {
    /// @var angularA
    /// rA x d (m).
    /// @var angularB
    /// rB x d (m).
    vector3 angularA{vector3_zero}, angularB{vector3_zero};
    /// @var inv_angularA
    /// Body A's world inverse inertia times `angularA`.
    /// @var inv_angularB
    /// Body B's world inverse inertia times `angularB`.
    vector3 inv_angularA{vector3_zero}, inv_angularB{vector3_zero};
};

/// One point of a contact as the solver's iterations see it: only what every pass reads or
/// writes, so that the passes stream through as little memory as possible (a large pile has
/// tens of thousands of points, far more than the caches hold). Geometry is captured at the
/// start of the step (narrowphase output); the current separation is recovered from the
/// bodies' accumulated motion.
/// The caller sets `rA`, `rB`, `normal`, `adjusted_separation`, `adjusted_anchor_gap` and last
/// step's impulses;
/// prepare_contacts() computes the rest: the path acceleration, the tangents, effective masses
/// and rows. For a point of
/// a bundled constraint that does not bounce it computes them in the bundle, several points at
/// once, and leaves the point's own unset.
struct contact_solver_point {
    /// @var rA
    /// Contact point on A relative to A's centre of mass, world space (m).
    /// @var rB
    /// Contact point on B relative to B's centre of mass, world space (m).
    vector3 rA, rB;
    vector3 normal;     ///< Unit contact normal, from B towards A, world space.
    vector3 tangent[2]; ///< Two unit tangents orthogonal to the normal, set by prepare_contacts().
    /// Separation minus dot(normal, rA - rB) (m): with the bodies' motion since the step began
    /// it gives the current separation (negative: overlap).
    scalar adjusted_separation{0};
    /// Where static friction holds the point: its anchor on A minus its anchor on B along the
    /// surfaces when the step began (contact_point::anchor_gap), minus rA - rB (m). Dotted with
    /// a tangent, with the bodies' motion since then, it gives how far the surfaces slid from
    /// where they stuck, which the biased pass's friction rows undo.
    vector3 adjusted_anchor_gap{vector3_zero};
    /// How fast the two bodies' points at the contact turn away from each other as the bodies
    /// rotate, when the step began: w_A x (w_A x rA') - w_B x (w_B x rB') for the levers' parts
    /// across the normal rA' and rB' (m/s^2; a rolling body's foot stays below its centre). The
    /// rows take the lever arms of the step's start; with this the friction rows hold the points
    /// together in the middle of each sub-step, on their curved paths, not on the lines they
    /// started along. Set by prepare_contacts() for every point, bundled or not.
    vector3 path_acceleration{vector3_zero};
    scalar normal_mass{0};           ///< Effective mass along the normal (kg).
    scalar tangent_mass[2]{0, 0};    ///< Effective mass along each tangent (kg).
    scalar normal_impulse{0};        ///< Normal impulse of the sub-step (N s), not negative.
    scalar tangent_impulse[2]{0, 0}; ///< Friction impulse of the sub-step along each tangent (N s).
    contact_row normal_row;          ///< The normal row's angular parts.
    contact_row tangent_row[2];      ///< The tangent rows' angular parts.
};

/// What a point needs only once per sub-step or step: restitution and the impulses reported
/// to the user. Kept apart from contact_solver_point, at the same index.
struct contact_point_totals {
    /// The fastest normal approach of the point seen in the step not yet answered by a bounce:
    /// its relative normal velocity when the step began (prepare_contacts), lowered by each
    /// restitution pass, 0 once bounced. In m/s, negative when approaching.
    scalar relative_velocity{0};
    /// Sum of the restitution solver's normal impulses on the point over the step (N s).
    scalar restitution_impulse{0};
    /// Sum of the restitution solver's friction impulses along each tangent over the step (N s).
    scalar tangent_restitution_impulse[2]{0, 0};
    /// Sums over the step's sub-steps of the point's impulses.
    /// The normal impulse (N s).
    scalar normal_impulse{0};
    /// Sum over the step's sub-steps of the friction impulse along each tangent (N s).
    scalar tangent_impulse[2]{0, 0};
};

/// A manifold's contact ready to be solved: up to four points (each with its own normal, as
/// compound shapes may give several), stored from `first_point` in the set's point arrays,
/// their friction, and torsional (spin) and rolling friction about the manifold's main normal.
/// Filled by the caller from the contact manifold and the mixed material; prepare_contacts()
/// computes the effective masses.
struct contact_solver_constraint {
    static constexpr std::size_t max_points = 4; ///< Most points a constraint may have.
    solver_body_index body[2]{0, 0};             ///< Indices of the two bodies in the solver bodies.
    vector3 normal{vector3_zero};                ///< Main normal, for spinning and rolling friction.
    scalar friction{0};                          ///< Friction coefficient of the mixed material.
    scalar restitution{0};                       ///< Restitution of the mixed material, in [0, 1].
    /// Rolling friction of the mixed material: resisting torque per unit normal force (m).
    scalar roll_friction{0};
    /// Spinning friction of the mixed material: resisting torque per unit normal force (m).
    scalar spin_friction{0};
    /// The mixed material's stiffness (N/m) and damping (Ns/m) of the whole contact, shared by
    /// its points; large_scalar means the global contact_hertz and damping ratio apply.
    /// This member is the stiffness.
    scalar stiffness{large_scalar};
    /// The mixed material's damping (N s/m); large_scalar means the contact damping ratio applies.
    scalar damping{large_scalar};
    std::uint32_t first_point{0}; ///< Index of the first point in the set's point arrays.
    std::uint32_t num_points{0};  ///< Number of points, at most `max_points`.
    /// Spinning friction about the normal.
    /// Effective mass of the spinning row (kg m^2), set by prepare_contacts().
    scalar spin_mass{0};
    scalar spin_impulse{0}; ///< Spinning friction impulse of the sub-step (N m s).
    /// Rolling friction about up to two axes orthogonal to the normal (one for cylinders).
    /// The number of those axes, 0 to 2.
    std::uint32_t num_roll_axes{0};
    vector3 roll_axis[2]{vector3_zero, vector3_zero}; ///< The rolling axes, unit, world space.
    scalar roll_mass[2]{0, 0};                        ///< Effective mass of each rolling row (kg m^2).
    scalar roll_impulse[2]{0, 0}; ///< Rolling friction impulse of the sub-step per axis (N m s).
    scalar total_spin_impulse{0}; ///< Sum over the step's sub-steps of the spinning impulse (N m s).
    /// Sum over the step's sub-steps of the rolling impulse per axis (N m s).
    scalar total_roll_impulse[2]{0, 0};
    /// Where the impulses go back when the step ends (index into the caller's manifold list).
    std::uint32_t source{0};
    /// The side whose body the relax passes may hold still at this contact's normal rows: the
    /// body fewer contacts away from the bodies that do not move (contact_order's depth; the
    /// lower one in a stack), none when both are as far. When every point of the contact parts
    /// faster than contact_hold_parting_speed in a relax pass, the normal rows move only the
    /// other body (see contact_hold_parting_speed).
    edyn::fixed_side held{edyn::fixed_side::none};
};

/// Every contact of a step: the constraints, and their points in two parallel arrays (hot and
/// cold). Reused from step to step, so that a step allocates nothing once the world stops
/// growing.
struct contact_solver_set {
    std::vector<contact_solver_constraint> constraints; ///< The contacts' constraints.
    /// Hot part of every constraint's points, indexed by `first_point`.
    std::vector<contact_solver_point> points;
    /// Cold part of every point, at the same index as in `points`.
    std::vector<contact_point_totals> totals;
    /// The constraints in colour order (see constraint_colouring): colour k is the range
    /// [colour_begin[k], colour_begin[k + 1]), and no two constraints of one colour share a body
    /// that moves, so a colour's constraints are solved at once on the scheduler's threads. Any
    /// constraints from colour_begin.back() on (all of them when the set was not coloured) are
    /// solved in order on the calling thread, after the colours.
    std::vector<std::uint32_t> colour_begin;
    /// The coloured constraints as prepare_contacts() packs them, contact_bundle_lanes to a bundle, colour by
    /// colour: colour k's bundles are [bundle_begin[k], bundle_begin[k + 1]). Between
    /// prepare_contacts() and unpack_contact_impulses() a bundled constraint's impulses live
    /// in its bundle's slots, not in its points.
    std::vector<contact_bundle> bundles;
    /// The bundles' point slots, indexed by contact_bundle::first_slot.
    std::vector<contact_bundle_slot> bundle_slots;
    /// The step totals of each of bundle_slots, at the same index.
    std::vector<contact_bundle_totals> bundle_totals;
    /// Where each colour's bundles begin in `bundles`, one entry per colour and one past the end.
    std::vector<std::uint32_t> bundle_begin;
    /// The coloured constraints solved one at a time (those with spinning or rolling friction or a
    /// material spring), colour by colour: colour k's are [single_begin[k], single_begin[k + 1]).
    std::vector<std::uint32_t> singles;
    /// Where each colour's constraints begin in `singles`, as `bundle_begin`.
    std::vector<std::uint32_t> single_begin;
    /// The colours' bundles and single constraints cut into blocks for the scheduler's threads,
    /// numbered colour after colour: colour k's are [block_begin[k], block_begin[k + 1]).
    std::vector<std::uint32_t> block_begin;
    /// Bundles and single constraints per block of each colour (a colour's last block may have
    /// fewer): colours are cut to keep every thread busy, whatever their size.
    std::vector<std::uint32_t> block_items;
    /// The constraints with restitution, in order: those solve_restitution() looks at. Listed
    /// by prepare_contacts().
    std::vector<std::uint32_t> bouncy;
    /// Scratch of prepare_contacts(): one colour's bundled constraints, most points first.
    std::vector<std::uint32_t> packing;
    /// Scratch of prepare_contacts(): what the bundle packing and the list of bouncy constraints
    /// need of each constraint, a byte each, worked out on the scheduler's threads.
    std::vector<std::uint8_t> pack_keys;

    /// Empties every array, keeping their capacity.
    void clear() noexcept {
        constraints.clear();
        points.clear();
        totals.clear();
        colour_begin.clear();
        bundles.clear();
        bundle_slots.clear();
        bundle_totals.clear();
        bundle_begin.clear();
        singles.clear();
        single_begin.clear();
        block_begin.clear();
        block_items.clear();
        bouncy.clear();
    }
    /// Appends `c` with `num_points` default points and returns the first of them.
    /// Sets the new constraint's `first_point` and `num_points` and grows `totals` alongside.
    /// The pointer is valid until the next add() or clear().
    /// @param c The constraint to append; its point range is overwritten.
    /// @param num_points Its number of points, at most contact_solver_constraint::max_points
    /// (not checked).
    /// @return The first of the new points, to be filled in.
    contact_solver_point *add(const contact_solver_constraint &c, std::uint32_t num_points);
};

/// Speed above which a contact's points part in a relax pass (m/s) for that pass to hold the
/// contact's lower body still (contact_solver_constraint::held). The relax passes take back the
/// velocity the biased pass gave to push overlap out, contact after contact from the ground up.
/// Between two moving bodies, taking it back from both gave the lower body the upper one's push
/// the other way after the contact below it was done with it for the pass: a ball dropped 1 m
/// onto a 1 kg box on the ground lifted the box by 57 mm (5 kg ball) or 177 mm (20 kg), and a
/// 5 kg box dropped onto a tower of five 1 kg boxes lifted its top by 151 mm. Held still, the
/// lower body keeps what its own support gave it, and none of them rises. The contacts of
/// resting bodies part by a few mm/s, which tall stacks need taken back from both sides so as
/// not to lean: below this speed, both move. The price is momentum where the lower body could
/// give way: it keeps the push the upper one loses (docs/guide/01-the-step.md gives a seesaw's
/// figures).
inline constexpr scalar contact_hold_parting_speed = scalar(0.05);

/// Tuning of the soft-step contact solver, shared by all contacts of a step. These are the
/// global contact stiffness and damping, the defaults for every contact: a contact whose mixed
/// material has a finite stiffness (material_base::stiffness) is instead a spring of that
/// stiffness, with the material's damping or, when that is not set, contact_damping_ratio.
/// Held by the world's settings (`settings::contact`); the solver reads it at every step.
struct contact_solver_settings {
    /// Stiffness of contacts as a spring frequency, in Hz. A loaded contact sinks by
    /// load / (m w^2), so stacks stand taller the stiffer it is. It is capped at
    /// max_hertz_ratio times the sub-step rate for stability: at the default 60 Hz with 6
    /// sub-steps that cap is 90 Hz, the default, so a stiffer value takes effect only with more
    /// sub-steps or a smaller fixed dt.
    scalar contact_hertz{90};
    /// Stiffness with which static friction holds a point where it stuck, as a spring frequency
    /// in Hz, damped with contact_damping_ratio and capped like contact_hertz. In the biased
    /// pass the friction rows pull the surfaces back by how far they slid since the point stuck
    /// (contact_solver_point::adjusted_anchor_gap; kept across collide() up to
    /// contact_anchor_max_slip; since the step began for points younger than
    /// contact_anchor_min_lifetime), so that a body at rest does not creep
    /// by what the velocity rows leave over each sub-step; friction's limit still applies. Lower than
    /// contact_hertz because a body resting on many points feels the sum of their springs: at 90 Hz the top
    /// box of a pyramid jitters, at 45 Hz it rests. 0 turns the hold off. Default 45.
    scalar friction_anchor_hertz{45};
    /// Damping ratio of the contact spring. Measured with the 30-box tower and the 40-wide
    /// pyramid over 10 s: ratios of 1 to 2 leave the top box within 3 mm (tower) and 1.4 cm
    /// (pyramid, mostly the springs' compression), while 5 to 10 let stacks wobble and creep by
    /// 5 to 30 cm and never sleep.
    /// Default 2.
    scalar contact_damping_ratio{2};
    /// Contact frequency (global, or a material's) is capped at this fraction of the sub-step
    /// rate: a material stiffer than that is as stiff as the global default.
    /// Default 0.25.
    scalar max_hertz_ratio{scalar(0.25)};
    /// Cap on the speed at which overlap is pushed out by rigid contacts, m/s (a material spring
    /// pushes as hard as its stiffness says).
    /// Default 3.
    scalar max_push_out_velocity{3};
    /// Approach speed below which restitution is ignored, so resting bodies do not jitter.
    /// In m/s; default 0.5.
    scalar restitution_threshold{scalar(0.5)};

    /// Whether every field is the same.
    bool operator==(const contact_solver_settings &) const = default;
};

/// Computes tangent frames, effective masses and starting normal velocities; call after the
/// points' rA, rB, normal and adjusted separation are set, and before any solve.
/// The work of this and the passes below is spread over the scheduler's threads when there is
/// one, colour by colour; the results do not depend on it, nor on its number of threads.
/// Also resets each point's totals (keeping the carried approach) and each constraint's
/// spinning and rolling totals, and packs each colour's plain constraints contact_bundle_lanes
/// to a bundle (contact_bundle), which the passes below solve that many at a time with vector
/// instructions (AVX2 or SSE2 on x86-64 in single precision, plain arrays otherwise), lane for
/// lane the same operations as one at a time, so that bundling changes no result. Called once
/// per step.
/// @param contacts The step's contacts.
/// @param bodies The step's solver bodies (their velocities and inverse inertias are read).
/// @param scheduler Threads to spread the work over; null runs it on the calling thread.
void prepare_contacts(contact_solver_set &contacts, std::span<const solver_body> bodies,
                      task_scheduler *scheduler = nullptr);

/// The passes below queue their work instead of running it (see stage_queue), a stage per
/// colour, so that a step's passes are handed to the scheduler together: they run, in the
/// order they were queued, when the queue is run. `contacts`, the storage behind `bodies` and
/// `settings` must outlive that run, and must not change before it.

/// Queues re-applying the accumulated impulses as the initial guess: last step's at the first
/// sub-step, then those of the sub-step before (they are applied as they are, not scaled).
/// Queued at the start of each sub-step, after the restitution solve.
/// @param contacts The step's contacts.
/// @param bodies The step's solver bodies.
/// @param queue Where the pass is queued.
void warm_start_contacts(contact_solver_set &contacts, std::span<solver_body> bodies, stage_queue &queue);

/// Queues one Gauss-Seidel pass. With `use_bias`, overlap is pushed out softly at the sub-step rate h;
/// without it (relax pass) only the velocity constraints are enforced, removing the push-out
/// velocity so that it does not turn into bounce; a contact that parts faster than
/// contact_hold_parting_speed moves only its body further from the ground there. The springs of contacts with
/// a material stiffness are forces of the model: they act in the biased pass only, and bounce as springs do.
/// Each constraint solves its points' normal rows, then their friction, then its spinning and
/// rolling friction. Points still apart may close their gap within the sub-step, no further.
/// @param contacts The step's contacts; their impulses accumulate.
/// @param bodies The step's solver bodies.
/// @param h The sub-step (s).
/// @param substep Which sub-step of the step this is, from 0: friction holds the points in its
/// middle (contact_solver_point::path_acceleration).
/// @param settings The contact settings.
/// @param use_bias True for the biased pass, false for the relax pass.
/// @param queue Where the pass is queued.
void solve_contacts(contact_solver_set &contacts, std::span<solver_body> bodies, scalar h, unsigned substep,
                    const contact_solver_settings &settings, bool use_bias, stage_queue &queue);

/// Queues adding each impulse of the sub-step just solved to the step's totals, once at the end
/// of every sub-step. The accumulated impulses themselves are per sub-step (each sub-step starts
/// from the last one's, warm starting), so their sum is what the contact gave over the step.
/// The bundled constraints' totals are kept in their bundles until unpack_contact_impulses().
/// @param contacts The step's contacts.
/// @param queue Where the work is queued.
void accumulate_contact_impulses(contact_solver_set &contacts, stage_queue &queue);

/// Copies the bundled constraints' impulses and step totals from their bundles back into their
/// points and totals; call once after the last sub-step, before anything reads them (the
/// step-end restitution, the write-back).
/// @param contacts The step's contacts.
/// @param scheduler Threads to spread the work over; null runs it on the calling thread.
void unpack_contact_impulses(contact_solver_set &contacts, task_scheduler *scheduler = nullptr);

/// When solve_restitution looks for points to bounce.
enum class bounce_moment {
    /// At the start of a sub-step, before the contact solve: points that touch, or will within
    /// the sub-step h.
    sub_step,
    /// At the end of the step, after the last sub-step: points the contact braked short of the
    /// surface and that still approach. Their bounce is answered in the step that saw their
    /// speed, so that the next step needs nothing but the bodies' state (a world restored from
    /// positions and velocities alone, as a networked client's is, bounces the same).
    step_end
};

/// Restitution: a point approaching faster than the threshold, found as `moment` says, gets an
/// impulse making it separate at restitution times the fastest approach speed seen in the step.
/// Manifolds are solved one at a time for `individual_iterations`, the whole set up to
/// `iterations` times, until no point is hit, so that a shock travels along a chain of bodies.
/// Returns the number of passes that found a hit. Runs on the calling thread. Contacts without
/// restitution are skipped; friction acts during each bounce. The impulses are added to the
/// points' restitution totals.
/// @param contacts The step's contacts, prepared.
/// @param bodies The step's solver bodies.
/// @param settings The contact settings (restitution threshold).
/// @param h The sub-step (s).
/// @param iterations Most passes over the whole set; 0 turns the restitution solver off.
/// @param individual_iterations Iterations of each manifold's isolated solve; 0 turns the
/// restitution solver off.
/// @param moment Which points are looked at: see bounce_moment.
/// @return The number of passes that found a hit (0 when it is off).
unsigned solve_restitution(contact_solver_set &contacts, std::span<solver_body> bodies,
                           const contact_solver_settings &settings, scalar h, unsigned iterations,
                           unsigned individual_iterations, bounce_moment moment = bounce_moment::sub_step);

/// Lowers each point's approach speed (contact_point_totals::relative_velocity) to its relative
/// normal velocity now, if faster, on the contacts with restitution: the fastest approach of the
/// step, which bounce_without_restitution_solver answers. Call at each sub-step, after the
/// velocities are integrated. Runs on the calling thread.
/// @param contacts The step's contacts, prepared.
/// @param bodies The step's solver bodies.
void record_approach_speeds(contact_solver_set &contacts, std::span<const solver_body> bodies);

/// Restitution without the restitution solver (its iterations set to 0), the limited kind
/// the manual describes: at the end of the step, each point of a contact with restitution that
/// approached faster than the threshold in the step (record_approach_speeds), and that the
/// contact solver met in the step, gets the normal impulse making it separate at restitution
/// times that speed.
/// Manifolds are taken one at a time, without friction, and each once: a point already resting
/// (approaching slower than the threshold) returns nothing, so the shock does not travel along a
/// chain of touching bodies. The impulses are added to the points' normal impulse totals. Runs
/// on the calling thread.
/// @param contacts The step's contacts, solved and unpacked (unpack_contact_impulses).
/// @param bodies The step's solver bodies.
/// @param settings The contact settings (restitution threshold).
void bounce_without_restitution_solver(contact_solver_set &contacts, std::span<solver_body> bodies,
                                       const contact_solver_settings &settings);

} // namespace edyn

#endif // EDYN_CONSTRAINTS_CONTACT_SOLVER_HPP
