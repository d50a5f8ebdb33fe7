#ifndef EDYN_CONSTRAINTS_CONSTRAINT_COLOURING_HPP
#define EDYN_CONSTRAINTS_CONSTRAINT_COLOURING_HPP

#include "edyn/dynamics/solver_body.hpp"
#include <cstdint>
#include <span>
#include <vector>

namespace edyn {

/// Colours a step's constraints, taken in the order the sequential solver visits them, so that
/// no two constraints of one colour share a body that moves, and every constraint comes after
/// each earlier one that shares a moving body with it. Solving the colours in turn, the
/// constraints of one colour at once on any number of threads, then gives bit for bit what
/// solving them one after another in the given order gives: two constraints that share no moving
/// body touch no common state, and those that do keep their order. Bodies that do not move (the
/// static body, kinematic bodies: see moves() in solver_body.hpp) are only read by the solver and order
/// nothing. A constraint's colour is one more than the highest colour taken so far by either of
/// its moving bodies, found in constant time; colouring allocates only when the world grows.
///
/// The colour count is the longest run of constraints, one after another in the given order,
/// that each share a body with the next: a few dozen in a pile, the whole length of a chain
/// solved end to end (which then runs on one thread, as it must to give the sequential result).
///
/// Use: reset(), assign() for every constraint in solving order, colour_ranges(), then
/// next_place() for every constraint to find where it goes. One colouring is used by one thread
/// at a time.
class constraint_colouring {
public:
    /// Starts a new colouring for these bodies, which must outlive it (only whether they move
    /// is read).
    /// @param bodies The step's solver bodies, indexed by solver_body_index.
    void reset(std::span<const solver_body> bodies);

    /// The colour of the next constraint, between bodies a and b, with `num_points` rows of
    /// storage (contact points); both are counted per colour for place().
    /// @param a Index of the constraint's first body in the bodies given to reset().
    /// @param b Index of its second body.
    /// @param num_points Points (or rows) the constraint stores; 1 for a joint.
    /// @return The constraint's colour, from 0.
    std::uint32_t assign(solver_body_index a, solver_body_index b, std::uint32_t num_points = 1);

    /// Number of colours taken so far (one more than the highest colour assigned).
    /// @return The colour count; 0 before any assign() since reset().
    std::uint32_t num_colours() const noexcept { return static_cast<std::uint32_t>(counts.size()); }

    /// Once every constraint is assigned: the first constraint index of each colour, colours in
    /// order, and one past the last, written over `begin` (num_colours() + 1 entries).
    /// Call it once per colouring, as it turns the counts into the places next_place() hands out.
    /// @param begin Cleared, then filled with the colour boundaries.
    void colour_ranges(std::vector<std::uint32_t> &begin);

    /// Once colour_ranges has run: the next place of a constraint of `colour` in the colour-ordered
    /// arrays, and the first of its num_points points; constraints of one colour are placed in
    /// the order they are asked for.
    struct place {
        /// @var constraint
        /// Index of the constraint in the colour-ordered constraint array.
        /// @var first_point
        /// Index of its first point in the colour-ordered point array.
        std::uint32_t constraint, first_point;
    };
    /// The next free place of a constraint of `colour` (see place).
    /// @param colour A colour returned by assign(), below num_colours().
    /// @param num_points Points the constraint stores, as given to assign().
    /// @return Where the constraint and its points go.
    place next_place(std::uint32_t colour, std::uint32_t num_points) noexcept;

private:
    struct colour_count {
        std::uint32_t constraints{0}, points{0};
    };
    /// next_colour of a body that does not move: it orders nothing.
    static constexpr std::uint32_t does_not_move = ~std::uint32_t(0);
    std::span<const solver_body> bodies;
    /// Per body: one more than the highest colour it took, or does_not_move; empty until the
    /// colouring's first constraint. Whether a body moves is read once, not at every constraint.
    std::vector<std::uint32_t> next_colour;
    std::vector<colour_count> counts; ///< Per colour, then per colour the next free place.
};

} // namespace edyn

#endif // EDYN_CONSTRAINTS_CONSTRAINT_COLOURING_HPP
